/// \file
/// Four triangles tested at once: a single-precision filter over a packet of four triangles
/// that can only throw away triangles the ray certainly misses, then the exact watertight test
/// of triangle.h on the few that remain.
#pragma once

#include <xmmintrin.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "bvh/float_rounding.h"
#include "bvh/triangle.h"

namespace rb {

/// Four triangles lane by lane (structure of arrays), so that one SSE load fetches one
/// coordinate of all four. The float vertices serve the filter only; the exact test reads the
/// mesh's double vertices through `vertex`. Lanes past a leaf's count repeat its last triangle.
/// 224 bytes.
struct alignas(16) Triangle4 {
    float p[3][3][4];            ///< [vertex][axis][lane], rounded to nearest.
    float extent[4];             ///< The largest |coordinate| of the lane's vertices, rounded up.
    std::uint32_t vertex[3][4];  ///< Indices of the vertices in the mesh's double positions.
    std::uint32_t source[4];     ///< The OBJ triangle index.
};
static_assert(sizeof(Triangle4) == 224);

/// The ray as the float filter sees it: the watertight test's axis permutation and shear,
/// rounded to float, and the size of the origin's largest coordinate.
struct FilterRay {
    int kx, ky, kz;
    __m128 ox, oy, oz;   ///< Origin, permuted.
    __m128 Sx, Sy;       ///< Shear.
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
          originExtent(
              roundUpToFloat(std::max({std::abs(w.o.x), std::abs(w.o.y), std::abs(w.o.z)}))) {}
};

/// |x| for four floats.
[[gnu::always_inline]] inline __m128 abs4(__m128 x) {
    return _mm_andnot_ps(_mm_set1_ps(-0.0f), x);
}

// [triangle4-filter]
/// Which of the first `count` lanes of `tri` might the ray hit? Bit i of the result is clear
/// only when lane i's triangle certainly lies to one side of the ray: two of the watertight
/// test's edge functions, computed in float, have opposite signs by more than their rounding
/// error can explain. So every triangle that the exact test would hit keeps its bit.
///
/// The error bound, with u = 2⁻²⁴ and M the largest |coordinate| of the vertices plus that of
/// the origin: rounding the vertices, the origin and the shear to float, and the translation
/// and shear themselves, move each sheared coordinate by δ ≤ 9uM; an edge function
/// Cx·By − Cy·Bx then moves by at most 4Xδ + 2δ² + 5uX², X being the largest sheared
/// coordinate (enlarged by δ). The filter keeps twice that as its margin e.
[[gnu::always_inline]] inline int filterTriangle4(const FilterRay& r, const Triangle4& tri,
                                                  int count) {
    constexpr float u = 1.0f / (1 << 24);
    // Step 1: translate to the origin and shear, as the exact test does, in float.
    __m128 x[3], y[3], X = _mm_setzero_ps();
    for (int v = 0; v < 3; ++v) {
        const __m128 a = _mm_sub_ps(_mm_load_ps(tri.p[v][r.kx]), r.ox);
        const __m128 b = _mm_sub_ps(_mm_load_ps(tri.p[v][r.ky]), r.oy);
        const __m128 c = _mm_sub_ps(_mm_load_ps(tri.p[v][r.kz]), r.oz);
        x[v] = _mm_sub_ps(a, _mm_mul_ps(r.Sx, c));
        y[v] = _mm_sub_ps(b, _mm_mul_ps(r.Sy, c));
        X = _mm_max_ps(X, _mm_max_ps(abs4(x[v]), abs4(y[v])));
    }
    // Step 2: the edge functions (A = vertex 0, B = 1, C = 2).
    const __m128 U = _mm_sub_ps(_mm_mul_ps(x[2], y[1]), _mm_mul_ps(y[2], x[1]));
    const __m128 V = _mm_sub_ps(_mm_mul_ps(x[0], y[2]), _mm_mul_ps(y[0], x[2]));
    const __m128 W = _mm_sub_ps(_mm_mul_ps(x[1], y[0]), _mm_mul_ps(y[1], x[0]));
    // Step 3: their error bound e (see above).
    const __m128 M = _mm_add_ps(_mm_load_ps(tri.extent), _mm_set1_ps(r.originExtent));
    const __m128 delta = _mm_mul_ps(_mm_set1_ps(9.0f * u), M);
    const __m128 Xe = _mm_add_ps(X, delta);
    const __m128 bound =
        _mm_add_ps(_mm_mul_ps(_mm_mul_ps(_mm_set1_ps(4.0f), Xe), delta),
                   _mm_add_ps(_mm_mul_ps(_mm_mul_ps(_mm_set1_ps(2.0f), delta), delta),
                              _mm_mul_ps(_mm_mul_ps(_mm_set1_ps(5.0f * u), Xe), Xe)));
    const __m128 e = _mm_mul_ps(_mm_set1_ps(2.0f), bound);
    const __m128 minusE = _mm_sub_ps(_mm_setzero_ps(), e);
    // Step 4: certainly outside when one edge function is clearly negative and another clearly
    // positive. A NaN or infinite value compares false, so such a lane is kept.
    const __m128 negative = _mm_or_ps(_mm_or_ps(_mm_cmplt_ps(U, minusE), _mm_cmplt_ps(V, minusE)),
                                      _mm_cmplt_ps(W, minusE));
    const __m128 positive =
        _mm_or_ps(_mm_or_ps(_mm_cmpgt_ps(U, e), _mm_cmpgt_ps(V, e)), _mm_cmpgt_ps(W, e));
    const int outside = _mm_movemask_ps(_mm_and_ps(negative, positive));
    return ~outside & ((1 << count) - 1);
}
// [triangle4-filter]

/// The vertices of lane `lane` of `tri`, in double, from the mesh's positions.
[[gnu::always_inline]] inline std::array<Vec3, 3> vertices(const Triangle4& tri, int lane,
                                                           const std::vector<Vec3>& positions) {
    return {positions[tri.vertex[0][lane]], positions[tri.vertex[1][lane]],
            positions[tri.vertex[2][lane]]};
}

/// The nearest hit so far on a mesh: its distance and its OBJ triangle index.
struct NearestTriangle {
    double t;                  ///< The ray's limit until a hit is found.
    std::uint32_t source = 0;  ///< 0 until a hit is found.
    bool found = false;
};

// [triangle4]
/// Look for a hit nearer than `nearest` among the first `count` lanes of `tri`: the filter, then
/// the exact test on the lanes it keeps. Returns the lane of the new nearest hit, or -1. Two
/// triangles hit at exactly the same distance (a ray through their shared edge) go to the lower
/// OBJ index, so the answer depends neither on the tree nor on the order of the visit.
[[gnu::always_inline]] inline int intersectTriangle4(const WatertightRay& ray, const FilterRay& r,
                                                     const Triangle4& tri, int count,
                                                     const std::vector<Vec3>& positions,
                                                     NearestTriangle& nearest, TriangleHit& hit) {
    int best = -1;
    for (int mask = filterTriangle4(r, tri, count); mask != 0; mask &= mask - 1) {
        const int lane = __builtin_ctz(mask);
        const std::array<Vec3, 3> v = vertices(tri, lane, positions);
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

/// Does the ray hit any of the first `count` lanes of `tri` in (0, tMax)?
[[gnu::always_inline]] inline bool occludedTriangle4(const WatertightRay& ray, const FilterRay& r,
                                                     const Triangle4& tri, int count,
                                                     const std::vector<Vec3>& positions,
                                                     double tMax) {
    for (int mask = filterTriangle4(r, tri, count); mask != 0; mask &= mask - 1) {
        const int lane = __builtin_ctz(mask);
        const std::array<Vec3, 3> v = vertices(tri, lane, positions);
        TriangleHit unused;
        if (intersectTriangle(ray, v[0], v[1], v[2], tMax, unused)) return true;
    }
    return false;
}

}  // namespace rb
