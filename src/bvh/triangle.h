/// \file
/// Watertight ray–triangle intersection (Woop, Benthin and Wald 2013).
#pragma once

#include "core/ray.h"

namespace rb {

/// A ray prepared for the watertight test: a permutation that makes z the dominant axis of
/// the direction, and a shear that turns the direction into +z.
struct WatertightRay {
    Vec3 o;
    int kx, ky, kz;
    double Sx, Sy, Sz;
    /// Prepare ray r.
    explicit WatertightRay(const Ray& r);
};

/// The result of a triangle test: distance and barycentrics (b0 for p0, b1 for p1, b2 for p2).
struct TriangleHit {
    double t;
    double b0, b1, b2;
};

// [watertight-triangle]
/// Does the ray hit triangle (p0, p1, p2) at some t in (0, tMax)? Either side counts (no
/// back-face culling). Watertight: a ray through a shared edge hits at least one of the two
/// triangles, and a degenerate triangle is never hit.
[[gnu::always_inline]] inline bool intersectTriangle(const WatertightRay& ray, const Vec3& p0,
                                                     const Vec3& p1, const Vec3& p2, double tMax,
                                                     TriangleHit& hit) {
    // [exercise-watertight-triangle]
    // Exercise 3.1, the watertight ray–triangle test: read ch03-equations.
    // Blank: return false;
    // Translate the vertices so the ray starts at the origin.
    const Vec3 A = p0 - ray.o, B = p1 - ray.o, C = p2 - ray.o;
    // Shear and scale them so the ray runs along +z.
    const double Ax = A[ray.kx] - ray.Sx * A[ray.kz], Ay = A[ray.ky] - ray.Sy * A[ray.kz];
    const double Bx = B[ray.kx] - ray.Sx * B[ray.kz], By = B[ray.ky] - ray.Sy * B[ray.kz];
    const double Cx = C[ray.kx] - ray.Sx * C[ray.kz], Cy = C[ray.ky] - ray.Sy * C[ray.kz];
    // Edge functions: the signed areas the ray's foot makes with each edge. Each is computed
    // the same way for both triangles sharing an edge, so no ray slips between them.
    const double U = Cx * By - Cy * Bx;
    const double V = Ax * Cy - Ay * Cx;
    const double W = Bx * Ay - By * Ax;
    // Inside means all three have one sign (either sign: no back-face culling).
    if ((U < 0.0 || V < 0.0 || W < 0.0) && (U > 0.0 || V > 0.0 || W > 0.0)) return false;
    const double det = U + V + W;
    if (det == 0.0) return false;  // the ray is in the triangle's plane, or it is degenerate
    // The scaled distance along the ray.
    const double Az = ray.Sz * A[ray.kz], Bz = ray.Sz * B[ray.kz], Cz = ray.Sz * C[ray.kz];
    const double T = U * Az + V * Bz + W * Cz;
    const double t = T / det;
    if (!(t > 0.0 && t < tMax)) return false;
    const double invDet = 1.0 / det;
    hit = TriangleHit{t, U * invDet, V * invDet, W * invDet};
    return true;
    // [exercise-watertight-triangle]
}
// [watertight-triangle]

}  // namespace rb
