#include "core/bvh.h"

#include <algorithm>

namespace rb {

namespace {

/// What the recursive build works on.
struct BuildState {
    const std::vector<AABB>& bounds;
    std::vector<Vec3> centroids;
    std::vector<std::uint32_t>& order;
    std::vector<BVHNode>& nodes;
    const BVHBuildOptions& options;
    int depth = 0;
};

/// The best SAH split found for a range.
struct Split {
    int axis = -1;
    double position = 0.0;
    double cost = std::numeric_limits<double>::infinity();
};

// [binned-sah]
/// Find the cheapest binned SAH split of order[begin, end) over all three axes.
Split findSplit(const BuildState& s, std::uint32_t begin, std::uint32_t end,
                const AABB& nodeBounds) {
    // Bin the primitives by centroid, within the bounds of the centroids.
    AABB centroidBounds;
    for (std::uint32_t i = begin; i < end; ++i) centroidBounds.extend(s.centroids[s.order[i]]);
    Split best;
    const int nBins = s.options.bins;
    for (int axis = 0; axis < 3; ++axis) {
        const double lo = centroidBounds.lo[axis], hi = centroidBounds.hi[axis];
        if (!(hi > lo)) continue;  // all centroids on one plane: no split on this axis
        const double scale = nBins / (hi - lo);
        std::vector<AABB> binBounds(nBins);
        std::vector<std::uint32_t> binCount(nBins, 0);
        for (std::uint32_t i = begin; i < end; ++i) {
            const std::uint32_t p = s.order[i];
            const int b = std::min(nBins - 1, static_cast<int>((s.centroids[p][axis] - lo) * scale));
            binBounds[b].extend(s.bounds[p]);
            ++binCount[b];
        }
        // Sweep from the right to get the area and count of every suffix of bins.
        std::vector<double> rightArea(nBins);
        std::vector<std::uint32_t> rightCount(nBins);
        AABB acc;
        std::uint32_t count = 0;
        for (int b = nBins - 1; b > 0; --b) {
            acc.extend(binBounds[b]);
            count += binCount[b];
            rightArea[b] = acc.halfArea();
            rightCount[b] = count;
        }
        // Sweep from the left; the cost of splitting before bin b is
        // C_trav + (A_L·N_L + A_R·N_R) / A_node.
        acc = AABB();
        count = 0;
        const double invArea = 1.0 / std::max(nodeBounds.halfArea(), 1e-300);
        for (int b = 1; b < nBins; ++b) {
            acc.extend(binBounds[b - 1]);
            count += binCount[b - 1];
            if (count == 0 || rightCount[b] == 0) continue;
            const double cost = s.options.traversalCost +
                                (acc.halfArea() * count + rightArea[b] * rightCount[b]) * invArea;
            if (cost < best.cost) best = Split{axis, lo + b / scale, cost};
        }
    }
    return best;
}
// [binned-sah]

/// Build the subtree over order[begin, end) and return its node index.
std::uint32_t buildNode(BuildState& s, std::uint32_t begin, std::uint32_t end, int depth) {
    const std::uint32_t index = static_cast<std::uint32_t>(s.nodes.size());
    s.nodes.emplace_back();
    s.depth = std::max(s.depth, depth);
    AABB bounds;
    for (std::uint32_t i = begin; i < end; ++i) bounds.extend(s.bounds[s.order[i]]);
    s.nodes[index].bounds = bounds;
    const std::uint32_t n = end - begin;

    // Split when the SAH says it pays, or when the range is too big for a leaf.
    Split split = n > 1 ? findSplit(s, begin, end, bounds) : Split{};
    const double leafCost = static_cast<double>(n);
    const bool mustSplit = n > static_cast<std::uint32_t>(s.options.maxLeafSize);
    std::uint32_t mid = begin;
    if (split.axis >= 0 && (mustSplit || split.cost < leafCost)) {
        auto* first = s.order.data() + begin;
        auto* last = s.order.data() + end;
        mid = static_cast<std::uint32_t>(
            std::partition(first, last, [&](std::uint32_t p) {
                return s.centroids[p][split.axis] < split.position;
            }) - s.order.data());
    }
    // Fall back to a median split when binning could not separate the primitives (all
    // centroids equal, or every one on one side) but the range is too big for a leaf.
    if ((mid == begin || mid == end) && mustSplit && n <= 0xFFFF) {
        if (split.axis < 0 || mid == begin || mid == end) {
            s.nodes[index].count = static_cast<std::uint16_t>(n);
            s.nodes[index].offset = begin;
            return index;
        }
    }
    if (mid == begin || mid == end) {
        if (n <= 0xFFFF) {
            s.nodes[index].count = static_cast<std::uint16_t>(n);
            s.nodes[index].offset = begin;
            return index;
        }
        mid = begin + n / 2;  // too many identical primitives for one leaf: split in half
    }
    const std::uint8_t axis = static_cast<std::uint8_t>(std::max(split.axis, 0));
    buildNode(s, begin, mid, depth + 1);
    const std::uint32_t second = buildNode(s, mid, end, depth + 1);
    s.nodes[index].offset = second;
    s.nodes[index].axis = axis;
    s.nodes[index].count = 0;
    return index;
}

}  // namespace

void BVH::build(const std::vector<AABB>& primitiveBounds, const BVHBuildOptions& options) {
    nodes_.clear();
    order_.resize(primitiveBounds.size());
    for (std::uint32_t i = 0; i < order_.size(); ++i) order_[i] = i;
    if (primitiveBounds.empty()) return;
    nodes_.reserve(2 * primitiveBounds.size());
    BuildState s{primitiveBounds, {}, order_, nodes_, options};
    s.centroids.reserve(primitiveBounds.size());
    for (const AABB& b : primitiveBounds) s.centroids.push_back(b.centre());
    buildNode(s, 0, static_cast<std::uint32_t>(primitiveBounds.size()), 0);
    depth_ = s.depth;
    nodes_.shrink_to_fit();
}

}  // namespace rb
