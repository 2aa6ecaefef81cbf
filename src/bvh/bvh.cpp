#include "bvh/bvh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

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

/// What the recursive build works on.
struct BuildState {
    std::vector<PrimRef> refs;
    std::vector<BVHNode>& nodes;
    const BVHBuildOptions& options;
    int depth = 0;
};

/// The best SAH split found for a range.
struct Split {
    int axis = -1;
    int bin = 0;  ///< Primitives in bins [0, bin) go left.
    double cost = std::numeric_limits<double>::infinity();
};

// [binned-sah]
/// Find the cheapest binned SAH split of refs[begin, end) over all three axes.
Split findSplit(const BuildState& s, std::uint32_t begin, std::uint32_t end, const AABB& nodeBounds,
                const AABB& centroidBounds, int nBins) {
    // [exercise-sah-split]
    // Exercise 3.2, the binned SAH split: read ch03-equations.
    // Blank: return Split{};
    // Drop every primitive into a bin per axis by its centroid, in one pass.
    std::array<std::array<AABB, kMaxBins>, 3> binBounds;
    std::array<std::array<std::uint32_t, kMaxBins>, 3> binCount;
    for (int axis = 0; axis < 3; ++axis)
        for (int b = 0; b < nBins; ++b) {
            binBounds[axis][b] = AABB();
            binCount[axis][b] = 0;
        }
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
            binBounds[axis][b].extend(r.box);
            ++binCount[axis][b];
        }
    }
    Split best;
    const double invArea = 1.0 / std::max(nodeBounds.halfArea(), 1e-300);
    for (int axis = 0; axis < 3; ++axis) {
        if (scale[axis] == 0.0) continue;  // all centroids on one plane: no split here
        // Sweep from the right for the area and count of every suffix of bins.
        std::array<double, kMaxBins> rightArea;
        std::array<std::uint32_t, kMaxBins> rightCount;
        AABB acc;
        std::uint32_t count = 0;
        for (int b = nBins - 1; b > 0; --b) {
            acc.extend(binBounds[axis][b]);
            count += binCount[axis][b];
            rightArea[b] = acc.halfArea();
            rightCount[b] = count;
        }
        // Sweep from the left; splitting before bin b costs
        // C_trav + (A_L·N_L + A_R·N_R) / A_node.
        acc = AABB();
        count = 0;
        for (int b = 1; b < nBins; ++b) {
            acc.extend(binBounds[axis][b - 1]);
            count += binCount[axis][b - 1];
            if (count == 0 || rightCount[b] == 0) continue;
            const double cost = s.options.traversalCost +
                                (acc.halfArea() * count + rightArea[b] * rightCount[b]) * invArea;
            if (cost < best.cost) best = Split{axis, b, cost};
        }
    }
    return best;
    // [exercise-sah-split]
}
// [binned-sah]

/// Make node `index` a leaf over refs[begin, end).
void makeLeaf(BuildState& s, std::uint32_t index, std::uint32_t begin, std::uint32_t end) {
    s.nodes[index].count = static_cast<std::uint16_t>(end - begin);
    s.nodes[index].offset = begin;
}

/// Build the subtree over refs[begin, end) and return its node index.
std::uint32_t buildNode(BuildState& s, std::uint32_t begin, std::uint32_t end, int depth) {
    const std::uint32_t index = static_cast<std::uint32_t>(s.nodes.size());
    s.nodes.emplace_back();
    s.depth = std::max(s.depth, depth);
    // Bounds of the primitives and of their centroids, in one pass.
    AABB bounds, centroidBounds;
    for (std::uint32_t i = begin; i < end; ++i) {
        bounds.extend(s.refs[i].box);
        centroidBounds.extend(s.refs[i].centroid);
    }
    s.nodes[index].bounds = bounds;
    const std::uint32_t n = end - begin;
    const bool mustSplit = n > static_cast<std::uint32_t>(s.options.maxLeafSize);
    if (n == 1) {
        makeLeaf(s, index, begin, end);
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
            makeLeaf(s, index, begin, end);
            return index;
        }
        buildNode(s, begin, half, depth + 1);
        const std::uint32_t second = buildNode(s, half, end, depth + 1);
        s.nodes[index].offset = second;
        s.nodes[index].axis = static_cast<std::uint8_t>(longest);
        return index;
    }

    // Small ranges need fewer candidate planes.
    const int nBins = std::clamp(std::min<int>(s.options.bins, n), 2, kMaxBins);
    const Split split = findSplit(s, begin, end, bounds, centroidBounds, nBins);
    std::uint32_t mid = begin;
    int axis = split.axis;
    if (split.axis >= 0 && (mustSplit || split.cost < static_cast<double>(n))) {
        const double lo = centroidBounds.lo[axis];
        const double scale = nBins / (centroidBounds.hi[axis] - lo);
        mid = static_cast<std::uint32_t>(
            std::partition(s.refs.begin() + begin, s.refs.begin() + end,
                           [&](const PrimRef& r) {
                               const int b = std::min(
                                   nBins - 1, static_cast<int>((r.centroid[axis] - lo) * scale));
                               return b < split.bin;
                           }) -
            s.refs.begin());
    } else if (!mustSplit || n <= 0xFFFF) {
        // A leaf is cheaper, or nothing separates the primitives (all centroids equal).
        if (!mustSplit || split.axis < 0) {
            makeLeaf(s, index, begin, end);
            return index;
        }
    }
    if (mid == begin || mid == end) {
        // Too many primitives with one centroid for one leaf: halve the range.
        mid = begin + n / 2;
        axis = 0;
    }
    buildNode(s, begin, mid, depth + 1);
    const std::uint32_t second = buildNode(s, mid, end, depth + 1);
    s.nodes[index].offset = second;
    s.nodes[index].axis = static_cast<std::uint8_t>(axis);
    s.nodes[index].count = 0;
    return index;
}

}  // namespace

void BVH::build(std::vector<AABB> primitiveBounds, const BVHBuildOptions& options) {
    nodes_.clear();
    order_.clear();
    if (primitiveBounds.empty()) return;
    const size_t n = primitiveBounds.size();
    BuildState s{{}, nodes_, options};
    s.refs.reserve(n);
    for (std::uint32_t i = 0; i < n; ++i)
        s.refs.push_back({primitiveBounds[i], primitiveBounds[i].centre(), i});
    // Memory is the limit for big meshes: drop each temporary as soon as it is used up.
    std::vector<AABB>().swap(primitiveBounds);
    nodes_.reserve(2 * n);
    buildNode(s, 0, static_cast<std::uint32_t>(s.refs.size()), 0);
    depth_ = s.depth;
    order_.reserve(s.refs.size());
    for (const PrimRef& r : s.refs) order_.push_back(r.index);
    std::vector<PrimRef>().swap(s.refs);
    nodes_.shrink_to_fit();
    buildWide();
}

namespace {
/// The largest float not above x, and the smallest not below: bounds rounded outwards.
float roundDown(double x) {
    float f = static_cast<float>(x);
    return static_cast<double>(f) > x ? std::nextafter(f, -std::numeric_limits<float>::infinity()) : f;
}
float roundUp(double x) {
    float f = static_cast<float>(x);
    return static_cast<double>(f) < x ? std::nextafter(f, std::numeric_limits<float>::infinity()) : f;
}
}  // namespace

void BVH::buildWide() {
    wide_.clear();
    if (nodes_.empty()) return;
    wide_.reserve(nodes_.size() / 2 + 1);
    if (nodes_[0].count > 0) {
        // A single leaf: one compact node whose second child is an empty box.
        WideNode n{};
        for (int axis = 0; axis < 3; ++axis) {
            n.lo[axis][0] = roundDown(nodes_[0].bounds.lo[axis]);
            n.hi[axis][0] = roundUp(nodes_[0].bounds.hi[axis]);
            n.lo[axis][1] = std::numeric_limits<float>::infinity();
            n.hi[axis][1] = -std::numeric_limits<float>::infinity();
        }
        n.child[0] = nodes_[0].offset;
        n.count[0] = nodes_[0].count;
        n.count[1] = 1;  // an empty leaf range is never reached: its box is empty
        n.child[1] = 0;
        wide_.push_back(n);
        return;
    }
    convert(0);
}

std::uint32_t BVH::convert(std::uint32_t i) {
    // The build tree keeps an interior node's first child at i + 1 and its second at offset.
    const std::uint32_t index = static_cast<std::uint32_t>(wide_.size());
    wide_.emplace_back();
    const std::uint32_t children[2] = {i + 1, nodes_[i].offset};
    for (int c = 0; c < 2; ++c) {
        const BVHNode& child = nodes_[children[c]];
        for (int axis = 0; axis < 3; ++axis) {
            wide_[index].lo[axis][c] = roundDown(child.bounds.lo[axis]);
            wide_[index].hi[axis][c] = roundUp(child.bounds.hi[axis]);
        }
        if (child.count > 0) {
            wide_[index].child[c] = child.offset;
            wide_[index].count[c] = child.count;
        } else {
            const std::uint32_t converted = convert(children[c]);
            wide_[index].child[c] = converted;
            wide_[index].count[c] = 0;
        }
    }
    return index;
}

}  // namespace rb
