#include "quadrics/quadric.h"

#include <cmath>
#include <glm/gtc/constants.hpp>
#include <limits>
#include <utility>

namespace rb {

// [clip-to-slab]
bool clipToSlab(const Ray& ray, const SideSpans& side, SolidSpan& span) {
    // [exercise-cap-slab]
    // Exercise 15.3, the caps as a slab: read ch15-caps.
    // Blank: return false;
    constexpr double inf = std::numeric_limits<double>::infinity();
    // Find the slab −1 ≤ y ≤ 1 along the line, and the cap through which it enters.
    double s0 = -inf, s1 = inf;
    QuadricPart capIn = QuadricPart::Bottom, capOut = QuadricPart::Top;
    if (ray.d.y == 0.0) {
        // Parallel to the caps: between them everywhere or nowhere.
        if (ray.o.y < -1.0 || ray.o.y > 1.0) return false;
    } else {
        s0 = (-1.0 - ray.o.y) / ray.d.y;
        s1 = (1.0 - ray.o.y) / ray.d.y;
        if (s0 > s1) {
            std::swap(s0, s1);
            std::swap(capIn, capOut);
        }
    }
    // Intersect each side span with the slab; the larger start and the smaller end win, and
    // the surface they belong to is the one the line crosses there.
    bool any = false;
    for (int k = 0; k < side.count; ++k) {
        SolidSpan piece;
        const bool sideIn = side.lo[k] > s0, sideOut = side.hi[k] < s1;
        piece.tIn = sideIn ? side.lo[k] : s0;
        piece.partIn = sideIn ? QuadricPart::Side : capIn;
        piece.tOut = sideOut ? side.hi[k] : s1;
        piece.partOut = sideOut ? QuadricPart::Side : capOut;
        if (piece.tIn > piece.tOut) continue;
        // A convex solid meets a line in one interval; two pieces only survive rounding at a
        // cone's apex, where they touch. Their hull is then the interval.
        if (!any || piece.tIn < span.tIn) {
            span.tIn = piece.tIn;
            span.partIn = piece.partIn;
        }
        if (!any || piece.tOut > span.tOut) {
            span.tOut = piece.tOut;
            span.partOut = piece.partOut;
        }
        any = true;
    }
    return any;
    // [exercise-cap-slab]
}
// [clip-to-slab]

int solidCrossings(const Ray& ray, const SideSpans& side, std::array<QuadricCrossing, 2>& out) {
    SolidSpan span;
    if (!clipToSlab(ray, side, span)) return 0;
    // A line parallel to the caps meets a side in a finite stretch, and a line crossing the
    // slab leaves it in a finite one: infinite ends come only from degenerate input.
    if (!std::isfinite(span.tIn) || !std::isfinite(span.tOut)) return 0;
    out[0] = {span.tIn, span.partIn};
    out[1] = {span.tOut, span.partOut};
    return 2;
}

int openCrossings(const Ray& ray, const SideSpans& side, std::array<QuadricCrossing, 2>& out) {
    int n = 0;
    // Each finite end of a span is a root of the side's quadratic: keep those between the caps.
    for (int k = 0; k < side.count; ++k)
        for (const double t : {side.lo[k], side.hi[k]}) {
            const double y = ray.o.y + t * ray.d.y;
            if (std::isfinite(t) && y >= -1.0 && y <= 1.0 && n < 2)
                out[n++] = {t, QuadricPart::Side};
        }
    if (n == 2 && out[0].t > out[1].t) std::swap(out[0], out[1]);
    return n;
}

Vec2 quadricUv(const Vec3& p, QuadricPart part) {
    if (part != QuadricPart::Side) return {0.5 * (p.x + 1.0), 0.5 * (p.z + 1.0)};
    // atan2 returns (−π, π]; shift the back half up so u runs over [0, 1).
    double u = std::atan2(p.x, p.z) / (2.0 * glm::pi<double>());
    if (u < 0.0) u += 1.0;
    return {u, 0.5 * (p.y + 1.0)};
}

bool Quadric::surfaceCoordinates(const Vec3& p, std::uint32_t part, Vec2& uv, Vec3& dpdu,
                                 Vec3& dpdv) const {
    uv = quadricUv(p, static_cast<QuadricPart>(part));
    if (static_cast<QuadricPart>(part) != QuadricPart::Side) {
        // The cap's disk: u = (x + 1)/2, v = (z + 1)/2.
        dpdu = Vec3(2.0, 0.0, 0.0);
        dpdv = Vec3(0.0, 0.0, 2.0);
        return true;
    }
    // p = (r(y) sin φ, y, r(y) cos φ) with φ = 2πu and y = 2v − 1: dp/dφ = (z, 0, −x), and
    // dp/dy = (r'·sin φ, 1, r'·cos φ), where sin φ = x/r (0 at a cone's apex).
    constexpr double twoPi = 2.0 * glm::pi<double>();
    dpdu = twoPi * Vec3(p.z, 0.0, -p.x);
    const double r = std::sqrt(p.x * p.x + p.z * p.z);
    const double slope = radiusSlope();
    dpdv = r > 0.0 ? 2.0 * Vec3(slope * p.x / r, 1.0, slope * p.z / r) : Vec3(0.0, 2.0, 0.0);
    return true;
}

ObjectHit Quadric::hitAt(const Ray& ray, const QuadricCrossing& c) const {
    ObjectHit hit;
    hit.t = c.t;
    const Vec3 p = ray.o + c.t * ray.d;
    hit.n = normal(p, c.part);
    hit.uv = quadricUv(p, c.part);
    hit.primitive = static_cast<std::uint32_t>(c.part);
    return hit;
}

int Quadric::allHits(const Ray& ray, std::array<ObjectHit, 2>& out) const {
    std::array<QuadricCrossing, 2> c;
    const int n = crossings(ray, c);
    for (int k = 0; k < n; ++k) out[k] = hitAt(ray, c[k]);
    return n;
}

// [quadric-intersect]
bool Quadric::intersect(const Ray& ray, double tMax, ObjectHit& hit) const {
    // The closest hit is the first crossing ahead of the origin: the entry when the ray
    // starts outside, the exit when it starts inside (a refracted ray in a glass cylinder).
    std::array<QuadricCrossing, 2> c;
    const int n = crossings(ray, c);
    for (int k = 0; k < n; ++k)
        if (c[k].t > 0.0) {
            if (c[k].t >= tMax) return false;
            hit = hitAt(ray, c[k]);
            return true;
        }
    return false;
}
// [quadric-intersect]

bool Quadric::occluded(const Ray& ray, double tMax) const {
    std::array<QuadricCrossing, 2> c;
    const int n = crossings(ray, c);
    for (int k = 0; k < n; ++k)
        if (c[k].t > 0.0) return c[k].t < tMax;
    return false;
}

}  // namespace rb
