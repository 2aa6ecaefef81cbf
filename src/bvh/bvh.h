/// \file
/// A bounding volume hierarchy built with the binned surface area heuristic. Used twice: over
/// the triangles of each mesh, and over the instances of the scene (two levels).
#pragma once

#include <cstdint>
#include <limits>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif
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
    /// The bounds are taken by value: pass them with std::move to free them during the build.
    void build(std::vector<AABB> primitiveBounds, const BVHBuildOptions& options = {});
    const std::vector<BVHNode>& nodes() const { return nodes_; }
    const std::vector<std::uint32_t>& primitiveOrder() const { return order_; }
    /// Bytes of node storage.
    size_t nodeBytes() const { return nodes_.size() * sizeof(BVHNode); }
    /// Depth of the deepest leaf.
    int depth() const { return depth_; }

    // [bvh-traverse]
    /// The simple closest-hit traversal over the build tree: one box per node, the nearer
    /// child by the split axis's sign. leaf(i, tMax) tests primitive slot i (an index into
    /// primitiveOrder()) and returns true after shrinking tMax to a closer hit. Kept as the
    /// reference the fast traversal below is tested and measured against.
    template <class LeafTest>
    bool closestSimple(const Ray& ray, double& tMax, LeafTest&& leaf) const {
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

    /// The simple any-hit traversal for shadow rays: stops at the first primitive for which
    /// leaf(i, tMax) returns true.
    template <class LeafTest>
    bool anySimple(const Ray& ray, double tMax, LeafTest&& leaf) const {
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

      // [bvh-fast-traverse]
    /// Closest-hit traversal over the compact nodes: both children's boxes are tested from one
    /// 64-byte node, the nearer child is visited first by its actual entry distance, and a
    /// popped subtree farther than the closest hit so far is skipped. Same contract as
    /// closestSimple().
    template <class LeafTest>
    bool closest(const Ray& ray, double& tMax, LeafTest&& leaf) const {
        if (wide_.empty()) return false;
        const RayInverse ri(ray);
        struct Entry {
            std::uint32_t node;  // compact node holding the child
            std::uint32_t which; // 0 or 1
            double tEntry;
        };
        Entry stack[kStackSize];
        int top = 0;
        bool found = false;
        std::uint32_t current = 0;
        for (;;) {
            const WideNode& n = wide_[current];
            double t[2];
            const int mask = intersectChildren(n, ri, tMax, t);
            const bool hit0 = mask & 1, hit1 = mask & 2;
            int next = -1;
            if (hit0 && hit1) {
                const int nearer = t[1] < t[0] ? 1 : 0;
                stack[top++] = {current, static_cast<std::uint32_t>(1 - nearer), t[1 - nearer]};
                next = nearer;
            } else if (hit0) {
                next = 0;
            } else if (hit1) {
                next = 1;
            }
            // Descend into an interior child, or test a leaf and then pop.
            if (next >= 0 && n.count[next] > 0) {
                for (std::uint32_t i = n.child[next]; i < n.child[next] + n.count[next]; ++i)
                    found |= leaf(i, tMax);
                next = -1;
            }
            if (next >= 0) {
                current = n.child[next];
                continue;
            }
            // Pop the nearest pending subtree that can still hold a closer hit.
            bool resumed = false;
            while (top > 0) {
                const Entry e = stack[--top];
                if (e.tEntry > tMax) continue;
                const WideNode& p = wide_[e.node];
                if (p.count[e.which] > 0) {
                    for (std::uint32_t i = p.child[e.which]; i < p.child[e.which] + p.count[e.which];
                         ++i)
                        found |= leaf(i, tMax);
                    continue;
                }
                current = p.child[e.which];
                resumed = true;
                break;
            }
            if (!resumed) return found;
        }
    }
    // [bvh-fast-traverse]

    /// Any-hit traversal for shadow rays over the compact nodes: stops at the first primitive
    /// for which leaf(i, tMax) returns true.
    template <class LeafTest>
    bool any(const Ray& ray, double tMax, LeafTest&& leaf) const {
        if (wide_.empty()) return false;
        const RayInverse ri(ray);
        std::uint32_t stack[kStackSize];
        int top = 0;
        std::uint32_t current = 0;
        for (;;) {
            const WideNode& n = wide_[current];
            double t[2];
            const int mask = intersectChildren(n, ri, tMax, t);
            for (int c = 0; c < 2; ++c) {
                if (!(mask & (1 << c))) continue;
                if (n.count[c] > 0) {
                    for (std::uint32_t i = n.child[c]; i < n.child[c] + n.count[c]; ++i)
                        if (leaf(i, tMax)) return true;
                } else {
                    stack[top++] = n.child[c];
                }
            }
            if (top == 0) return false;
            current = stack[--top];
        }
    }

    /// Bytes of the compact traversal nodes.
    size_t wideNodeBytes() const { return wide_.size() * sizeof(WideNode); }

private:
    /// A compact node for traversal: the boxes of both children in float, rounded outwards so
    /// they still contain everything, and each child's node index or leaf range. 64 bytes, one
    /// cache line.
    struct alignas(64) WideNode {
        float lo[3][2];              ///< [axis][child]
        float hi[3][2];
        std::uint32_t child[2];      ///< Interior: compact node index. Leaf: first slot.
        std::uint16_t count[2];      ///< 0 for an interior child; primitives in a leaf.
    };
    static_assert(sizeof(WideNode) == 64);

    /// The slab test against both children's boxes at once, in double from the float bounds:
    /// bit c of the result is set when child c is entered for some t in (0, tMax), with its
    /// entry distance in tEntry[c]. SSE2 (every x86-64) holds the two children in one register.
    [[gnu::always_inline]] static int intersectChildren(const WideNode& n, const RayInverse& ri,
                                                        double tMax, double tEntry[2]) {
#if defined(__SSE2__)
        __m128d t0 = _mm_setzero_pd(), t1 = _mm_set1_pd(tMax);
        const __m128d widen = _mm_set1_pd(1.0 + 8.0 * std::numeric_limits<double>::epsilon());
        for (int axis = 0; axis < 3; ++axis) {
            // Load the two children's planes on this axis, float → double.
            const __m128d lo = _mm_cvtps_pd(_mm_castpd_ps(_mm_load_sd(
                reinterpret_cast<const double*>(&n.lo[axis][0]))));
            const __m128d hi = _mm_cvtps_pd(_mm_castpd_ps(_mm_load_sd(
                reinterpret_cast<const double*>(&n.hi[axis][0]))));
            const __m128d o = _mm_set1_pd(ri.o[axis]), invD = _mm_set1_pd(ri.invD[axis]);
            const __m128d nearPlane = ri.dirIsNeg[axis] ? hi : lo;
            const __m128d farPlane = ri.dirIsNeg[axis] ? lo : hi;
            const __m128d tNear = _mm_mul_pd(_mm_sub_pd(nearPlane, o), invD);
            const __m128d tFar = _mm_mul_pd(_mm_mul_pd(_mm_sub_pd(farPlane, o), invD), widen);
            // maxpd/minpd return their second operand when either is NaN: the running interval
            // survives a 0·∞ slab, as in intersectBox().
            t0 = _mm_max_pd(tNear, t0);
            t1 = _mm_min_pd(tFar, t1);
        }
        _mm_storeu_pd(tEntry, t0);
        return _mm_movemask_pd(_mm_cmple_pd(t0, t1));
#else
        int mask = 0;
        for (int c = 0; c < 2; ++c) {
            double t0 = 0.0, t1 = tMax;
            for (int axis = 0; axis < 3; ++axis) {
                const double lo = n.lo[axis][c], hi = n.hi[axis][c];
                const double tNear = ((ri.dirIsNeg[axis] ? hi : lo) - ri.o[axis]) * ri.invD[axis];
                double tFar = ((ri.dirIsNeg[axis] ? lo : hi) - ri.o[axis]) * ri.invD[axis];
                tFar *= 1.0 + 8.0 * std::numeric_limits<double>::epsilon();
                t0 = tNear > t0 ? tNear : t0;  // NaN-ignoring, as in intersectBox()
                t1 = tFar < t1 ? tFar : t1;
            }
            tEntry[c] = t0;
            if (t0 <= t1) mask |= 1 << c;
        }
        return mask;
#endif
    }

    /// Build the compact nodes from the build tree.
    void buildWide();
    /// Convert the subtree under build node i; returns its compact index.
    std::uint32_t convert(std::uint32_t i);

    std::vector<BVHNode> nodes_;
    std::vector<WideNode> wide_;
    std::vector<std::uint32_t> order_;
    int depth_ = 0;
};

}  // namespace rb
