#include "quadrics/cone.h"

#include <cmath>
#include <limits>
#include <utility>

namespace rb {

// [quadratic-roots]
int quadraticRoots(double A, double H, double C, double disc, std::array<double, 2>& roots) {
    if (!(disc >= 0.0)) return 0;  // no real roots (or a NaN from a degenerate ray)
    // Compute the root away from cancellation first, then the other from the product C/q,
    // as chapter 1 does; this form also survives A = 0, where q/A would divide by zero.
    const double q = -(H + std::copysign(std::sqrt(disc), H));
    if (q == 0.0) {
        // H = 0 and A·C = 0: F is constant (no root), or A·t² (a double root at t = 0).
        if (A == 0.0) return 0;
        roots = {0.0, 0.0};
        return 2;
    }
    if (A == 0.0) {
        roots[0] = C / q;  // the linear equation 2H·t + C = 0
        return 1;
    }
    roots = {q / A, C / q};
    if (roots[0] > roots[1]) std::swap(roots[0], roots[1]);
    return 2;
}
// [quadratic-roots]

// [cone-side]
SideSpans coneSideSpans(const Ray& ray, const ConeProfile& profile) {
    SideSpans spans;
    // [exercise-cone-side]
    // Exercise 15.2, the cone quadratic: read ch15-cone.
    // Blank: return spans;
    constexpr double inf = std::numeric_limits<double>::infinity();
    const Vec3 &o = ray.o, &d = ray.d;
    // Compute the quadratic coefficients of F(t) = x² + z² − r(y)² with r(y) = a + b·y,
    // writing r along the ray as w + t·w_d.
    const double w = profile.a + profile.b * o.y, wd = profile.b * d.y;
    const double A = d.x * d.x + d.z * d.z - wd * wd;
    const double H = o.x * d.x + o.z * d.z - w * wd;
    const double C = o.x * o.x + o.z * o.z - w * w;
    // The discriminant H² − A·C from the 2×2 minors of (o_x, o_z, w) and (d_x, d_z, w_d)
    // (Lagrange's identity for the cone's metric diag(1, 1, −1)): no difference of two
    // products that grow like |o|² when the ray starts far away.
    const double m12 = o.x * d.z - o.z * d.x;
    const double m13 = o.x * wd - w * d.x;
    const double m23 = o.z * wd - w * d.z;
    const double disc = m13 * m13 + m23 * m23 - m12 * m12;
    std::array<double, 2> t;
    const int n = quadraticRoots(A, H, C, disc, t);
    // Inside is F ≤ 0; read the inside set off the roots and the sign of A.
    if (n == 2 && A > 0.0) {
        spans.add(t[0], t[1]);  // shallower than the cone: in between the roots
    } else if (n == 2) {
        spans.add(-inf, t[0]);  // steeper: out of one nappe, then into the other
        spans.add(t[1], inf);
    } else if (n == 1) {
        // A = 0, parallel to the cone's slope: F = 2H·t + C changes sign once.
        if (H > 0.0)
            spans.add(-inf, t[0]);
        else
            spans.add(t[0], inf);
    } else if (A < 0.0 || (A == 0.0 && C <= 0.0)) {
        spans.add(-inf, inf);  // F never changes sign and is ≤ 0
    }
    return spans;
    // [exercise-cone-side]
}
// [cone-side]

int Cone::crossings(const Ray& ray, std::array<QuadricCrossing, 2>& out) const {
    if (isDegenerateDirection(ray.d)) return 0;
    // The second nappe lies above y = (1 + r₁)/(1 − r₁) ≥ 1, so the slab cuts it away.
    const SideSpans side = coneSideSpans(ray, profile_);
    return capped() ? solidCrossings(ray, side, out) : openCrossings(ray, side, out);
}

// [cone-normal]
Vec3 Cone::normal(const Vec3& p, QuadricPart part) const {
    if (part == QuadricPart::Bottom) return Vec3(0.0, -1.0, 0.0);
    if (part == QuadricPart::Top) return Vec3(0.0, 1.0, 0.0);
    // [exercise-cone-normal]
    // Exercise 15.4, the cone's normal: read ch15-normals.
    // Blank: return Vec3(p.x, 0.0, p.z);
    // ∇(x² + z² − r(y)²)/2 = (x, −b·r, z), and on the surface r = ρ = √(x² + z²). Divided by
    // ρ it is (x/ρ, −b, z/ρ), which keeps its length as the point nears the apex.
    const double rho = std::sqrt(p.x * p.x + p.z * p.z);
    // At the apex itself the normal is undefined: take the axis the apex faces, never a zero
    // vector, which would normalise to NaN.
    if (!(rho > 0.0)) return Vec3(0.0, 1.0, 0.0);
    return Vec3(p.x / rho, -profile_.b, p.z / rho);
    // [exercise-cone-normal]
}
// [cone-normal]

}  // namespace rb
