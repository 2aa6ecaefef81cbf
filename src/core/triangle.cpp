#include "core/triangle.h"

namespace rb {

// [watertight-ray]
WatertightRay::WatertightRay(const Ray& r) : o(r.o) {
    // Choose z as the axis where |d| is largest, and keep the winding by swapping x and y
    // when d_z is negative.
    const Vec3 a = glm::abs(r.d);
    kz = a.x > a.y ? (a.x > a.z ? 0 : 2) : (a.y > a.z ? 1 : 2);
    kx = (kz + 1) % 3;
    ky = (kx + 1) % 3;
    if (r.d[kz] < 0.0) std::swap(kx, ky);
    // The shear that maps d to (0, 0, 1).
    Sx = r.d[kx] / r.d[kz];
    Sy = r.d[ky] / r.d[kz];
    Sz = 1.0 / r.d[kz];
}
// [watertight-ray]

// [watertight-triangle]
bool intersectTriangle(const WatertightRay& ray, const Vec3& p0, const Vec3& p1, const Vec3& p2,
                       double tMax, TriangleHit& hit) {
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
}
// [watertight-triangle]

}  // namespace rb
