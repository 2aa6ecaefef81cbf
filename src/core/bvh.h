/// \file
/// A bounding volume hierarchy built with the binned surface area heuristic. Used twice: over
/// the triangles of each mesh, and over the instances of the scene (two levels).
#pragma once

#include <cstdint>
#include <vector>

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

/// Build settings.
struct BVHBuildOptions {
    int bins = 16;               ///< SAH candidate planes per axis = bins − 1.
    int maxLeafSize = 4;         ///< A node with more primitives is always split.
    double traversalCost = 1.0;  ///< SAH cost of visiting a node, relative to one primitive test.
};

/// A binned-SAH BVH over primitives given by their bounds.
class BVH {
  public:
    /// Entries of the traversal stack. The build keeps the tree shallower than this (it splits
    /// at the median below depth 48, so the depth is at most 48 + 32).
    static constexpr int kStackSize = 96;

    /// Build over the primitives' bounds. primitiveOrder() then lists the primitive indices in
    /// the order leaves refer to them.
    void build(const std::vector<AABB>& primitiveBounds, const BVHBuildOptions& options = {});
    const std::vector<BVHNode>& nodes() const { return nodes_; }
    const std::vector<std::uint32_t>& primitiveOrder() const { return order_; }
    /// Bytes of node storage.
    size_t nodeBytes() const { return nodes_.size() * sizeof(BVHNode); }
    /// Depth of the deepest leaf.
    int depth() const { return depth_; }

    // [bvh-traverse]
    /// Closest-hit traversal. leaf(i, tMax) tests primitive slot i (an index into
    /// primitiveOrder()) and returns true after shrinking tMax to a closer hit.
    template <class LeafTest>
    bool closest(const Ray& ray, double& tMax, LeafTest&& leaf) const {
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
                    for (std::uint32_t i = node.offset; i < node.offset + node.count; ++i)
                        found |= leaf(i, tMax);
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

    /// Any-hit traversal for shadow rays: stops at the first primitive for which
    /// leaf(i, tMax) returns true.
    template <class LeafTest>
    bool any(const Ray& ray, double tMax, LeafTest&& leaf) const {
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
                    for (std::uint32_t i = node.offset; i < node.offset + node.count; ++i)
                        if (leaf(i, tMax)) return true;
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

  private:
    std::vector<BVHNode> nodes_;
    std::vector<std::uint32_t> order_;
    int depth_ = 0;
};

}  // namespace rb
