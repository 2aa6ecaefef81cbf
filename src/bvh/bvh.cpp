#include "bvh/bvh.h"

#include <omp.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "core/error.h"

namespace rb {

namespace {

/// The most bins a build may use (fixed arrays keep the build free of allocations).
constexpr int kMaxBins = 32;

/// Depth from which the build splits at the median (see buildNode).
constexpr int kMedianDepth = 48;

/// A primitive during the build: its bounds, centroid and original index. The build
/// partitions an array of these in place, so every pass reads memory in order.
struct PrimRef {
    AABB box;
    Vec3 centroid;
    std::uint32_t index;
};

/// What the recursive build works on. Tasks share it: each partitions its own range of refs.
struct BuildState {
    std::vector<PrimRef> refs;
    const BVHBuildOptions& options;
};

/// Ranges at least this big build their two halves as parallel OpenMP tasks.
constexpr std::uint32_t kTaskGrain = 4096;

/// The bounds of a range of primitives and of their centroids: what a node's split needs.
struct RangeBounds {
    AABB bounds, centroids;
    /// Grow to hold primitive r.
    void extend(const PrimRef& r) {
        bounds.extend(r.box);
        centroids.extend(r.centroid);
    }
};

/// The bounds of refs[begin, end), in one pass.
RangeBounds boundsOf(const std::vector<PrimRef>& refs, std::uint32_t begin, std::uint32_t end) {
    RangeBounds b;
    for (std::uint32_t i = begin; i < end; ++i) b.extend(refs[i]);
    return b;
}

/// Reorder refs[begin, end) so that those for which goesLeft() holds come first; return where
/// the others start, with the bounds of both sides gathered on the way (so the children need
/// no pass of their own).
template <class Predicate>
std::uint32_t partitionWithBounds(std::vector<PrimRef>& refs, std::uint32_t begin,
                                  std::uint32_t end, Predicate goesLeft, RangeBounds side[2]) {
    std::uint32_t i = begin, j = end;
    for (;;) {
        while (i < j && goesLeft(refs[i])) side[0].extend(refs[i++]);
        while (i < j && !goesLeft(refs[j - 1])) side[1].extend(refs[--j]);
        if (i == j) return i;
        // refs[i] belongs right and refs[j − 1] left: swap them.
        std::swap(refs[i], refs[j - 1]);
    }
}

/// A subtree under construction: its nodes, numbered from 0 in depth-first order, and the
/// depth of its deepest leaf.
struct Subtree {
    std::vector<BVHNode> nodes;
    int depth = 0;
};

/// The best SAH split found for a range.
struct Split {
    int axis = -1;
    int bin = 0;  ///< Primitives in bins [0, bin) go left.
    double cost = std::numeric_limits<double>::infinity();
};

/// The SAH cost of a leaf of n primitives, in units of one primitive test: n, or for leaves
/// tested `leafBlock` primitives at a time, blockCost per block.
double leafCost(const BVHBuildOptions& options, std::uint32_t n) {
    if (options.leafBlock <= 1) return static_cast<double>(n);
    return options.blockCost * static_cast<double>((n + options.leafBlock - 1) / options.leafBlock);
}

// [binned-sah]
/// Find the cheapest binned SAH split of refs[begin, end) over all three axes.
Split findSplit(const BuildState& s, std::uint32_t begin, std::uint32_t end, const AABB& nodeBounds,
                const AABB& centroidBounds, int nBins) {
    // [exercise-sah-split]
    // Exercise 3.2, the binned SAH split: read ch03-equations.
    // Blank: return Split{};
    // Drop every primitive into a bin per axis by its centroid, in one pass. A bin's box is
    // set by its first primitive and grown by the others, so only the counts start at zero
    // (an empty bin's box is never read, and a BinBox, unlike an AABB, starts unset).
    struct BinBox {
        Vec3 lo, hi;
    };
    std::array<std::array<BinBox, kMaxBins>, 3> binBounds;
    std::array<std::array<std::uint32_t, kMaxBins>, 3> binCount{};
    Vec3 scale;
    for (int axis = 0; axis < 3; ++axis) {
        const double extent = centroidBounds.hi[axis] - centroidBounds.lo[axis];
        scale[axis] = extent > 0.0 ? nBins / extent : 0.0;
    }
    for (std::uint32_t i = begin; i < end; ++i) {
        const PrimRef& r = s.refs[i];
        for (int axis = 0; axis < 3; ++axis) {
            const int b = std::min(
                nBins - 1,
                static_cast<int>((r.centroid[axis] - centroidBounds.lo[axis]) * scale[axis]));
            BinBox& bin = binBounds[axis][b];
            if (binCount[axis][b]++ == 0) {
                bin = {r.box.lo, r.box.hi};
            } else {
                bin.lo = glm::min(bin.lo, r.box.lo);
                bin.hi = glm::max(bin.hi, r.box.hi);
            }
        }
    }
    Split best;
    const double invArea = 1.0 / std::max(nodeBounds.halfArea(), 1e-300);
    for (int axis = 0; axis < 3; ++axis) {
        if (scale[axis] == 0.0) continue;  // all centroids on one plane: no split here
        const auto& bounds = binBounds[axis];
        const auto& counts = binCount[axis];
        // Sweep from the right for the area and count of every suffix of bins (an empty bin
        // leaves both as they were).
        std::array<double, kMaxBins> rightArea;
        std::array<std::uint32_t, kMaxBins> rightCount;
        AABB acc;
        std::uint32_t count = 0;
        double area = 0.0;
        for (int b = nBins - 1; b > 0; --b) {
            if (counts[b] > 0) {
                acc.extend(AABB{bounds[b].lo, bounds[b].hi});
                count += counts[b];
                area = acc.halfArea();
            }
            rightArea[b] = area;
            rightCount[b] = count;
        }
        // Sweep from the left; splitting before bin b costs
        // C_trav + (A_L·N_L + A_R·N_R) / A_node. After an empty bin the split costs what the
        // one before it did, so only a bin that holds primitives gives a new candidate.
        acc = AABB();
        count = 0;
        for (int b = 1; b < nBins; ++b) {
            if (counts[b - 1] == 0) continue;
            acc.extend(AABB{bounds[b - 1].lo, bounds[b - 1].hi});
            count += counts[b - 1];
            if (rightCount[b] == 0) break;  // every primitive is on the left from here on
            const double cost =
                s.options.traversalCost + (acc.halfArea() * leafCost(s.options, count) +
                                           rightArea[b] * leafCost(s.options, rightCount[b])) *
                                              invArea;
            if (cost < best.cost) best = Split{axis, b, cost};
        }
    }
    return best;
    // [exercise-sah-split]
}
// [binned-sah]

/// Make node `index` a leaf over refs[begin, end).
void makeLeaf(Subtree& t, std::uint32_t index, std::uint32_t begin, std::uint32_t end) {
    t.nodes[index].count = static_cast<std::uint16_t>(end - begin);
    t.nodes[index].offset = begin;
}

std::uint32_t buildNode(BuildState& s, Subtree& t, std::uint32_t begin, std::uint32_t end,
                        int depth, const RangeBounds& range);

/// Build the two children of node `index` (over [begin, mid) and [mid, end), with bounds
/// side[0] and side[1]) and link them.
/// Big ranges build each child as an OpenMP task into a subtree of its own, then append both
/// in order, so the nodes come out exactly as the serial build would number them.
void buildChildren(BuildState& s, Subtree& t, std::uint32_t index, std::uint32_t begin,
                   std::uint32_t mid, std::uint32_t end, int depth, const RangeBounds side[2]) {
    if (end - begin < kTaskGrain || omp_get_num_threads() == 1) {
        buildNode(s, t, begin, mid, depth + 1, side[0]);
        t.nodes[index].offset = buildNode(s, t, mid, end, depth + 1, side[1]);
        return;
    }
    Subtree left, right;
#pragma omp task default(shared)
    buildNode(s, left, begin, mid, depth + 1, side[0]);
#pragma omp task default(shared)
    buildNode(s, right, mid, end, depth + 1, side[1]);
#pragma omp taskwait
    // Append a subtree: its interior nodes' second-child indices move with it.
    auto append = [&](const Subtree& sub) {
        const auto base = static_cast<std::uint32_t>(t.nodes.size());
        for (BVHNode n : sub.nodes) {
            if (n.count == 0) n.offset += base;
            t.nodes.push_back(n);
        }
        t.depth = std::max(t.depth, sub.depth);
        return base;
    };
    append(left);
    t.nodes[index].offset = append(right);
}

/// Build the subtree over refs[begin, end), whose bounds are `range`, into t and return its
/// node index.
std::uint32_t buildNode(BuildState& s, Subtree& t, std::uint32_t begin, std::uint32_t end,
                        int depth, const RangeBounds& range) {
    const std::uint32_t index = static_cast<std::uint32_t>(t.nodes.size());
    t.nodes.emplace_back();
    t.depth = std::max(t.depth, depth);
    const AABB& bounds = range.bounds;
    const AABB& centroidBounds = range.centroids;
    t.nodes[index].bounds = bounds;
    const std::uint32_t n = end - begin;
    const bool mustSplit = n > static_cast<std::uint32_t>(s.options.maxLeafSize);
    if (n == 1) {
        makeLeaf(t, index, begin, end);
        return index;
    }

    // Split where the SAH says it pays, or always when the range is too big for a leaf.
    // Deep in a lopsided tree, split at the median instead: that bounds the depth by
    // kMedianDepth + log2(n), so traversal's fixed stack can never overflow.
    if (depth >= kMedianDepth && n > 1) {
        int longest = 0;
        const Vec3 extent = centroidBounds.hi - centroidBounds.lo;
        if (extent.y > extent[longest]) longest = 1;
        if (extent.z > extent[longest]) longest = 2;
        const std::uint32_t half = begin + n / 2;
        std::nth_element(s.refs.begin() + begin, s.refs.begin() + half, s.refs.begin() + end,
                         [&](const PrimRef& a, const PrimRef& b) {
                             return a.centroid[longest] < b.centroid[longest];
                         });
        if (n <= static_cast<std::uint32_t>(s.options.maxLeafSize)) {
            makeLeaf(t, index, begin, end);
            return index;
        }
        t.nodes[index].axis = static_cast<std::uint8_t>(longest);
        const RangeBounds side[2] = {boundsOf(s.refs, begin, half), boundsOf(s.refs, half, end)};
        buildChildren(s, t, index, begin, half, end, depth, side);
        return index;
    }

    // Small ranges need fewer candidate planes.
    const int nBins = std::clamp(std::min<int>(s.options.bins, n), 2, kMaxBins);
    const Split split = findSplit(s, begin, end, bounds, centroidBounds, nBins);
    std::uint32_t mid = begin;
    int axis = split.axis;
    RangeBounds side[2];
    if (split.axis >= 0 && (mustSplit || split.cost < leafCost(s.options, n))) {
        const double lo = centroidBounds.lo[axis];
        const double scale = nBins / (centroidBounds.hi[axis] - lo);
        mid = partitionWithBounds(
            s.refs, begin, end,
            [&](const PrimRef& r) {
                const int b =
                    std::min(nBins - 1, static_cast<int>((r.centroid[axis] - lo) * scale));
                return b < split.bin;
            },
            side);
    } else if (!mustSplit || n <= 0xFFFF) {
        // A leaf is cheaper, or nothing separates the primitives (all centroids equal).
        if (!mustSplit || split.axis < 0) {
            makeLeaf(t, index, begin, end);
            return index;
        }
    }
    if (mid == begin || mid == end) {
        // Too many primitives with one centroid for one leaf: halve the range.
        mid = begin + n / 2;
        axis = 0;
        side[0] = boundsOf(s.refs, begin, mid);
        side[1] = boundsOf(s.refs, mid, end);
    }
    t.nodes[index].axis = static_cast<std::uint8_t>(axis);
    t.nodes[index].count = 0;
    buildChildren(s, t, index, begin, mid, end, depth, side);
    return index;
}

/// Box b grown by a few ulps of its largest coordinate. A shape's hit point carries rounding
/// error of that size (offsetRayOrigin makes the same argument), so a hit computed on a face of
/// the box may land just outside it; the padded box still holds it.
AABB padded(const AABB& b) {
    if (b.empty()) return b;
    const double extent = std::max(maxAbsComponent(b.lo), maxAbsComponent(b.hi));
    const Vec3 pad(64.0 * std::numeric_limits<double>::epsilon() * extent);
    return AABB{b.lo - pad, b.hi + pad};
}

}  // namespace

void BVH::build(std::vector<AABB> primitiveBounds, const BVHBuildOptions& options) {
    nodes_.clear();
    wide_.clear();
    wide8_.clear();
    order_.clear();
    bounds_ = AABB();
    layout_ = options.layout;
    if (layout_ == BVHLayout::Wide8 && !wide8Available()) layout_ = BVHLayout::Wide4;
    if (primitiveBounds.empty()) return;
    const size_t n = primitiveBounds.size();
    BuildState s{{}, options};
    s.refs.reserve(n);
    for (std::uint32_t i = 0; i < n; ++i) {
        bounds_.extend(primitiveBounds[i]);
        s.refs.push_back({padded(primitiveBounds[i]), primitiveBounds[i].centre(), i});
    }
    // Memory is the limit for big meshes: drop each temporary as soon as it is used up.
    std::vector<AABB>().swap(primitiveBounds);
    Subtree tree;
    tree.nodes.reserve(2 * n);
    // One thread starts the recursion; big ranges hand their halves to the team as tasks.
#pragma omp parallel if (n >= kTaskGrain)
#pragma omp single
    buildNode(s, tree, 0, static_cast<std::uint32_t>(n), 0, boundsOf(s.refs, 0, n));
    depth_ = tree.depth;
    order_.reserve(n);
    for (const PrimRef& r : s.refs) order_.push_back(r.index);
    std::vector<PrimRef>().swap(s.refs);
    if (layout_ == BVHLayout::Wide4) {
        wide_ = collapseToWide<4>(tree.nodes);
    } else if (layout_ == BVHLayout::Wide8) {
        wide8_ = collapseToWide<8>(tree.nodes);
    } else {
        tree.nodes.shrink_to_fit();
        nodes_ = std::move(tree.nodes);
    }
}

bool wide8Available() {
#if RB_HAVE_WIDE8
    // libgcc's check reads cpuid, and XGETBV for the operating system's support of the 256-bit
    // registers.
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2");
#else
    return false;
#endif
}

BVHLayout bestWideLayout() {
    return wide8Available() ? BVHLayout::Wide8 : BVHLayout::Wide4;
}

BVHLayout bvhLayoutNamed(const std::string& name) {
    if (name.empty() || name == "wide") return bestWideLayout();
    if (name == "binary") return BVHLayout::Binary;
    if (name == "wide4") return BVHLayout::Wide4;
    if (name == "wide8") {
        if (!wide8Available())
            throw InputError(
                "--bvh=wide8: this CPU has no AVX2 (or this build is not for x86-64); use wide4 "
                "or wide");
        return BVHLayout::Wide8;
    }
    throw InputError("--bvh: expected binary, wide, wide4 or wide8, got '" + name + "'");
}

const char* bvhLayoutDescription(BVHLayout layout) {
    switch (layout) {
        case BVHLayout::Binary:
            return "binary";
        case BVHLayout::Wide4:
            return "wide4 (SSE)";
        case BVHLayout::Wide8:
            return "wide8 (AVX2)";
    }
    return "?";
}

namespace {

/// Where to cut the binary tree into wide nodes so that the wide tree's SAH cost is least (in
/// the manner of Ylitie, Karras and Laine, "Efficient Incoherent Ray Traversal on GPUs Through
/// Compressed Wide BVHs", HPG 2017, without their leaf merging). The leaves are fixed, so that
/// cost is, up to constants, the summed surface area of the wide nodes: each is opened by the
/// rays that enter its box. For a binary node c given a slots in its parent's wide node,
/// cost(c, a) is the least summed area of the wide nodes below that parent that c's subtree
/// needs: 0 for a leaf; for an interior node the smaller of taking it as one child (it becomes a
/// wide node: its area, plus the cost of cutting its own subtree into N slots) and, with a ≥ 2,
/// opening it (its two children share the a slots).
template <int N>
class CollapsePlan {
  public:
    explicit CollapsePlan(const std::vector<BVHNode>& binary)
        : cost_(binary.size()), openCost_(binary.size()), split_(binary.size()) {
        // Children come after their parent in the build's numbering: go backwards.
        for (size_t i = binary.size(); i-- > 0;) {
            const BVHNode& node = binary[i];
            if (node.count > 0) {
                cost_[i].fill(0.0);
                continue;
            }
            const std::uint32_t left = static_cast<std::uint32_t>(i) + 1, right = node.offset;
            // Opening with a slots: the best share s of them for the first child.
            for (int a = 2; a <= N; ++a) {
                double best = std::numeric_limits<double>::infinity();
                for (int s = 1; s < a; ++s) {
                    const double c = cost_[left][s] + cost_[right][a - s];
                    if (c < best) {
                        best = c;
                        split_[i][a] = static_cast<std::int8_t>(s);
                    }
                }
                openCost_[i][a] = best;
            }
            // Taking it as one child: a wide node of its own, cut into N slots.
            const double take = node.bounds.halfArea() + openCost_[i][N];
            cost_[i][1] = take;
            for (int a = 2; a <= N; ++a) cost_[i][a] = std::min(take, openCost_[i][a]);
        }
    }
    /// Append to kids the children that binary node c becomes when given a slots; `open` makes
    /// an interior node give up its own slot (the wide node made from it).
    void expand(const std::vector<BVHNode>& binary, std::uint32_t c, int a, bool open,
                std::uint32_t* kids, int& kidCount) const {
        if (binary[c].count > 0 || a < 2 || (!open && cost_[c][a] < openCost_[c][a])) {
            kids[kidCount++] = c;
            return;
        }
        const int s = split_[c][a];
        expand(binary, c + 1, s, false, kids, kidCount);
        expand(binary, binary[c].offset, a - s, false, kids, kidCount);
    }

  private:
    std::vector<std::array<double, N + 1>> cost_, openCost_;
    std::vector<std::array<std::int8_t, N + 1>> split_;
};

/// Collapse the binary subtree under node i into wide node `index` of `wide` (already
/// allocated), recursing into the interior children it keeps. With a plan (eight-wide), its
/// cut; without (four-wide), the greedy one.
template <int N>
void collapseNode(const std::vector<BVHNode>& binary, std::uint32_t i,
                  std::vector<WideNodeN<N>>& wide, std::uint32_t index,
                  const CollapsePlan<N>* plan) {
    // Step 1: start from the two children, then open the interior child with the largest
    // surface area until there are N (the nodes a ray is most likely to enter are the ones
    // worth testing together); or take the children the plan says.
    std::uint32_t kids[N] = {i + 1, binary[i].offset};
    int kidCount = 2;
    if (plan) {
        kidCount = 0;
        plan->expand(binary, i, N, true, kids, kidCount);
    }
    while (!plan && kidCount < N) {
        int open = -1;
        double largest = -1.0;
        for (int k = 0; k < kidCount; ++k) {
            const BVHNode& kid = binary[kids[k]];
            if (kid.count == 0 && kid.bounds.halfArea() > largest) {
                largest = kid.bounds.halfArea();
                open = k;
            }
        }
        if (open < 0) break;  // all leaves
        // Replace the opened child by its two children, keeping the build's order.
        const std::uint32_t opened = kids[open];
        for (int k = kidCount; k > open + 1; --k) kids[k] = kids[k - 1];
        kids[open] = opened + 1;
        kids[open + 1] = binary[opened].offset;
        ++kidCount;
    }
    // Step 2: fill in the boxes, rounded outwards to float; unused children get empty boxes.
    WideNodeN<N> n{};
    for (int c = 0; c < N; ++c)
        for (int axis = 0; axis < 3; ++axis) {
            n.lo[axis][c] = c < kidCount ? roundDownToFloat(binary[kids[c]].bounds.lo[axis])
                                         : std::numeric_limits<float>::infinity();
            n.hi[axis][c] = c < kidCount ? roundUpToFloat(binary[kids[c]].bounds.hi[axis])
                                         : -std::numeric_limits<float>::infinity();
        }
    // Step 3: leaves keep their range; interior children become wide nodes of their own.
    for (int c = 0; c < kidCount; ++c) {
        const BVHNode& kid = binary[kids[c]];
        if (kid.count > 0) {
            n.child[c] = kid.offset;
            n.count[c] = kid.count;
        } else {
            n.child[c] = static_cast<std::uint32_t>(wide.size());
            wide.emplace_back();
        }
    }
    wide[index] = n;
    for (int c = 0; c < kidCount; ++c)
        if (n.count[c] == 0) collapseNode<N>(binary, kids[c], wide, n.child[c], plan);
}

}  // namespace

template <int N>
std::vector<WideNodeN<N>> collapseToWide(const std::vector<BVHNode>& binary) {
    std::vector<WideNodeN<N>> wide;
    if (binary.empty()) return wide;
    // Enough for the nodes the collapse makes in practice (about a fifth of the binary nodes
    // for N = 4, a seventh for N = 8, on the bunny), so the vector is not regrown.
    wide.reserve(binary.size() / (N / 2 + 1) + 1);
    wide.emplace_back();
    if (binary[0].count > 0) {
        // A single leaf: a root with one child.
        WideNodeN<N> n{};
        for (int c = 0; c < N; ++c)
            for (int axis = 0; axis < 3; ++axis) {
                n.lo[axis][c] = c == 0 ? roundDownToFloat(binary[0].bounds.lo[axis])
                                       : std::numeric_limits<float>::infinity();
                n.hi[axis][c] = c == 0 ? roundUpToFloat(binary[0].bounds.hi[axis])
                                       : -std::numeric_limits<float>::infinity();
            }
        n.child[0] = binary[0].offset;
        n.count[0] = binary[0].count;
        wide[0] = n;
        return wide;
    }
    if constexpr (N == 8) {
        const CollapsePlan<N> plan(binary);
        collapseNode<N>(binary, 0, wide, 0, &plan);
    } else {
        collapseNode<N>(binary, 0, wide, 0, nullptr);
    }
    wide.shrink_to_fit();
    return wide;
}

template std::vector<WideNodeN<4>> collapseToWide<4>(const std::vector<BVHNode>&);
template std::vector<WideNodeN<8>> collapseToWide<8>(const std::vector<BVHNode>&);

}  // namespace rb
