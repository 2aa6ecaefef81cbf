/// \file
/// Four triangles tested at once: the watertight test in single precision over a packet of four
/// triangles, with an error bound on each of its values, decides every lane it can (a certain
/// miss; for a shadow ray, a certain hit too), and the exact double-precision test of triangle.h
/// runs only on the lanes it cannot decide, and on the hits a closest-hit query must measure.
#pragma once

#include <xmmintrin.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "bvh/float_rounding.h"
#include "bvh/traversal_counts.h"
#include "bvh/triangle.h"

namespace rb {

/// Four triangles lane by lane (structure of arrays), so that one SSE load fetches one
/// coordinate of all four. These float vertices are the mesh's only copy: the float test reads
/// them, and the exact test reads them too, widened to double (exactly), so the pack it has just
/// filtered is the only memory it touches. Lanes past a leaf's count repeat its last triangle.
/// 176 bytes.
struct alignas(16) Triangle4 {
    float p[3][3][4];         ///< [vertex][axis][lane]: the mesh's vertices, in float.
    float extent[4];          ///< The largest |coordinate| of the lane's vertices.
    std::uint32_t source[4];  ///< The OBJ triangle index.
};
static_assert(sizeof(Triangle4) == 176);

/// The ray as the float filter sees it: the watertight test's axis permutation and shear,
/// rounded to float, and the size of the origin's largest coordinate.
struct FilterRay {
    int kx, ky, kz;
    __m128 ox, oy, oz;   ///< Origin, permuted.
    __m128 Sx, Sy, Sz;   ///< Shear and scale.
    float originExtent;  ///< max |o|, rounded up.

    explicit FilterRay(const WatertightRay& w)
        : kx(w.kx),
          ky(w.ky),
          kz(w.kz),
          ox(_mm_set1_ps(static_cast<float>(w.o[w.kx]))),
          oy(_mm_set1_ps(static_cast<float>(w.o[w.ky]))),
          oz(_mm_set1_ps(static_cast<float>(w.o[w.kz]))),
          Sx(_mm_set1_ps(static_cast<float>(w.Sx))),
          Sy(_mm_set1_ps(static_cast<float>(w.Sy))),
          Sz(_mm_set1_ps(static_cast<float>(w.Sz))),
          originExtent(
              roundUpToFloat(std::max({std::abs(w.o.x), std::abs(w.o.y), std::abs(w.o.z)}))) {}
};

/// A query's distance limit tMax as the float test compares with it: two floats around it,
/// chosen so that a comparison in float, however it rounds, still decides against tMax.
struct FloatLimit {
    float below;  ///< Below tMax by more than 2⁻²¹ of it (0 when tMax is tiny).
    float above;  ///< At least tMax (+∞ for an unlimited ray).

    explicit FloatLimit(double tMax) {
        // roundDownToFloat(tMax) ≤ tMax; the factor 1 − 2⁻²⁰, rounded, keeps it below
        // tMax·(1 − 2⁻²¹) while it is a normal float (the 2⁻¹⁰⁰ keeps subnormals out).
        const float down = roundDownToFloat(tMax);
        below = down >= 0x1p-100f ? down * (1.0f - 0x1p-20f) : 0.0f;
        // Rounding up, and a factor above 1 rounded to nearest, never go below tMax.
        above = roundUpToFloat(tMax) * (1.0f + 0x1p-20f);
    }
};

/// What the float test decides about the lanes of a pack.
struct Triangle4Verdict {
    int maybe;  ///< Lanes the exact test might hit in (0, tMax); it certainly misses the others.
    int hit;    ///< Lanes among `maybe` that it certainly hits in (0, tMax).
};

/// |x| for four floats.
[[gnu::always_inline]] inline __m128 abs4(__m128 x) {
    return _mm_andnot_ps(_mm_set1_ps(-0.0f), x);
}

// [triangle4-filter]
/// The watertight test in float on the first `count` lanes of `tri`, each of its values with a
/// bound on how far it can be from the value the exact double test computes. A lane is decided
/// only when the bounds leave no doubt: a certain miss (two edge functions of opposite signs,
/// or a distance certainly ≤ 0 or ≥ tMax) or a certain hit (three edge functions of one sign
/// and a distance certainly in (0, tMax)). So the exact test, run on `maybe`, agrees with it.
///
/// The error bounds, with u = 2⁻²⁴, γₙ = nu/(1 − nu), and M the largest |coordinate| of the
/// vertices plus that of the origin. Sources: Higham, "Accuracy and Stability of Numerical
/// Algorithms" (2nd ed., 2002), §2.2 and Lemma 3.1 (|fl(Σ xᵢyᵢ) − Σ xᵢyᵢ| ≤ γₙ Σ|xᵢyᵢ|);
/// Pharr, Jakob and Humphreys, "Physically Based Rendering" (3rd ed.), §3.9.2 (the same γₙ
/// bounds for a float ray–triangle test).
/// - Edge functions. Rounding the vertices, the origin and the shear to float, and the
///   translation and shear themselves, move each sheared coordinate x, y by δ ≤ 9uM; an edge
///   function Cx·By − Cy·Bx then moves by at most 4Xδ + 2δ² + 5uX², X being the largest
///   sheared coordinate (enlarged by δ). E is twice that: twice covers the rounding of the
///   bound itself and of the double test (2²⁹ times finer).
/// - Scaled z. z = fl(Sz·fl(p − o)): rounding p and o moves p − o by u·M, the subtraction by
///   u|p − o| ≤ uM, the rounding of Sz and the product by 2u of the result, so
///   |z_f − z| ≤ 5u|Sz|M (1 + O(u)) ≤ δz = 6u|Sz|M. Z is the largest |z_f|.
/// - det = U + V + W: three edge functions off by E each, and two roundings of a sum of
///   S = |U| + |V| + |W|: |det_f − det| ≤ 3E + γ₂S. The bound kept, e_det, is twice 3E + 3uS.
/// - T = U·z₀ + V·z₁ + W·z₂: each product moves by |ΔU||z_f| + |U||Δz| ≤ E·Z + (|U_f| + E)δz,
///   and the sum of three products rounds by γ₃·Σ|U_f||z_f| ≤ γ₃·S·Z (Higham's Lemma 3.1):
///   |T_f − T| ≤ 3E·Z + (S + 3E)δz + γ₃SZ. The bound kept, e_T, is twice that with 4u for γ₃.
/// - t = T/det, for det certainly of one sign (|det_f| > e_det): with the signs made positive,
///   T ∈ [T_f − e_T, T_f + e_T] and det ∈ [det_f − e_det, det_f + e_det], so t ≤ 0 when
///   T_f + e_T ≤ 0, and t ≥ tMax when T_f − e_T ≥ fl(above·(det_f + e_det)), a normal float
///   (FloatLimit says why its rounding cannot matter); t < tMax when T_f + e_T <
///   fl(below·(det_f − e_det)), since below·(1 + u) < tMax·(1 − 2⁻²²) and the double division
///   rounds by 2⁻⁵³ only.
/// A NaN or infinite value compares false everywhere, so such a lane is never decided. With
/// kDecideDistance false the test stops after step 4: `maybe` from the edge functions alone,
/// and no lane called a hit.
template <bool kDecideDistance = true>
[[gnu::always_inline]] inline Triangle4Verdict testTriangle4(const FilterRay& r,
                                                             const Triangle4& tri, int count,
                                                             const FloatLimit& limit) {
    constexpr float u = 0x1p-24f;
    // Step 1: translate to the origin, shear and scale, as the exact test does, in float.
    __m128 x[3], y[3], z[3], X = _mm_setzero_ps(), Z = _mm_setzero_ps();
    for (int v = 0; v < 3; ++v) {
        const __m128 a = _mm_sub_ps(_mm_load_ps(tri.p[v][r.kx]), r.ox);
        const __m128 b = _mm_sub_ps(_mm_load_ps(tri.p[v][r.ky]), r.oy);
        const __m128 c = _mm_sub_ps(_mm_load_ps(tri.p[v][r.kz]), r.oz);
        x[v] = _mm_sub_ps(a, _mm_mul_ps(r.Sx, c));
        y[v] = _mm_sub_ps(b, _mm_mul_ps(r.Sy, c));
        z[v] = _mm_mul_ps(r.Sz, c);
        X = _mm_max_ps(X, _mm_max_ps(abs4(x[v]), abs4(y[v])));
        Z = _mm_max_ps(Z, abs4(z[v]));
    }
    // Step 2: the edge functions (A = vertex 0, B = 1, C = 2).
    const __m128 U = _mm_sub_ps(_mm_mul_ps(x[2], y[1]), _mm_mul_ps(y[2], x[1]));
    const __m128 V = _mm_sub_ps(_mm_mul_ps(x[0], y[2]), _mm_mul_ps(y[0], x[2]));
    const __m128 W = _mm_sub_ps(_mm_mul_ps(x[1], y[0]), _mm_mul_ps(y[1], x[0]));
    // Step 3: their error bound E (see above).
    const __m128 M = _mm_add_ps(_mm_load_ps(tri.extent), _mm_set1_ps(r.originExtent));
    const __m128 delta = _mm_mul_ps(_mm_set1_ps(9.0f * u), M);
    const __m128 Xe = _mm_add_ps(X, delta);
    const __m128 bound =
        _mm_add_ps(_mm_mul_ps(_mm_mul_ps(_mm_set1_ps(4.0f), Xe), delta),
                   _mm_add_ps(_mm_mul_ps(_mm_mul_ps(_mm_set1_ps(2.0f), delta), delta),
                              _mm_mul_ps(_mm_mul_ps(_mm_set1_ps(5.0f * u), Xe), Xe)));
    const __m128 E = _mm_mul_ps(_mm_set1_ps(2.0f), bound);
    const __m128 minusE = _mm_sub_ps(_mm_setzero_ps(), E);
    // Step 4: certainly outside when one edge function is clearly negative and another clearly
    // positive.
    const __m128 negative = _mm_or_ps(_mm_or_ps(_mm_cmplt_ps(U, minusE), _mm_cmplt_ps(V, minusE)),
                                      _mm_cmplt_ps(W, minusE));
    const __m128 positive =
        _mm_or_ps(_mm_or_ps(_mm_cmpgt_ps(U, E), _mm_cmpgt_ps(V, E)), _mm_cmpgt_ps(W, E));
    int maybe = ~_mm_movemask_ps(_mm_and_ps(negative, positive)) & ((1 << count) - 1);
    if (!kDecideDistance || maybe == 0) return {maybe, 0};
    // Step 5: the determinant and the scaled distance, with their bounds e_det and e_T.
    const __m128 det = _mm_add_ps(_mm_add_ps(U, V), W);
    const __m128 T =
        _mm_add_ps(_mm_add_ps(_mm_mul_ps(U, z[0]), _mm_mul_ps(V, z[1])), _mm_mul_ps(W, z[2]));
    const __m128 S = _mm_add_ps(_mm_add_ps(abs4(U), abs4(V)), abs4(W));
    const __m128 E3 = _mm_mul_ps(_mm_set1_ps(3.0f), E);
    const __m128 deltaZ = _mm_mul_ps(_mm_mul_ps(_mm_set1_ps(6.0f * u), abs4(r.Sz)), M);
    const __m128 eDet =
        _mm_mul_ps(_mm_set1_ps(2.0f), _mm_add_ps(E3, _mm_mul_ps(_mm_set1_ps(3.0f * u), S)));
    const __m128 eT =
        _mm_mul_ps(_mm_set1_ps(2.0f),
                   _mm_add_ps(_mm_add_ps(_mm_mul_ps(E3, Z), _mm_mul_ps(_mm_add_ps(S, E3), deltaZ)),
                              _mm_mul_ps(_mm_mul_ps(_mm_set1_ps(4.0f * u), S), Z)));
    // Step 6: make det positive (T takes its sign), and bound both.
    const __m128 sign = _mm_and_ps(det, _mm_set1_ps(-0.0f));
    const __m128 Tn = _mm_xor_ps(T, sign), Dn = abs4(det);
    const __m128 Dlo = _mm_sub_ps(Dn, eDet), Dhi = _mm_add_ps(Dn, eDet);
    const __m128 Tlo = _mm_sub_ps(Tn, eT), Thi = _mm_add_ps(Tn, eT);
    const __m128 detCertain = _mm_cmpgt_ps(Dlo, _mm_setzero_ps());
    const __m128 normal = _mm_set1_ps(0x1p-126f);
    // Step 7: certainly behind the origin, or certainly at or beyond tMax: a miss.
    const __m128 farProduct = _mm_mul_ps(_mm_set1_ps(limit.above), Dhi);
    const __m128 behind = _mm_cmple_ps(Thi, _mm_setzero_ps());
    const __m128 beyond =
        _mm_and_ps(_mm_cmpge_ps(Tlo, farProduct), _mm_cmpge_ps(farProduct, normal));
    maybe &= ~_mm_movemask_ps(_mm_and_ps(detCertain, _mm_or_ps(behind, beyond)));
    // Step 8: certainly inside, and certainly in (0, tMax): a hit.
    const __m128 inside = _mm_or_ps(
        _mm_and_ps(_mm_and_ps(_mm_cmpgt_ps(U, E), _mm_cmpgt_ps(V, E)), _mm_cmpgt_ps(W, E)),
        _mm_and_ps(_mm_and_ps(_mm_cmplt_ps(U, minusE), _mm_cmplt_ps(V, minusE)),
                   _mm_cmplt_ps(W, minusE)));
    const __m128 nearProduct = _mm_mul_ps(_mm_set1_ps(limit.below), Dlo);
    const __m128 inRange =
        _mm_and_ps(_mm_and_ps(_mm_cmpgt_ps(Tlo, _mm_setzero_ps()), _mm_cmplt_ps(Thi, nearProduct)),
                   _mm_cmpge_ps(nearProduct, normal));
    const int hit = _mm_movemask_ps(_mm_and_ps(_mm_and_ps(inside, detCertain), inRange));
    return {maybe, hit & maybe};
}
// [triangle4-filter]

/// The float test's first half alone (steps 1 to 4): the lanes whose edge functions do not
/// certainly rule out a hit. A closest-hit query uses only this: it must run the exact test on
/// its hits anyway, to report their exact distance, and deciding distances in float as well
/// measured slower (chapter 3, "What each step bought").
[[gnu::always_inline]] inline int filterTriangle4(const FilterRay& r, const Triangle4& tri,
                                                  int count) {
    return testTriangle4<false>(r, tri, count, FloatLimit(0.0)).maybe;
}

/// The vertices of lane `lane` of `tri`, widened to double (every float is a double exactly).
[[gnu::always_inline]] inline std::array<Vec3, 3> vertices(const Triangle4& tri, int lane) {
    std::array<Vec3, 3> v;
    for (int vertex = 0; vertex < 3; ++vertex)
        v[vertex] = Vec3(tri.p[vertex][0][lane], tri.p[vertex][1][lane], tri.p[vertex][2][lane]);
    return v;
}

/// The nearest hit so far on a mesh: its distance and its OBJ triangle index.
struct NearestTriangle {
    double t;                  ///< The ray's limit until a hit is found.
    std::uint32_t source = 0;  ///< 0 until a hit is found.
    bool found = false;
};

// [triangle4]
/// Look for a hit nearer than `nearest` among the first `count` lanes of `tri`: the float
/// filter, then the exact test on the lanes it keeps (a hit's distance and barycentrics are the
/// exact test's, to the last bit). Returns the lane of the new nearest hit, or -1. Two
/// triangles hit at exactly the same distance (a ray through their shared edge) go to the lower
/// OBJ index, so the answer depends neither on the tree nor on the order of the visit.
/// `counts` counts the pack and its exact tests (TraversalCounts), or nothing.
template <class Counts = NoCounts>
[[gnu::always_inline]] inline int intersectTriangle4(const WatertightRay& ray, const FilterRay& r,
                                                     const Triangle4& tri, int count,
                                                     NearestTriangle& nearest, TriangleHit& hit,
                                                     Counts&& counts = {}) {
    int best = -1;
    counts.pack();
    for (int mask = filterTriangle4(r, tri, count); mask != 0; mask &= mask - 1) {
        const int lane = __builtin_ctz(mask);
        counts.exact();
        const std::array<Vec3, 3> v = vertices(tri, lane);
        // After a hit, a tie at exactly its distance is considered too.
        const double tLimit = nearest.found ? nextUp(nearest.t) : nearest.t;
        TriangleHit h;
        if (!intersectTriangle(ray, v[0], v[1], v[2], tLimit, h)) continue;
        if (h.t == nearest.t && tri.source[lane] >= nearest.source) continue;
        nearest = {h.t, tri.source[lane], true};
        hit = h;
        best = lane;
    }
    return best;
}
// [triangle4]

/// Does the ray hit any of the first `count` lanes of `tri` in (0, tMax)? `limit` is
/// FloatLimit(tMax). A certain hit of the float test answers; the exact test runs only on the
/// lanes the float test could not decide. `counts` as for intersectTriangle4().
template <class Counts = NoCounts>
[[gnu::always_inline]] inline bool occludedTriangle4(const WatertightRay& ray, const FilterRay& r,
                                                     const Triangle4& tri, int count, double tMax,
                                                     const FloatLimit& limit,
                                                     Counts&& counts = {}) {
    counts.pack();
    const Triangle4Verdict verdict = testTriangle4(r, tri, count, limit);
    if (verdict.hit != 0) return true;
    for (int mask = verdict.maybe; mask != 0; mask &= mask - 1) {
        const int lane = __builtin_ctz(mask);
        counts.exact();
        const std::array<Vec3, 3> v = vertices(tri, lane);
        TriangleHit unused;
        if (intersectTriangle(ray, v[0], v[1], v[2], tMax, unused)) return true;
    }
    return false;
}

}  // namespace rb
