/// \file
/// The wide BVH: the binary build tree collapsed into nodes of four children whose boxes, in
/// single precision, are tested together with SSE (every x86-64 has it); wide_bvh8.h does the
/// same eight at a time with AVX2. Chapter 3's "going
/// further" section. The boxes are rounded outwards and the slab test is made conservative in
/// the manner of Ize, "Robust BVH Ray Traversal" (JCGT 2013), so it never misses a box that the
/// exact ray enters.
#pragma once

#include <xmmintrin.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "bvh/float_rounding.h"
#include "bvh/traversal_counts.h"
#include "core/aabb.h"

namespace rb {

struct BVHNode;

/// A node of N children (4 for SSE, 8 for AVX2): their boxes in float, axis by axis (so one load
/// fetches one plane of all N), and for each child either a node index or a leaf's range. An
/// unused child has an empty box (lo = +∞, hi = −∞), which no ray enters. N = 4: 128 bytes, two
/// cache lines; N = 8: 256 bytes, four.
template <int N>
struct alignas(64) WideNodeN {
    float lo[3][N];          ///< [axis][child], rounded down.
    float hi[3][N];          ///< [axis][child], rounded up.
    std::uint32_t child[N];  ///< Interior: node index. Leaf: first primitive slot.
    std::uint16_t count[N];  ///< 0 for an interior child; primitives in a leaf.
};
/// The four-wide node, tested with SSE (every x86-64 has it).
using WideNode = WideNodeN<4>;
/// The eight-wide node, tested with AVX2 (wide_bvh8.h) where the CPU has it.
using WideNode8 = WideNodeN<8>;
static_assert(sizeof(WideNode) == 128);
static_assert(sizeof(WideNode8) == 256);

/// Collapse a binary build tree (first child after its parent, second at `offset`) into nodes
/// of up to N children, each a subtree below one binary node: for N = 4 greedily (the largest
/// child is opened until there are four), for N = 8 where the SAH cost of the wide tree is least
/// (CollapsePlan in bvh.cpp). Leaves stay as they are. Node 0 of the result is the root.
/// Instantiated for N = 4 and 8.
template <int N>
std::vector<WideNodeN<N>> collapseToWide(const std::vector<BVHNode>& binary);

/// How much the far end of a float slab interval is stretched. Each t carries three roundings
/// (the subtraction, the reciprocal, the product: relative error γ₃ = 3u/(1 − 3u), u = 2⁻²⁴);
/// comparing tNear with tFar, or tNear with the closest hit, needs 1 + 2γ₃ plus the rounding of
/// the stretch itself. 2⁻²⁰ is 2.7 times that, and exact in float.
/// Source: Ize, "Robust BVH Ray Traversal", JCGT 2(2), 2013, §3.
inline constexpr float kFarWidening = 1.0f + 1.0f / (1 << 20);

/// A ray prepared for the float slab test. Rounding the double origin to float moves the ray;
/// so each plane is measured from a float origin that can only bring a near plane nearer and
/// push a far plane farther: o rounded to float, moved by more than the rounding can have moved
/// it (|o_f|·2⁻²³, plus the smallest subnormal for origins near 0). The far planes use the
/// reciprocal direction stretched by kFarWidening (Ize's widening, folded into the multiply).
/// Built with a few SSE instructions for all three axes: it runs twice per ray and mesh.
struct WideRay {
    __m128 oNear[3], oFar[3], invDNear[3], invDFar[3];
    int nearPlane[3], farPlane[3];  ///< Offsets, in floats, of the near and far planes in a node.

    [[gnu::always_inline]] explicit WideRay(const Ray& r) {
        // x, y, z in lanes 0–2, converted to float (round to nearest).
        const __m128 o = _mm_movelh_ps(_mm_cvtpd_ps(_mm_set_pd(r.o.y, r.o.x)),
                                       _mm_cvtpd_ps(_mm_set_pd(0.0, r.o.z)));
        const __m128 invD =
            _mm_movelh_ps(_mm_cvtpd_ps(_mm_div_pd(_mm_set1_pd(1.0), _mm_set_pd(r.d.y, r.d.x))),
                          _mm_cvtpd_ps(_mm_div_pd(_mm_set1_pd(1.0), _mm_set_pd(1.0, r.d.z))));
        // |o − o_f| ≤ ½ ulp(o_f) ≤ 2⁻²⁴|o_f| for normal o_f, ≤ 2⁻¹⁵⁰ below; err exceeds both, and
        // o_f ± err rounds to a float at least one ulp away, so it stays on its side of o.
        const __m128 absO = _mm_andnot_ps(_mm_set1_ps(-0.0f), o);
        const __m128 err =
            _mm_add_ps(_mm_mul_ps(absO, _mm_set1_ps(1.0f / (1 << 23))), _mm_set1_ps(0x1p-149f));
        alignas(16) float up[4], down[4], inv[4];
        _mm_store_ps(up, _mm_add_ps(o, err));
        _mm_store_ps(down, _mm_sub_ps(o, err));
        _mm_store_ps(inv, invD);
        for (int axis = 0; axis < 3; ++axis) {
            const bool negative = std::signbit(inv[axis]);
            // Positive direction: near plane lo, t = (lo − o)/d is smallest with o rounded up.
            oNear[axis] = _mm_set1_ps(negative ? down[axis] : up[axis]);
            oFar[axis] = _mm_set1_ps(negative ? up[axis] : down[axis]);
            invDNear[axis] = _mm_set1_ps(inv[axis]);
            invDFar[axis] = _mm_set1_ps(inv[axis] * kFarWidening);
            const int lo = 4 * axis, hi = 12 + 4 * axis;  // WideNode: lo[3][4], then hi[3][4]
            nearPlane[axis] = negative ? hi : lo;
            farPlane[axis] = negative ? lo : hi;
        }
    }
};

// [wide-slab-test]
/// The slab test against the four children of n at once: bit c of the result is set when the
/// ray enters child c for some t in (0, tMax], with the entry distance in tEntry lane c.
/// `tMax` is the closest hit so far, rounded up to float and stretched by kFarWidening.
[[gnu::always_inline]] inline int intersectChildren4(const WideNode& n, const WideRay& r,
                                                     __m128 tMax, __m128& tEntry) {
    const float* planes = &n.lo[0][0];
    __m128 t0 = _mm_setzero_ps(), t1 = tMax;
    for (int axis = 0; axis < 3; ++axis) {
        // Near and far planes by the sign of the direction, four children at a time.
        const __m128 tNear = _mm_mul_ps(
            _mm_sub_ps(_mm_load_ps(planes + r.nearPlane[axis]), r.oNear[axis]), r.invDNear[axis]);
        const __m128 tFar = _mm_mul_ps(
            _mm_sub_ps(_mm_load_ps(planes + r.farPlane[axis]), r.oFar[axis]), r.invDFar[axis]);
        // maxps/minps return their second operand when either is NaN (0·∞: a ray in the
        // plane of a slab), so the running interval survives it, as in intersectBox().
        t0 = _mm_max_ps(tNear, t0);
        t1 = _mm_min_ps(tFar, t1);
    }
    tEntry = t0;
    return _mm_movemask_ps(_mm_cmple_ps(t0, t1));
}
// [wide-slab-test]

/// A traversal's pending work: node indices and leaf ranges, each with the distance at which
/// the ray enters its box. Reference and count share one 64-bit word so that moving an entry is
/// two register moves. N is the width of the nodes.
template <int N = 4>
class WideStack {
  public:
    /// Entries: a node pushes at most N − 1 more than it pops, and the build keeps the tree at
    /// most 80 binary levels deep (bvh.h), so the wide tree is no deeper.
    static constexpr int kSize = (N - 1) * 80 + 16;

    bool empty() const { return top_ == 0; }
    int size() const { return top_; }
    /// Push child c of node n, entered at tEntry.
    void push(const WideNodeN<N>& n, int c, float tEntry) {
        key_[top_] = std::uint64_t{n.count[c]} << 32 | n.child[c];
        t_[top_++] = tEntry;
    }
    /// Sort the entries from `first` to the top by entry distance, nearest on top.
    void sortFrom(int first) {
        for (int i = first + 1; i < top_; ++i)
            for (int k = i; k > first && t_[k - 1] < t_[k]; --k) {
                std::swap(t_[k - 1], t_[k]);
                std::swap(key_[k - 1], key_[k]);
            }
    }
    /// Drop entries from the top that the ray enters beyond tLimit.
    void dropBeyond(float tLimit) {
        while (top_ > 0 && t_[top_ - 1] > tLimit) --top_;
    }
    /// Pop the top entry: its reference, and its count (0 for a node).
    void pop(std::uint32_t& ref, std::uint32_t& count) {
        const std::uint64_t key = key_[--top_];
        ref = static_cast<std::uint32_t>(key);
        count = static_cast<std::uint32_t>(key >> 32);
    }

  private:
    std::uint64_t key_[kSize];
    float t_[kSize];
    int top_ = 0;
};
static_assert(WideStack<4>::kSize == 256);

/// The closest hit so far, rounded up to float and stretched, in all four lanes.
inline __m128 wideTMax(double tMax) {
    return _mm_set1_ps(roundUpToFloat(tMax) * kFarWidening);
}

// [wide-traverse]
/// Closest-hit traversal of a wide BVH: the boxes of a node's four children are tested at once;
/// the children hit are visited nearest first (the others wait on the stack with their entry
/// distance, and are dropped when a closer hit has been found by then). leaf(first, count,
/// tMax) tests a leaf's primitives and returns true after shrinking tMax to a closer hit;
/// `counts` counts the nodes visited (TraversalCounts), or nothing.
template <class LeafTest, class Counts = NoCounts>
[[gnu::always_inline]] inline bool closestWide(const std::vector<WideNode>& nodes, const Ray& ray,
                                               double& tMax, LeafTest&& leaf,
                                               Counts&& counts = {}) {
    if (nodes.empty()) return false;
    const WideRay r(ray);
    __m128 tMaxF = wideTMax(tMax);
    WideStack<4> stack;
    bool found = false;
    std::uint32_t ref = 0, count = 0;  // start at the root node
    for (;;) {
        if (count > 0) {
            // A leaf: test its primitives.
            if (leaf(ref, count, tMax)) {
                found = true;
                tMaxF = wideTMax(tMax);
            }
        } else {
            // A node: which children does the ray enter, and where?
            const WideNode& n = nodes[ref];
            counts.node();
            __m128 tEntry;
            int mask = intersectChildren4(n, r, tMaxF, tEntry);
            if (mask != 0) {
                const int c = __builtin_ctz(mask);
                mask &= mask - 1;
                if (mask == 0) {
                    // One child: go straight on.
                    ref = n.child[c];
                    count = n.count[c];
                    continue;
                }
                alignas(16) float t[4];
                _mm_store_ps(t, tEntry);
                const int k = __builtin_ctz(mask);
                if ((mask & (mask - 1)) == 0) {
                    // Two: wait on the farther, go on with the nearer.
                    const bool kFirst = t[k] < t[c];
                    stack.push(n, kFirst ? c : k, kFirst ? t[c] : t[k]);
                    ref = n.child[kFirst ? k : c];
                    count = n.count[kFirst ? k : c];
                    continue;
                }
                // More: push them all, nearest on top, and continue with the nearest.
                const int first = stack.size();
                stack.push(n, c, t[c]);
                for (; mask != 0; mask &= mask - 1) {
                    const int k = __builtin_ctz(mask);
                    stack.push(n, k, t[k]);
                }
                stack.sortFrom(first);
                stack.pop(ref, count);
                continue;
            }
        }
        // Pop the nearest pending entry that can still hold a closer hit.
        stack.dropBeyond(_mm_cvtss_f32(tMaxF));
        if (stack.empty()) return found;
        stack.pop(ref, count);
    }
}
// [wide-traverse]

/// Any-hit traversal of a wide BVH for shadow rays: stops at the first leaf for which
/// leaf(first, count, tMax) returns true. Order does not matter here, so the leaves among a
/// node's children are tested at once and only nodes wait on the stack.
template <class LeafTest, class Counts = NoCounts>
[[gnu::always_inline]] inline bool anyWide(const std::vector<WideNode>& nodes, const Ray& ray,
                                           double tMax, LeafTest&& leaf, Counts&& counts = {}) {
    if (nodes.empty()) return false;
    const WideRay r(ray);
    const __m128 tMaxF = wideTMax(tMax);
    WideStack<4> stack;
    std::uint32_t ref = 0, count = 0;  // start at the root node
    for (;;) {
        const WideNode& n = nodes[ref];
        counts.node();
        __m128 tEntry;
        for (int mask = intersectChildren4(n, r, tMaxF, tEntry); mask; mask &= mask - 1) {
            const int c = __builtin_ctz(mask);
            if (n.count[c] == 0)
                stack.push(n, c, 0.0f);
            else if (leaf(n.child[c], n.count[c], tMax))
                return true;
        }
        if (stack.empty()) return false;
        stack.pop(ref, count);
    }
}

}  // namespace rb
