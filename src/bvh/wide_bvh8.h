/// \file
/// The eight-wide BVH: the same tree as wide_bvh.h collapsed into nodes of eight children, whose
/// boxes are tested together with AVX2. Chapter 3's "going further" section. Only x86-64 has
/// it, and only some x86-64 CPUs: every function here is compiled for AVX2 alone (the
/// `target("avx2")` attribute, not a compiler flag, so no AVX2 instruction reaches code that
/// runs before the check), and the BVH takes this path only after wide8Available() said yes.
/// Elsewhere (another CPU family, or the WebAssembly build) RB_HAVE_WIDE8 is 0 and the
/// four-wide SSE path is the widest.
#pragma once

#include "bvh/wide_bvh.h"

#if defined(__x86_64__) && !defined(__EMSCRIPTEN__)
#define RB_HAVE_WIDE8 1
#else
#define RB_HAVE_WIDE8 0
#endif

namespace rb {

/// True when this build has the eight-wide path and this CPU (and its operating system, which
/// must save the 256-bit registers) runs AVX2. Asked once per BVH build, not per ray.
bool wide8Available();

}  // namespace rb

#if RB_HAVE_WIDE8

#include <immintrin.h>

/// The eight-wide functions' attribute: AVX2, and nothing more. Not FMA: the leaf tests are
/// inlined into these functions, and contracting the exact triangle test's a·b + c into one
/// rounding would change its bits, so the images would depend on the path. The build's
/// -ffp-contract=off forbids that too; leaving FMA out keeps it so without the flag.
#define RB_AVX2 gnu::target("avx2")

namespace rb {

/// Lane `lane` of v in all eight lanes.
[[gnu::always_inline, RB_AVX2]] inline __m256 broadcastLane(__m128 v, int lane) {
    return _mm256_permutevar8x32_ps(_mm256_castps128_ps256(v), _mm256_set1_epi32(lane));
}

/// The ray of WideRay, each value in all eight lanes; the plane offsets are those of a
/// WideNode8 (lo[3][8], then hi[3][8]), twice those of a WideNode. Built as WideRay builds its
/// values, with the same operations on the same numbers (so the same bits), but for x, y and z
/// at once: the origins and reciprocals in one register each, the near and far origins picked
/// by a blend on the reciprocal's sign, not axis by axis through memory.
struct WideRay8 {
    __m256 oNear[3], oFar[3], invDNear[3], invDFar[3];
    int nearPlane[3], farPlane[3];  ///< Offsets, in floats, of the near and far planes in a node.

    [[gnu::always_inline, RB_AVX2]] explicit WideRay8(const Ray& r) {
        // x, y, z in lanes 0–2, converted to float (round to nearest); lane 3 is unused.
        const __m128 o = _mm256_cvtpd_ps(_mm256_set_pd(0.0, r.o.z, r.o.y, r.o.x));
        const __m128 invD = _mm256_cvtpd_ps(
            _mm256_div_pd(_mm256_set1_pd(1.0), _mm256_set_pd(1.0, r.d.z, r.d.y, r.d.x)));
        // The origin moved up and down by more than its rounding (WideRay says why).
        const __m128 absO = _mm_andnot_ps(_mm_set1_ps(-0.0f), o);
        const __m128 err =
            _mm_add_ps(_mm_mul_ps(absO, _mm_set1_ps(1.0f / (1 << 23))), _mm_set1_ps(0x1p-149f));
        const __m128 up = _mm_add_ps(o, err), down = _mm_sub_ps(o, err);
        // A negative direction (the sign bit of 1/d) swaps the near and far origins and planes.
        const __m128 near = _mm_blendv_ps(up, down, invD);
        const __m128 far = _mm_blendv_ps(down, up, invD);
        const __m128 invDFar4 = _mm_mul_ps(invD, _mm_set1_ps(kFarWidening));
        const int negative = _mm_movemask_ps(invD);
        for (int axis = 0; axis < 3; ++axis) {
            oNear[axis] = broadcastLane(near, axis);
            oFar[axis] = broadcastLane(far, axis);
            invDNear[axis] = broadcastLane(invD, axis);
            invDFar[axis] = broadcastLane(invDFar4, axis);
            const int lo = 8 * axis, hi = 24 + 8 * axis;  // WideNode8: lo[3][8], then hi[3][8]
            nearPlane[axis] = negative >> axis & 1 ? hi : lo;
            farPlane[axis] = negative >> axis & 1 ? lo : hi;
        }
    }
};

// [wide8-slab-test]
/// The slab test of intersectChildren4 against the eight children of n at once: bit c of the
/// result is set when the ray enters child c for some t in (0, tMax], with the entry distance in
/// tEntry lane c. The same arithmetic, lane for lane, so the same margins make it conservative:
/// the far planes use the reciprocal stretched by kFarWidening, and `tMax` is the closest hit
/// so far rounded up to float and stretched.
[[gnu::always_inline, RB_AVX2]] inline int intersectChildren8(const WideNode8& n, const WideRay8& r,
                                                              __m256 tMax, __m256& tEntry) {
    const float* planes = &n.lo[0][0];
    __m256 t0 = _mm256_setzero_ps(), t1 = tMax;
    for (int axis = 0; axis < 3; ++axis) {
        // Near and far planes by the sign of the direction, eight children at a time.
        const __m256 tNear =
            _mm256_mul_ps(_mm256_sub_ps(_mm256_load_ps(planes + r.nearPlane[axis]), r.oNear[axis]),
                          r.invDNear[axis]);
        const __m256 tFar =
            _mm256_mul_ps(_mm256_sub_ps(_mm256_load_ps(planes + r.farPlane[axis]), r.oFar[axis]),
                          r.invDFar[axis]);
        // vmaxps/vminps return their second operand when either is NaN, as maxps/minps do.
        t0 = _mm256_max_ps(tNear, t0);
        t1 = _mm256_min_ps(tFar, t1);
    }
    tEntry = t0;
    return _mm256_movemask_ps(_mm256_cmp_ps(t0, t1, _CMP_LE_OQ));
}
// [wide8-slab-test]

/// The closest hit so far, rounded up to float and stretched, in all eight lanes.
[[gnu::always_inline, RB_AVX2]] inline __m256 wideTMax8(double tMax) {
    return _mm256_set1_ps(roundUpToFloat(tMax) * kFarWidening);
}

// [wide8-traverse]
/// closestWide over eight-wide nodes: the same walk (children hit visited nearest first, the
/// others waiting on the stack with their entry distance), eight boxes per node.
template <class LeafTest, class Counts>
[[gnu::always_inline, RB_AVX2]] inline bool closestWide8(const std::vector<WideNode8>& nodes,
                                                         const Ray& ray, double& tMax,
                                                         LeafTest&& leaf, Counts& counts) {
    if (nodes.empty()) return false;
    const WideRay8 r(ray);
    __m256 tMaxF = wideTMax8(tMax);
    WideStack<8> stack;
    bool found = false;
    std::uint32_t ref = 0, count = 0;  // start at the root node
    for (;;) {
        if (count > 0) {
            // A leaf: test its primitives.
            if (leaf(ref, count, tMax)) {
                found = true;
                tMaxF = wideTMax8(tMax);
            }
        } else {
            // A node: which children does the ray enter, and where?
            const WideNode8& n = nodes[ref];
            counts.node();
            __m256 tEntry;
            int mask = intersectChildren8(n, r, tMaxF, tEntry);
            if (mask != 0) {
                const int c = __builtin_ctz(mask);
                mask &= mask - 1;
                if (mask == 0) {
                    // One child: go straight on.
                    ref = n.child[c];
                    count = n.count[c];
                    continue;
                }
                alignas(32) float t[8];
                _mm256_store_ps(t, tEntry);
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
        stack.dropBeyond(_mm256_cvtss_f32(tMaxF));
        if (stack.empty()) return found;
        stack.pop(ref, count);
    }
}
// [wide8-traverse]

/// anyWide over eight-wide nodes: stops at the first leaf for which leaf(first, count, tMax)
/// returns true.
template <class LeafTest, class Counts>
[[gnu::always_inline, RB_AVX2]] inline bool anyWide8(const std::vector<WideNode8>& nodes,
                                                     const Ray& ray, double tMax, LeafTest&& leaf,
                                                     Counts& counts) {
    if (nodes.empty()) return false;
    const WideRay8 r(ray);
    const __m256 tMaxF = wideTMax8(tMax);
    WideStack<8> stack;
    std::uint32_t ref = 0, count = 0;  // start at the root node
    for (;;) {
        const WideNode8& n = nodes[ref];
        counts.node();
        __m256 tEntry;
        for (int mask = intersectChildren8(n, r, tMaxF, tEntry); mask; mask &= mask - 1) {
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

/// closestWide8 as a function of its own, compiled for AVX2, that a caller compiled for any
/// x86-64 may call (a function cannot be inlined into one with fewer instructions). The leaf
/// test is inlined into it. `counts` counts the nodes visited (TraversalCounts), or nothing.
template <class LeafTest, class Counts>
[[gnu::noinline, RB_AVX2]] bool closestWide8Call(const std::vector<WideNode8>& nodes,
                                                 const Ray& ray, double& tMax, LeafTest& leaf,
                                                 Counts& counts) {
    return closestWide8(nodes, ray, tMax, leaf, counts);
}

/// anyWide8 as a function of its own, compiled for AVX2 (see closestWide8Call).
template <class LeafTest, class Counts>
[[gnu::noinline, RB_AVX2]] bool anyWide8Call(const std::vector<WideNode8>& nodes, const Ray& ray,
                                             double tMax, LeafTest& leaf, Counts& counts) {
    return anyWide8(nodes, ray, tMax, leaf, counts);
}

}  // namespace rb

#endif  // RB_HAVE_WIDE8
