/// \file
/// A bounding volume hierarchy built with the binned surface area heuristic. Used twice: over
/// the triangles of each mesh, and over the instances of the scene (two levels).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "bvh/wide_bvh.h"
#include "bvh/wide_bvh8.h"
#include "core/aabb.h"

namespace rb {

/// One BVH node. Interior nodes keep their first child right after themselves and the second
/// at `offset`; leaves keep `count` primitives starting at `offset` in primitive order.
struct BVHNode {
    AABB bounds;
    std::uint32_t offset = 0;
    std::uint16_t count = 0;  ///< 0 for interior nodes.
    std::uint8_t axis = 0;    ///< Split axis of an interior node.
};

/// Which tree a BVH keeps for traversal (`--bvh=binary|wide4|wide8`, or `wide` for the widest
/// this CPU runs).
enum class BVHLayout {
    Binary,  ///< The build tree itself, one double-precision box per node: the lesson.
    Wide4,   ///< The build tree collapsed into four-wide float nodes, SSE (wide_bvh.h).
    Wide8,   ///< The build tree collapsed into eight-wide float nodes, AVX2 (wide_bvh8.h).
};

/// The widest layout this build and CPU run: Wide8 with AVX2, else Wide4. The default.
BVHLayout bestWideLayout();

/// The layout named by --bvh: "binary", "wide4", "wide8", or "wide" (also for ""), which is
/// bestWideLayout(). Throws InputError for another name, and for "wide8" where
/// wide8Available() is false.
BVHLayout bvhLayoutNamed(const std::string& name);

/// What --stats calls a layout: "binary", "wide4 (SSE)" or "wide8 (AVX2)".
const char* bvhLayoutDescription(BVHLayout layout);

/// Build settings.
struct BVHBuildOptions {
    int bins = 16;               ///< SAH candidate planes per axis = bins − 1.
    int maxLeafSize = 4;         ///< A node with more primitives is always split.
    double traversalCost = 1.0;  ///< SAH cost of visiting a node, relative to one primitive test.
    BVHLayout layout = bestWideLayout();  ///< The tree kept for traversal.
    int leafBlock = 1;       ///< Primitives a leaf tests at once (4 for packed triangles).
    double blockCost = 1.0;  ///< SAH cost of one such test, relative to one primitive test.
};

/// A binned-SAH BVH over primitives given by their bounds.
class BVH {
  public:
    /// Entries of the traversal stack. The build keeps the tree shallower than this (it splits
    /// at the median below depth 48, so the depth is at most 48 + 32).
    static constexpr int kStackSize = 96;

    /// Build over the primitives' bounds. primitiveOrder() then lists the primitive indices in
    /// the order leaves refer to them. BVHLayout::Wide8 where wide8Available() is false
    /// builds Wide4.
    /// The bounds are taken by value: pass them with std::move to free them during the build.
    /// Big ranges are split in parallel with OpenMP tasks; the tree is the same for any
    /// number of threads.
    void build(std::vector<AABB> primitiveBounds, const BVHBuildOptions& options = {});
    /// The layout chosen at build time.
    BVHLayout layout() const { return layout_; }
    /// The binary build tree (empty for the wide layouts, which free it after collapsing).
    const std::vector<BVHNode>& nodes() const { return nodes_; }
    /// The four-wide nodes (empty unless BVHLayout::Wide4).
    const std::vector<WideNode>& wideNodes() const { return wide_; }
    /// The eight-wide nodes (empty unless BVHLayout::Wide8).
    const std::vector<WideNode8>& wide8Nodes() const { return wide8_; }
    const std::vector<std::uint32_t>& primitiveOrder() const { return order_; }
    /// Frees primitiveOrder() once its owner has put its primitives in that order.
    void releasePrimitiveOrder() { std::vector<std::uint32_t>().swap(order_); }
    /// The bounds of every primitive (exact: the nodes' boxes are a few ulps wider).
    const AABB& bounds() const { return bounds_; }
    /// Nodes of the kept tree.
    size_t nodeCount() const { return nodes_.size() + wide_.size() + wide8_.size(); }
    /// Bytes of node storage.
    size_t nodeBytes() const {
        return nodes_.size() * sizeof(BVHNode) + wide_.size() * sizeof(WideNode) +
               wide8_.size() * sizeof(WideNode8);
    }
    /// Depth of the deepest leaf.
    int depth() const { return depth_; }

    // [bvh-traverse]
    /// The simple closest-hit traversal over the build tree: one box per node, the nearer
    /// child by the split axis's sign. leaf(first, count, tMax) tests the primitives in slots
    /// first … first + count − 1 (indices into primitiveOrder()) and returns true after
    /// shrinking tMax to a closer hit.
    template <class LeafTest>
    [[gnu::always_inline]] bool closestSimple(const Ray& ray, double& tMax, LeafTest&& leaf) const {
        if (nodes_.empty()) return false;
        const RayInverse ri(ray);
        std::uint32_t stack[kStackSize];
        int top = 0;
        std::uint32_t current = 0;
        bool found = false;
        for (;;) {
            const BVHNode& node = nodes_[current];
            double tEntry;
            if (intersectBox(node.bounds, ri, tMax, tEntry)) {
                if (node.count > 0) {
                    // Leaf: test its primitives; each hit shrinks tMax.
                    found |= leaf(node.offset, std::uint32_t{node.count}, tMax);
                } else {
                    // Interior: visit the child nearer along the split axis first.
                    if (ri.dirIsNeg[node.axis]) {
                        stack[top++] = current + 1;
                        current = node.offset;
                    } else {
                        stack[top++] = node.offset;
                        current = current + 1;
                    }
                    continue;
                }
            }
            if (top == 0) break;
            current = stack[--top];
        }
        return found;
    }
    // [bvh-traverse]

    /// The simple any-hit traversal for shadow rays: stops at the first leaf for which
    /// leaf(first, count, tMax) returns true.
    template <class LeafTest>
    [[gnu::always_inline]] bool anySimple(const Ray& ray, double tMax, LeafTest&& leaf) const {
        if (nodes_.empty()) return false;
        const RayInverse ri(ray);
        std::uint32_t stack[kStackSize];
        int top = 0;
        std::uint32_t current = 0;
        for (;;) {
            const BVHNode& node = nodes_[current];
            double tEntry;
            if (intersectBox(node.bounds, ri, tMax, tEntry)) {
                if (node.count > 0) {
                    if (leaf(node.offset, std::uint32_t{node.count}, tMax)) return true;
                } else {
                    stack[top++] = node.offset;
                    current = current + 1;
                    continue;
                }
            }
            if (top == 0) return false;
            current = stack[--top];
        }
    }

    /// Closest-hit query: the traversal of the layout the tree was built with (the binary one
    /// of the lesson, four-wide inlined here, or eight-wide in an AVX2 function of its own
    /// with the leaf test inlined into it). leaf(first, count, tMax) tests a leaf's primitives
    /// and returns true after shrinking tMax to a closer hit. `counts` counts the wide nodes
    /// visited (TraversalCounts; the binary lesson's traversal counts none), or nothing.
    template <class LeafTest, class Counts = NoCounts>
    [[gnu::always_inline]] bool closest(const Ray& ray, double& tMax, LeafTest&& leaf,
                                        Counts&& counts = {}) const {
#if RB_HAVE_WIDE8
        if (layout_ == BVHLayout::Wide8) return closestWide8Call(wide8_, ray, tMax, leaf, counts);
#endif
        return layout_ == BVHLayout::Wide4 ? closestWide(wide_, ray, tMax, leaf, counts)
                                           : closestSimple(ray, tMax, leaf);
    }
    /// Any-hit query for shadow rays: stops at the first leaf for which leaf(first, count,
    /// tMax) returns true. `counts` as for closest().
    template <class LeafTest, class Counts = NoCounts>
    [[gnu::always_inline]] bool any(const Ray& ray, double tMax, LeafTest&& leaf,
                                    Counts&& counts = {}) const {
#if RB_HAVE_WIDE8
        if (layout_ == BVHLayout::Wide8) return anyWide8Call(wide8_, ray, tMax, leaf, counts);
#endif
        return layout_ == BVHLayout::Wide4 ? anyWide(wide_, ray, tMax, leaf, counts)
                                           : anySimple(ray, tMax, leaf);
    }

    /// Call f(first, count) for every leaf, in depth-first order; f may change `first` (a mesh
    /// points its leaves at its packed triangles).
    template <class F>
    void forEachLeaf(F&& f) {
        for (BVHNode& n : nodes_)
            if (n.count > 0) f(n.offset, std::uint32_t{n.count});
        for (WideNode& n : wide_)
            for (int c = 0; c < 4; ++c)
                if (n.count[c] > 0) f(n.child[c], std::uint32_t{n.count[c]});
        for (WideNode8& n : wide8_)
            for (int c = 0; c < 8; ++c)
                if (n.count[c] > 0) f(n.child[c], std::uint32_t{n.count[c]});
    }
    /// Call f(first, count) for every leaf, in the same order.
    template <class F>
    void forEachLeaf(F&& f) const {
        const_cast<BVH*>(this)->forEachLeaf(
            [&](std::uint32_t first, std::uint32_t count) { f(first, count); });
    }

  private:
    std::vector<BVHNode> nodes_;    ///< The build tree; kept only for BVHLayout::Binary.
    std::vector<WideNode> wide_;    ///< The four-wide nodes; only for BVHLayout::Wide4.
    std::vector<WideNode8> wide8_;  ///< The eight-wide nodes; only for BVHLayout::Wide8.
    std::vector<std::uint32_t> order_;
    AABB bounds_;
    BVHLayout layout_ = BVHLayout::Wide4;
    int depth_ = 0;
};

}  // namespace rb
