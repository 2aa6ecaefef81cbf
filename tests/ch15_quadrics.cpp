/// \file
/// Chapter 15 tests: cylinders and cones.
///
/// Chapter 15 claims that a cylinder or a cone is a quadric side surface clipped to the slab
/// −1 ≤ y ≤ 1, and that a capped one is the *intersection* of the two sets along the ray, so
/// the caps are real surfaces with outward normals and the seam between cap and side has no
/// gap. The tests prove it against hand-solved hits (side, caps, apex, frustum), against the
/// implicit equations and their gradients on random rays, by firing a hundred thousand rays into
/// the solids exactly through points of their rims (in object space and under random
/// transforms: every one must hit), and at the places where quadrics are known to fail: the apex
/// (no NaN), rays along the axis, rays parallel to the cone's slope, grazing and far-away rays.
/// Textures (chapter 10) wrap round them by their own (u, v), with exact tangents dp/du, dp/dv.
/// As CSG operands (chapter 14) they give their exact crossings, and with the chapter switched
/// off they are left out of CSG nodes as they are left out of the scene.
/// Refraction through the caps is checked end to end: looking through the caps of a glass cylinder
/// is looking through a glass slab of the same thickness (seed 001 saw black there). The random
/// rays come from a fixed seed (1; RB_CH15_SEED re-runs them on other streams; checked for seeds 1
/// to 10).
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <deque>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>
#include <string>
#include <vector>

#include "core/error.h"
#include "csg/csg.h"
#include "quadrics/cone.h"
#include "quadrics/cylinder.h"
#include "test_helpers.h"
#include "texture/uv_mapping.h"

using Catch::Contains;
using rb::Cone;
using rb::Cylinder;
using rb::ObjectHit;
using rb::Quadric;
using rb::QuadricPart;
using rb::Ray;
using rb::Vec2;
using rb::Vec3;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

/// The seed of every random stream in this file: 1, or RB_CH15_SEED.
std::uint64_t seed() {
    return rbtest::seedFromEnv("RB_CH15_SEED");
}

/// The closest hit of a ray with t in (0, ∞), or a hit with t = −1 when there is none.
ObjectHit closest(const Quadric& shape, const Vec3& o, const Vec3& d) {
    ObjectHit hit;
    if (!shape.intersect(Ray{o, d}, kInf, hit)) hit.t = -1.0;
    return hit;
}

/// True when every component of v is finite.
bool finite(const Vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

/// The cosine of the angle between two vectors.
double cosAngle(const Vec3& a, const Vec3& b) {
    return glm::dot(a, b) / (glm::length(a) * glm::length(b));
}

/// The radius of a cone with top radius r1 at height y: r(y) = (1 + r1)/2 + (r1 − 1)/2 · y.
double coneRadius(double r1, double y) {
    return 0.5 * (1.0 + r1) + 0.5 * (r1 - 1.0) * y;
}

/// A random transform: rotation about a random axis, a non-uniform scale, a translation.
rb::Mat4 randomTransform(rbtest::Rng& rng) {
    rb::Mat4 m(1.0);
    m = glm::translate(m, Vec3(rng.uniform(-5, 5), rng.uniform(-5, 5), rng.uniform(-5, 5)));
    m = glm::rotate(m, rng.uniform(0.0, 6.28), rng.unitVector());
    m = glm::scale(m, Vec3(rng.uniform(0.3, 3), rng.uniform(0.3, 3), rng.uniform(0.3, 3)));
    return m;
}

}  // namespace

// [ch15-side-spans]
SCENARIO("the cylinder's side quadratic gives where a line is inside the infinite tube",
         "[ch15][ex15.1]") {
    GIVEN("the line (−5, 0.3, 0.2) + t·(2, 0.1, 0)") {
        const rb::SideSpans spans = rb::cylinderSideSpans(Ray{Vec3(-5, 0.3, 0.2), Vec3(2, 0.1, 0)});
        THEN("it is inside for t in [(5 − √0.96)/2, (5 + √0.96)/2]") {
            // Source: x² + z² = 1 with z = 0.2 gives x = ±√0.96, and x = −5 + 2t.
            const double x = std::sqrt(0.96);
            INFO("expected one span [" << (5 - x) / 2 << ", " << (5 + x) / 2 << "], got "
                                       << spans.count << " spans");
            REQUIRE(spans.count == 1);
            CHECK(spans.lo[0] == Approx((5 - x) / 2).epsilon(1e-14));
            CHECK(spans.hi[0] == Approx((5 + x) / 2).epsilon(1e-14));
        }
    }
    GIVEN("lines parallel to the axis inside and outside the tube, and a line passing by") {
        const rb::SideSpans in = rb::cylinderSideSpans(Ray{Vec3(0.5, 0, 0), Vec3(0, 1, 0)});
        const rb::SideSpans out = rb::cylinderSideSpans(Ray{Vec3(2, 0, 0), Vec3(0, 1, 0)});
        const rb::SideSpans by = rb::cylinderSideSpans(Ray{Vec3(-5, 0, 2), Vec3(1, 0, 0)});
        THEN("the inside one is inside along the whole line, the others never") {
            REQUIRE(in.count == 1);
            CHECK(in.lo[0] == -std::numeric_limits<double>::infinity());
            CHECK(in.hi[0] == std::numeric_limits<double>::infinity());
            CHECK(out.count == 0);
            CHECK(by.count == 0);
        }
    }
}

SCENARIO("the cone's quadratic gives where a line is inside the double cone", "[ch15][ex15.2]") {
    GIVEN("the cone of radius 1 at y = −1 and its apex at y = 1: r(y) = 0.5 − 0.5·y") {
        const rb::ConeProfile apex(0.0);
        WHEN("a line crosses it level at y = 0, (−5, 0, 0) + t·(1, 0, 0)") {
            const rb::SideSpans spans = rb::coneSideSpans(Ray{Vec3(-5, 0, 0), Vec3(1, 0, 0)}, apex);
            THEN("it is inside for t in [4.5, 5.5], where the radius is 0.5") {
                // Source: x² ≤ r(0)² = 0.25 and x = −5 + t.
                INFO("expected one span [4.5, 5.5], got " << spans.count << " spans");
                REQUIRE(spans.count == 1);
                CHECK(spans.lo[0] == Approx(4.5).epsilon(1e-14));
                CHECK(spans.hi[0] == Approx(5.5).epsilon(1e-14));
            }
        }
        WHEN("a line parallel to the axis, 0.2 off it, runs up through both nappes") {
            const rb::SideSpans spans =
                rb::coneSideSpans(Ray{Vec3(0.2, -3, 0), Vec3(0, 1, 0)}, apex);
            THEN("it is inside up to t = 3.6 (y = 0.6) and again from t = 4.4 (y = 1.4)") {
                // Source: 0.2² = (0.5 − 0.5·(−3 + t))² gives 2 − 0.5·t = ±0.2.
                INFO("expected the spans (−∞, 3.6] and [4.4, ∞), got " << spans.count << " spans");
                REQUIRE(spans.count == 2);
                CHECK(spans.lo[0] == -std::numeric_limits<double>::infinity());
                CHECK(spans.hi[0] == Approx(3.6).epsilon(1e-14));
                CHECK(spans.lo[1] == Approx(4.4).epsilon(1e-14));
                CHECK(spans.hi[1] == std::numeric_limits<double>::infinity());
            }
        }
        WHEN("a level line passes beside it, (−5, 0, 2) + t·(1, 0, 0)") {
            THEN("it is never inside") {
                CHECK(rb::coneSideSpans(Ray{Vec3(-5, 0, 2), Vec3(1, 0, 0)}, apex).count == 0);
            }
        }
    }
}
// [ch15-side-spans]

// [cylinder-closed-form]
SCENARIO("a ray meets the cylinder's side and caps where the closed form puts them",
         "[ch15][ex15.1][ex15.3]") {
    GIVEN("the capped unit cylinder (radius 1, y from −1 to 1)") {
        const Cylinder cylinder;
        WHEN("a ray from (0, 0.3, 5) travels along −z") {
            const ObjectHit hit = closest(cylinder, {0, 0.3, 5}, {0, 0, -1});
            THEN("it meets the side at z = 1, t = 4, facing +z, with u = 0 and v = 0.65") {
                // Source: x² + z² = 1 with x = 0 gives z = 1; v = (y + 1)/2 = 0.65.
                REQUIRE(hit.t == Approx(4.0).epsilon(1e-14));
                REQUIRE(hit.primitive == static_cast<std::uint32_t>(QuadricPart::Side));
                REQUIRE(cosAngle(hit.n, {0, 0, 1}) == Approx(1.0).epsilon(1e-14));
                REQUIRE(hit.uv.x == Approx(0.0).margin(1e-14));
                REQUIRE(hit.uv.y == Approx(0.65).epsilon(1e-14));
            }
        }
        WHEN("a ray from (5, 0.5, 0.6) travels along −x") {
            const ObjectHit hit = closest(cylinder, {5, 0.5, 0.6}, {-1, 0, 0});
            THEN("it meets the side at x = √(1 − 0.6²) = 0.8, t = 4.2, normal (0.8, 0, 0.6)") {
                // Source: x² + z² = 1 at z = 0.6; the normal is the point's xz part.
                REQUIRE(hit.t == Approx(4.2).epsilon(1e-14));
                REQUIRE(cosAngle(hit.n, {0.8, 0, 0.6}) == Approx(1.0).epsilon(1e-14));
                // u = atan2(x, z)/2π = atan2(0.8, 0.6)/2π.
                REQUIRE(hit.uv.x == Approx(std::atan2(0.8, 0.6) / (2 * M_PI)).epsilon(1e-14));
            }
        }
        WHEN("a ray from (0.3, 5, −0.2) travels down the y axis's direction") {
            const ObjectHit hit = closest(cylinder, {0.3, 5, -0.2}, {0, -1, 0});
            THEN("it meets the top cap at y = 1, t = 4, facing +y, uv = ((x+1)/2, (z+1)/2)") {
                REQUIRE(hit.t == Approx(4.0).epsilon(1e-14));
                REQUIRE(hit.primitive == static_cast<std::uint32_t>(QuadricPart::Top));
                REQUIRE(hit.n == Vec3(0, 1, 0));
                REQUIRE(hit.uv.x == Approx(0.65).epsilon(1e-14));
                REQUIRE(hit.uv.y == Approx(0.4).epsilon(1e-14));
            }
        }
        WHEN("a ray from below meets the bottom cap at a slant") {
            // From (0, −3, 0) towards (0.5, −1, 0.25): t = 1 at the cap.
            const ObjectHit hit = closest(cylinder, {0, -3, 0}, {0.5, 2, 0.25});
            THEN("it hits y = −1 at t = 1 with the outward normal −y") {
                REQUIRE(hit.t == Approx(1.0).epsilon(1e-14));
                REQUIRE(hit.primitive == static_cast<std::uint32_t>(QuadricPart::Bottom));
                REQUIRE(hit.n == Vec3(0, -1, 0));
            }
        }
        WHEN("a ray passes beside it, or over it") {
            THEN("it misses") {
                REQUIRE(closest(cylinder, {1.01, 0, 5}, {0, 0, -1}).t < 0);
                REQUIRE(closest(cylinder, {0, 1.01, 5}, {0, 0, -1}).t < 0);
                REQUIRE(closest(cylinder, {0, 0, 5}, {0, 0, 1}).t < 0);  // pointing away
            }
        }
    }
}
// [cylinder-closed-form]

// [cone-closed-form]
SCENARIO("a ray meets the cone and the frustum where the closed form puts them",
         "[ch15][ex15.2][ex15.3][ex15.4]") {
    GIVEN("the capped unit cone: radius 1 at y = −1, apex at y = 1, so r(y) = (1 − y)/2") {
        const Cone cone;
        WHEN("a ray from (5, y₀, 0) travels along −x, for several heights y₀") {
            // (No THEN inside the loop: Catch runs a section of a loop only once.)
            for (const double y0 : {-0.9, -0.5, 0.0, 0.4, 0.9}) {
                const ObjectHit hit = closest(cone, {5, y0, 0}, {-1, 0, 0});
                // It meets the side at x = r(y₀), with the normal (1, 1/2, 0).
                // Source: x = r(y₀) = (1 − y₀)/2; ∇(x² + z² − r²)/2 = (x, r/2, z) ∝
                // (1, 1/2, 0): the slope of the side is 1/2 (radius 1 over height 2).
                INFO("y0 = " << y0);
                REQUIRE(hit.t == Approx(5.0 - 0.5 * (1.0 - y0)).epsilon(1e-14));
                REQUIRE(cosAngle(hit.n, {1, 0.5, 0}) == Approx(1.0).epsilon(1e-14));
                REQUIRE(hit.uv.y == Approx(0.5 * (y0 + 1)).epsilon(1e-14));
            }
        }
        WHEN("a ray from (0.2, −5, 0.3) travels up") {
            const ObjectHit hit = closest(cone, {0.2, -5, 0.3}, {0, 1, 0});
            THEN("it meets the base cap at y = −1, t = 4, facing −y") {
                REQUIRE(hit.t == Approx(4.0).epsilon(1e-14));
                REQUIRE(hit.primitive == static_cast<std::uint32_t>(QuadricPart::Bottom));
                REQUIRE(hit.n == Vec3(0, -1, 0));
            }
        }
    }
    GIVEN("a frustum with top radius 0.5: r(y) = 0.75 − 0.25·y") {
        const Cone frustum(0.5);
        WHEN("a ray from (0, 0.2, 5) travels along −z") {
            const ObjectHit hit = closest(frustum, {0, 0.2, 5}, {0, 0, -1});
            THEN("it meets the side at z = r(0.2) = 0.7, normal (0, 0.25, 1)") {
                // Source: ∇/2 = (x, −b·r, z) with b = −1/4, divided by r.
                REQUIRE(hit.t == Approx(4.3).epsilon(1e-14));
                REQUIRE(cosAngle(hit.n, {0, 0.25, 1}) == Approx(1.0).epsilon(1e-14));
            }
        }
        WHEN("a ray travels down onto the top") {
            const ObjectHit hit = closest(frustum, {0.3, 4, 0.3}, {0, -1, 0});
            THEN("the top cap of radius 0.5 is there: y = 1, t = 3, facing +y") {
                REQUIRE(hit.t == Approx(3.0).epsilon(1e-14));
                REQUIRE(hit.primitive == static_cast<std::uint32_t>(QuadricPart::Top));
            }
            THEN("a ray just outside the top radius goes on to the sloping side") {
                // At x = 0.6 the side is at r(y) = 0.6: y = 0.6, t = 3.4.
                const ObjectHit side = closest(frustum, {0.6, 4, 0}, {0, -1, 0});
                REQUIRE(side.t == Approx(3.4).epsilon(1e-14));
                REQUIRE(side.primitive == static_cast<std::uint32_t>(QuadricPart::Side));
            }
        }
    }
}
// [cone-closed-form]

SCENARIO("on random rays every hit lies on the surface with the gradient as its normal",
         "[ch15][ex15.1][ex15.2][ex15.3][ex15.4]") {
    rbtest::Rng rng(seed());
    const Cylinder cylinder, tube(false);
    const Cone cone, openCone(0.0, false), frustum(0.35), openFrustum(0.35, false);
    struct Case {
        const Quadric* shape;
        double topRadius;  // −1 for the cylinder
    };
    const Case cases[] = {{&cylinder, -1}, {&tube, -1},      {&cone, 0},
                          {&openCone, 0},  {&frustum, 0.35}, {&openFrustum, 0.35}};
    for (const Case& c : cases) {
        int hits = 0;
        for (int i = 0; i < 2000; ++i) {
            const Vec3 o = 4.0 * rng.unitVector();
            const Vec3 target(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
            std::array<ObjectHit, 2> all;
            const int n = c.shape->allHits(Ray{o, target - o}, all);
            for (int k = 0; k < n; ++k) {
                ++hits;
                const Vec3 p = o + all[k].t * (target - o);
                const double r = c.topRadius < 0 ? 1.0 : coneRadius(c.topRadius, p.y);
                const auto part = static_cast<QuadricPart>(all[k].primitive);
                if (part == QuadricPart::Side) {
                    // Source: the implicit equation x² + z² = r(y)², and its gradient
                    // (x, −b·r, z) with b = (r₁ − 1)/2 (0 for the cylinder).
                    REQUIRE(std::hypot(p.x, p.z) == Approx(r).margin(1e-12));
                    REQUIRE(std::abs(p.y) <= 1.0 + 1e-12);
                    const double b = c.topRadius < 0 ? 0.0 : 0.5 * (c.topRadius - 1.0);
                    REQUIRE(cosAngle(all[k].n, {p.x, -b * r, p.z}) == Approx(1.0).epsilon(1e-12));
                } else {
                    const double capY = part == QuadricPart::Top ? 1.0 : -1.0;
                    REQUIRE(p.y == Approx(capY).margin(1e-12));
                    REQUIRE(std::hypot(p.x, p.z) <= r + 1e-12);
                    REQUIRE(all[k].n == Vec3(0, capY, 0));
                }
            }
            if (n == 2) REQUIRE(all[0].t <= all[1].t);
            // A capped shape is a solid: the line enters and leaves, so 0 or 2 crossings.
            if (c.shape->capped()) REQUIRE((n == 0 || n == 2));
        }
        REQUIRE(hits > 1000);  // the rays do find the shape
    }
}

SCENARIO("a solid's crossings are an entry with the normal against the ray and an exit with it",
         "[ch15][ex15.1][ex15.2][ex15.3][ex15.4]") {
    rbtest::Rng rng(seed() + 1);
    const Cylinder cylinder;
    const Cone frustum(0.5);
    for (const Quadric* shape :
         {static_cast<const Quadric*>(&cylinder), static_cast<const Quadric*>(&frustum)}) {
        for (int i = 0; i < 2000; ++i) {
            const Vec3 o = 4.0 * rng.unitVector();
            // Aim inside both: within radius 0.45 of the axis, below the frustum's top radius.
            const Vec3 d =
                Vec3(rng.uniform(-0.3, 0.3), rng.uniform(-0.9, 0.9), rng.uniform(-0.3, 0.3)) - o;
            std::array<ObjectHit, 2> all;
            REQUIRE(shape->allHits(Ray{o, d}, all) == 2);  // aimed inside: it must cross
            REQUIRE(glm::dot(all[0].n, d) < 0.0);
            REQUIRE(glm::dot(all[1].n, d) > 0.0);
            // A ray starting between the two crossings is inside: its closest hit is the exit,
            // and a ray starting behind the origin sees the entry at the same place.
            const double tMid = 0.5 * (all[0].t + all[1].t);
            ObjectHit exit;
            REQUIRE(shape->intersect(Ray{o + tMid * d, d}, kInf, exit));
            REQUIRE(exit.t == Approx(all[1].t - tMid).epsilon(1e-12));
            REQUIRE(glm::dot(exit.n, d) > 0.0);
        }
    }
}

// [seam-watertight]
SCENARIO("no ray slips between a cap and the side",
         "[ch15][stability][ex15.1][ex15.2][ex15.3][ex15.4]") {
    rbtest::Rng rng(seed() + 2);
    const Cylinder cylinder;
    const Cone frustum(0.6);
    GIVEN("rays that enter the solid exactly through a point of a rim") {
        // Each ray passes through a rim point (radius r, y = ±1) heading into the solid:
        // against the side's and the cap's outward normals, plus a random sideways part. It must
        // hit there, at t = 1. A cap tested as a disk (x² + z² ≤ r²) and a side tested as a tube
        // clipped to |y| ≤ 1, each rejecting a point a rounding error past its own edge, let about
        // one such ray in six through (seed 001's way; tests/perf/ch15 counts them).
        for (const Quadric* shape :
             {static_cast<const Quadric*>(&cylinder), static_cast<const Quadric*>(&frustum)}) {
            const double r1 = shape == &cylinder ? 1.0 : 0.6;
            int missed = 0, missedUnderTransform = 0;
            for (int i = 0; i < 50000; ++i) {
                const double phi = rng.uniform(0.0, 2 * M_PI);
                const double y = rng.uniform() < 0.5 ? -1.0 : 1.0;
                const Vec3 radial(std::cos(phi), 0.0, std::sin(phi));
                const Vec3 tangent(-radial.z, 0.0, radial.x);
                const Vec3 rim = (y > 0 ? r1 : 1.0) * radial + Vec3(0.0, y, 0.0);
                Vec3 in;
                do {
                    in = -rng.uniform(0.05, 1.0) * radial -
                         rng.uniform(0.05, 1.0) * Vec3(0.0, y, 0.0) +
                         rng.uniform(-1.0, 1.0) * tangent;
                    // Also into the frustum's sloping side, whose normal is (radial, −b).
                } while (!(glm::dot(in, radial + Vec3(0.0, 0.5 * (1.0 - r1), 0.0)) < -0.01));
                const Vec3 o = rim - rng.uniform(3.0, 20.0) * in;
                ObjectHit hit;
                if (!shape->intersect(Ray{o, rim - o}, 1.0 + 1e-9, hit)) ++missed;
                // The same in world space, under a random rotation, scale and translation.
                const rb::Instance instance = rbtest::makeInstance(*shape, randomTransform(rng));
                const Vec3 worldRim = rb::transformPoint(instance.objectToWorld, rim);
                const Vec3 worldOrigin = rb::transformPoint(instance.objectToWorld, o);
                if (!instance.intersect(Ray{worldOrigin, worldRim - worldOrigin}, 1.0 + 1e-9, hit))
                    ++missedUnderTransform;
            }
            // Every one of the 50 000 rays hits, in object space and under transforms.
            REQUIRE(missed == 0);
            REQUIRE(missedUnderTransform == 0);
        }
    }
}
// [seam-watertight]

// [apex]
SCENARIO("the cone's apex gives a hit with a finite unit normal, never NaN",
         "[ch15][stability][ex15.2][ex15.3][ex15.4]") {
    rbtest::Rng rng(seed() + 3);
    const Cone cone, openCone(0.0, false);
    GIVEN("rays aimed exactly at the apex (0, 1, 0) from every direction") {
        for (const Cone* shape : {&cone, &openCone}) {
            int hits = 0;
            for (int i = 0; i < 20000; ++i) {
                const Vec3 o = Vec3(0, 1, 0) + rng.uniform(0.1, 10.0) * rng.unitVector();
                const Ray ray{o, Vec3(0, 1, 0) - o};
                ObjectHit hit;
                if (!shape->intersect(ray, kInf, hit)) continue;
                ++hits;
                const rb::Instance instance = rbtest::makeInstance(*shape, rb::Mat4(1.0));
                const rb::Hit world = instance.toWorld(ray, hit);
                REQUIRE(std::isfinite(hit.t));
                REQUIRE(hit.t <= 1.0 + 1e-12);  // at the apex or before it
                REQUIRE(finite(world.ng));
                REQUIRE(glm::length(world.ng) == Approx(1.0).epsilon(1e-12));
                REQUIRE(std::isfinite(hit.uv.x));
                REQUIRE(std::isfinite(hit.uv.y));
            }
            // Those that come from below the apex's tangent cone find it.
            REQUIRE(hits > 1000);
        }
    }
    GIVEN("a ray that starts exactly at the apex") {
        for (const Vec3 d : {Vec3(0, -1, 0), Vec3(0.3, -1, 0.1), Vec3(1, 0, 0), Vec3(0, 1, 0)}) {
            std::array<ObjectHit, 2> all;
            const int n = cone.allHits(Ray{{0, 1, 0}, d}, all);
            // Every crossing is finite.
            for (int k = 0; k < n; ++k) {
                REQUIRE(std::isfinite(all[k].t));
                REQUIRE(finite(all[k].n));
                REQUIRE(glm::length(all[k].n) > 0.0);
            }
        }
        THEN("straight down the axis it leaves through the base at t = 2") {
            const ObjectHit hit = closest(cone, {0, 1, 0}, {0, -1, 0});
            REQUIRE(hit.t == Approx(2.0).epsilon(1e-14));
            REQUIRE(hit.n == Vec3(0, -1, 0));
        }
    }
}
// [apex]

SCENARIO("rays along the axis meet the caps, and miss an open tube",
         "[ch15][stability][ex15.1][ex15.2][ex15.3][ex15.4]") {
    const Cylinder cylinder, tube(false);
    const Cone cone, openCone(0.0, false), frustum(0.5, true);
    WHEN("a ray runs down the axis from above") {
        THEN("the capped cylinder and frustum are entered through the top cap at t = 4") {
            REQUIRE(closest(cylinder, {0, 5, 0}, {0, -1, 0}).t == Approx(4.0).epsilon(1e-14));
            REQUIRE(closest(frustum, {0, 5, 0}, {0, -1, 0}).n == Vec3(0, 1, 0));
        }
        THEN("the pointed cone is entered at its apex, with the axis as normal") {
            const ObjectHit hit = closest(cone, {0, 5, 0}, {0, -1, 0});
            REQUIRE(hit.t == Approx(4.0).epsilon(1e-14));
            REQUIRE(hit.n == Vec3(0, 1, 0));
            const ObjectHit open = closest(openCone, {0, 5, 0}, {0, -1, 0});
            REQUIRE(open.t == Approx(4.0).epsilon(1e-14));
            REQUIRE(finite(open.n));
        }
        THEN("the open tube, parallel to its wall, is never crossed") {
            REQUIRE(closest(tube, {0, 5, 0}, {0, -1, 0}).t < 0);
            REQUIRE(closest(tube, {0.5, 0, 0.2}, {0, 1, 0}).t < 0);  // from inside, too
        }
    }
    WHEN("a ray starts at the centre and runs up the axis") {
        THEN("it leaves the solid cylinder through the top cap at t = 1") {
            const ObjectHit hit = closest(cylinder, {0, 0, 0}, {0, 1, 0});
            REQUIRE(hit.t == Approx(1.0).epsilon(1e-14));
            REQUIRE(hit.n == Vec3(0, 1, 0));
        }
        THEN("it leaves the cone at its apex at t = 1") {
            REQUIRE(closest(cone, {0, 0, 0}, {0, 1, 0}).t == Approx(1.0).epsilon(1e-14));
        }
    }
}

SCENARIO("grazing rays and rays parallel to the cone's slope give exact or no hits",
         "[ch15][stability][ex15.1][ex15.2][ex15.3][ex15.4]") {
    const Cylinder cylinder, tube(false);
    const Cone cone;
    WHEN("a ray runs parallel to a line on the cone (A = 0: the quadratic is linear)") {
        // From (−1.5, 3, 0) along (1, −2, 0), the slope of the generator from the apex to
        // (1, −1, 0). Source, by hand: inside when |x| ≤ r(y) with x = t − 1.5 and
        // r = t − 1, first at t = 1.25 (x = −0.25, y = 0.5); then inside until y = −1, t = 2.
        std::array<ObjectHit, 2> all;
        REQUIRE(cone.allHits(Ray{{-1.5, 3, 0}, {1, -2, 0}}, all) == 2);
        THEN("it enters the side at t = 1.25 and leaves through the base at t = 2") {
            REQUIRE(all[0].t == Approx(1.25).epsilon(1e-14));
            REQUIRE(cosAngle(all[0].n, {-1, 0.5, 0}) == Approx(1.0).epsilon(1e-14));
            REQUIRE(all[1].t == Approx(2.0).epsilon(1e-14));
            REQUIRE(all[1].primitive == static_cast<std::uint32_t>(QuadricPart::Bottom));
        }
    }
    WHEN("rays touch the side tangentially or run in a cap's plane") {
        const Ray rays[] = {
            {{1, 0, 5}, {0, 0, -1}},         // tangent to the side at (1, 0, 0)
            {{5, 1, 0}, {-1, 0, 0}},         // in the top cap's plane
            {{5, -1, 0.3}, {-1, 0, 0}},      // in the bottom cap's plane
            {{1, 1, 5}, {0, 0, -1}},         // along the rim's tangent
            {{5, 1, 0}, {-1, 1e-17, 0}},     // a hair off the cap's plane
            {{1 - 1e-16, 0, 5}, {0, 0, -1}}  // a hair inside the tangent
        };
        for (const Quadric* shape :
             {static_cast<const Quadric*>(&cylinder), static_cast<const Quadric*>(&tube),
              static_cast<const Quadric*>(&cone)}) {
            for (const Ray& ray : rays) {
                std::array<ObjectHit, 2> all;
                const int n = shape->allHits(ray, all);
                // A hit, if any, is finite and on the shape's bounds.
                for (int k = 0; k < n; ++k) {
                    REQUIRE(std::isfinite(all[k].t));
                    REQUIRE(finite(all[k].n));
                    REQUIRE(glm::length(all[k].n) > 0.0);
                    const Vec3 p = ray.o + all[k].t * ray.d;
                    REQUIRE(rb::maxAbsComponent(p) <= 1.0 + 1e-9);
                }
            }
        }
        THEN("the ray in the top cap's plane crosses the capped cylinder from x = 1 to −1") {
            std::array<ObjectHit, 2> all;
            REQUIRE(cylinder.allHits(Ray{{5, 1, 0}, {-1, 0, 0}}, all) == 2);
            REQUIRE(all[0].t == Approx(4.0).epsilon(1e-14));
            REQUIRE(all[1].t == Approx(6.0).epsilon(1e-14));
        }
    }
}

SCENARIO("rays from far away find the surface to the accuracy of their origin",
         "[ch15][stability][ex15.1][ex15.2][ex15.3][ex15.4]") {
    // The cancellation-free discriminant keeps the hit on the surface when |o| is large: the
    // textbook h² − a·c would lose about |o|²·ε = 1e-4 at |o| = 1e6 before the square root.
    const Cylinder cylinder;
    const Cone cone;
    for (const double distance : {1e3, 1e6, 1e8}) {
        const Vec3 aim(0.3, 0.2, 0.1);
        const Vec3 o = aim + distance * glm::normalize(Vec3(1, 0.1, 0.4));
        for (const Quadric* shape :
             {static_cast<const Quadric*>(&cylinder), static_cast<const Quadric*>(&cone)}) {
            const ObjectHit hit = closest(*shape, o, aim - o);
            REQUIRE(hit.t > 0.0);
            const Vec3 p = o + hit.t * (aim - o);
            const double r = shape == &cylinder ? 1.0 : coneRadius(0.0, p.y);
            // The hit point carries the origin's rounding, about |o|·ε.
            REQUIRE(std::hypot(p.x, p.z) == Approx(r).margin(distance * 1e-15));
        }
    }
}

SCENARIO("rays spawned from a cylinder or cone never hit it again at once, at every scale",
         "[ch15][stability][ex15.1][ex15.2][ex15.4]") {
    rbtest::Rng rng(seed() + 4);
    const Cylinder cylinder;
    const Cone cone(0.3);
    for (const double scale : rbtest::kSceneScales) {
        for (const Quadric* shape :
             {static_cast<const Quadric*>(&cylinder), static_cast<const Quadric*>(&cone)}) {
            const rb::Instance instance =
                rbtest::makeInstance(*shape, rbtest::placeAtScale(scale, Vec3(1.0, 1.3, 0.8)));
            for (const rbtest::SurfacePoint& s : rbtest::sampleSurface(instance, rng, 300)) {
                // Outward (a reflection): a convex solid is never met again.
                const Vec3 out = rbtest::mirror(glm::normalize(s.probe.d), s.hit.ng);
                ObjectHit again;
                REQUIRE_FALSE(instance.intersect(rbtest::spawnRay(s.hit, out), kInf, again));
                // Inward (a refraction): the next hit is the far side, not the surface itself.
                const Vec3 in = glm::normalize(s.probe.d);
                REQUIRE(instance.intersect(rbtest::spawnRay(s.hit, in), kInf, again));
                REQUIRE(again.t * glm::length(in) > 1e-6 * scale);
            }
        }
    }
}

// [caps-refract]
SCENARIO("light passes through a glass cylinder's caps as through a glass slab",
         "[ch15][ex15.1][ex15.3]") {
    // Seed 001 saw the caps of its glass cylinders black. Through two parallel caps a ray
    // must see what it sees through a glass box of the same thickness: the same two planes,
    // the same normals, the same Fresnel shares.
    auto scene = [](const std::string& glassShape) {
        return "local glass = gr.material{kd = {0.05, 0.05, 0.05}, ks = {0, 0, 0},"
               " shininess = 1, ior = 1.5, transparency = 0.95}\n"
               "local red = gr.material({0.9, 0.1, 0.1}, {0, 0, 0}, 1)\n"
               "root = gr.node('root')\n"
               "local floor = gr.cube('floor')\n"
               "floor:scale(20, 1, 20)\nfloor:translate(-10, -3, -10)\n"
               "floor:set_material(red)\n"
               "root:add_child(floor)\n" +
               glassShape +
               "g:set_material(glass)\n"
               "root:add_child(g)\n"
               // A low light, so that no shadow ray from the floor below crosses the glass
               // (shadow rays are opaque).
               "gr.render(root, 'out.png', 8, 8, {0, 0, 10}, {0, 0, -1}, {0, 1, 0}, 50,"
               " {0.1, 0.1, 0.1}, {gr.light({20, 0, 0}, {5, 5, 5}, {1, 0, 0})})\n";
    };
    const auto cylinderWorld =
        rbtest::worldFromLua(scene("local g = gr.cylinder('g')\n"), rbtest::chapters(15));
    // The slab: the cube [0,1]³ moved to [−1,1]³, which holds the cylinder.
    const auto slabWorld = rbtest::worldFromLua(
        scene("local g = gr.cube('g')\ng:translate(-0.5, -0.5, -0.5)\ng:scale(2, 2, 2)\n"),
        rbtest::chapters(15));
    for (const Vec3 d : {Vec3(0, -1, 0), Vec3(0.05, -1, 0.02), Vec3(-0.1, -1, 0.03)}) {
        const Ray ray{{0.1, 5, -0.05}, d};
        const rb::Colour throughCylinder = rbtest::traceOne(*cylinderWorld, ray);
        const rb::Colour throughSlab = rbtest::traceOne(*slabWorld, ray);
        // The floor shows red through the caps, as through the slab.
        INFO("direction " << d.x << ", " << d.y << ", " << d.z);
        REQUIRE(throughCylinder.r > 0.2);
        REQUIRE(throughCylinder.r > 4.0 * throughCylinder.g);
        REQUIRE(throughCylinder.r == Approx(throughSlab.r).epsilon(1e-9));
        REQUIRE(throughCylinder.g == Approx(throughSlab.g).epsilon(1e-9));
        REQUIRE(throughCylinder.b == Approx(throughSlab.b).epsilon(1e-9));
    }
}
// [caps-refract]

SCENARIO("seed 001's calls and raybook's own make the shapes the page describes", "[ch15]") {
    const rb::FeatureSet features = rbtest::chapters(15);
    // Each loaded scene owns its shapes, so it is kept for the whole scenario: the pointers
    // shapeOf returns must not outlive it.
    std::deque<std::vector<rb::LoadedRender>> loaded;
    auto shapeOf = [&](const std::string& call) -> const Quadric* {
        const auto& renders = loaded.emplace_back(
            rbtest::loadSceneText("root = gr.node('root')\nlocal s = " + call +
                                      "\nroot:add_child(s)\n" + rbtest::renderLine(),
                                  features));
        REQUIRE(renders.at(0).instances.size() == 1);
        return dynamic_cast<const Quadric*>(renders[0].instances[0].shape);
    };
    WHEN("the seed's spelling gr.cyllinder, gr.cylinder and gr.cone take a name") {
        THEN("each is a capped shape of height 2 along y, in the box [−1, 1]³") {
            for (const char* call : {"gr.cyllinder('c')", "gr.cylinder('c')", "gr.cone('k')"}) {
                const Quadric* q = shapeOf(call);
                REQUIRE(q != nullptr);
                REQUIRE(q->capped());
                REQUIRE(q->bounds().lo == Vec3(-1.0));
                REQUIRE(q->bounds().hi == Vec3(1.0));
            }
            REQUIRE(dynamic_cast<const Cylinder*>(shapeOf("gr.cyllinder('c')")) != nullptr);
            REQUIRE(dynamic_cast<const Cone*>(shapeOf("gr.cone('c')"))->topRadius() == 0.0);
        }
    }
    WHEN("raybook's form names its fields") {
        THEN("open = true leaves the caps out, and top_radius makes a frustum") {
            REQUIRE_FALSE(shapeOf("gr.cylinder{name = 't', open = true}")->capped());
            REQUIRE(shapeOf("gr.cylinder{open = false}")->capped());
            const auto* frustum =
                dynamic_cast<const Cone*>(shapeOf("gr.cone{top_radius = 0.4, open = true}"));
            REQUIRE(frustum != nullptr);
            REQUIRE(frustum->topRadius() == 0.4);
            REQUIRE_FALSE(frustum->capped());
        }
    }
    WHEN("a call is malformed") {
        auto error = [&](const std::string& call) {
            return rbtest::loadError("local s = " + call + "\n", features);
        };
        THEN("the error names the file, the line, the call and what was expected") {
            REQUIRE_THAT(error("gr.cone{top = 1}"),
                         Contains("scene.lua:1: gr.cone: unknown field 'top'"));
            REQUIRE_THAT(error("gr.cylinder{open = 1}"),
                         Contains("gr.cylinder: field 'open' must be true or false"));
            REQUIRE_THAT(error("gr.cone{top_radius = 1.5}"),
                         Contains("field 'top_radius' must be a number from 0"));
            REQUIRE_THAT(error("gr.cone{top_radius = 0/0}"),
                         Contains("field 'top_radius' must be a number from 0"));
            REQUIRE_THAT(error("gr.cyllinder()"), Contains("gr.cyllinder"));
            REQUIRE_THAT(error("gr.cylinder(3)"), Contains("gr.cylinder"));
        }
    }
    WHEN("a chapter-8 build meets gr.cyllinder") {
        THEN("it names chapter 15") {
            REQUIRE_THAT(rbtest::loadError("local s = gr.cyllinder('c')\n", rbtest::chapters(8)),
                         Contains("gr.cyllinder needs chapter 15 (quadrics)"));
        }
    }
}

SCENARIO("with quadrics switched off, a scene renders as if the chapter were not written",
         "[ch15]") {
    const std::string withCylinder =
        "root = gr.node('root')\n"
        "local s = gr.sphere('s')\nroot:add_child(s)\n"
        "local c = gr.cylinder('c')\nc:translate(0, 0, 2)\nroot:add_child(c)\n" +
        rbtest::renderLine();
    const std::string withoutCylinder =
        "root = gr.node('root')\nlocal s = gr.sphere('s')\nroot:add_child(s)\n" +
        rbtest::renderLine();
    const auto off = rbtest::worldFromLua(withCylinder, rbtest::chapters(15, "all,-quadrics"));
    const auto plain = rbtest::worldFromLua(withoutCylinder, rbtest::chapters(15));
    THEN("the cylinder is left out, with a warning, and the image is the one without it") {
        REQUIRE(off->scene.instances.size() == 1);
        REQUIRE(off->warnings.size() == 1);
        REQUIRE_THAT(off->warnings[0], Contains("'quadrics' feature not drawn"));
        REQUIRE(rbtest::bitIdentical(rbtest::renderSmall(*off), rbtest::renderSmall(*plain)));
        const auto on = rbtest::worldFromLua(withCylinder, rbtest::chapters(15));
        REQUIRE(on->scene.instances.size() == 2);
        REQUIRE(on->warnings.empty());
    }
}

SCENARIO("degenerate rays and glass quadrics seen from everywhere give no NaN",
         "[ch15][stability][ex15.1][ex15.2][ex15.4]") {
    const Cylinder cylinder;
    const Cone cone;
    WHEN("a ray has a zero or NaN direction") {
        std::array<ObjectHit, 2> all;
        const double nan = std::numeric_limits<double>::quiet_NaN();
        THEN("it crosses nothing") {
            REQUIRE(cylinder.allHits(Ray{{0, 0, 5}, Vec3(0.0)}, all) == 0);
            REQUIRE(cone.allHits(Ray{{0, 0, 5}, Vec3(0.0)}, all) == 0);
            REQUIRE(cylinder.allHits(Ray{{0, 0, 5}, {nan, 0, -1}}, all) == 0);
            REQUIRE(cone.allHits(Ray{{0, 0, 5}, {0, nan, -1}}, all) == 0);
        }
    }
    WHEN("glass cylinders, cones and open shapes are rendered, the camera inside one of them") {
        const std::string lua =
            "gr.option('max_depth', 12)\n"
            "local glass = gr.material{kd = {0.05, 0.05, 0.05}, ks = {0.5, 0.5, 0.5},"
            " shininess = 50, ior = 1.5, transparency = 0.95}\n"
            "root = gr.node('root')\n"
            "local shapes = {gr.cylinder('a'), gr.cone{name = 'b'}, gr.cone{top_radius = 0.3},"
            " gr.cylinder{open = true}, gr.cone{open = true}}\n"
            "for i, s in ipairs(shapes) do\n"
            "  s:scale(0.8, 1.2, 0.8)\n  s:rotate('x', 25 * i)\n  s:translate(2 * i - 6, 0, 0)\n"
            "  s:set_material(glass)\n  root:add_child(s)\nend\n"
            "local floor = gr.cube('floor')\nfloor:scale(30, 1, 30)\n"
            "floor:translate(-15, -3, -15)\nroot:add_child(floor)\n"
            // The eye sits inside the first cylinder (centre (-4, 0, 0)).
            "gr.render(root, 'out.png', 8, 8, {-4, 0.1, 0.2}, {1, -0.2, -1}, {0, 1, 0}, 120,"
            " {0.2, 0.2, 0.2}, {gr.light({0, 8, 4}, {1, 1, 1}, {1, 0, 0})})\n";
        const auto world = rbtest::worldFromLua(lua, rbtest::chapters(15));
        THEN("every pixel is finite and non-negative") {
            REQUIRE(rbtest::allFiniteNonNegative(rbtest::renderSmall(*world, 96, 64)));
        }
    }
}

SCENARIO("seed 001's calls mark a scene as written for the pre-2015 framework", "[ch15]") {
    // Seed 001's framework post-multiplied transforms; its own spelling gr.cyllinder tells
    // raybook so (chapter 2's era detection). gr.cone(name) is seed 001's call too, but it is
    // also raybook's own first form, so it says nothing, as gr.cylinder and the table forms.
    auto eraOf = [](const std::string& call) {
        rbtest::TempDir dir;
        rb::SceneLoadOptions options;  // era: detect
        rb::SceneLoadReport report;
        rb::loadScene(dir.write("scene.lua", "root = gr.node('root')\nlocal s = " + call +
                                                 "\nroot:add_child(s)\n" + rbtest::renderLine()),
                      rbtest::chapters(15), options, &report);
        return report.era;
    };
    THEN("gr.cyllinder is a sign of the pre-2015 era") {
        const rb::EraDecision era = eraOf("gr.cyllinder('c')");
        INFO(era.line);
        REQUIRE(era.era == rb::Era::Legacy);
        REQUIRE_THAT(era.line, Contains("seed 001's gr.cyllinder"));
    }
    THEN("gr.cone(name), gr.cylinder(name) and the table forms are not") {
        for (const char* call :
             {"gr.cone('k')", "gr.cylinder('c')", "gr.cylinder{open = true}", "gr.cone{}"}) {
            const rb::EraDecision era = eraOf(call);
            INFO(call << ": " << era.line);
            REQUIRE(era.era == rb::Era::Modern);
            REQUIRE_THAT(era.line, !Contains("seed 001"));
        }
    }
}

// [ch15-csg-operand]
SCENARIO("a cylinder or cone operand of a CSG node gives its exact crossings, not marched ones",
         "[ch15][ex15.1][ex15.2][ex15.3][ex15.4]") {
    GIVEN("capped, open and frustum quadrics as CSG leaves under random transforms") {
        const Cylinder capped, tube(false);
        const Cone cone, frustum(0.4), openFrustum(0.3, false);
        rbtest::Rng rng(seed());
        WHEN("random lines through their bounds are listed by the leaf and by allHits") {
            THEN("the leaf's crossings are allHits' own t, bit for bit, entering first") {
                int crossingsSeen = 0;
                for (const Quadric* shape :
                     std::vector<const Quadric*>{&capped, &tube, &cone, &frustum, &openFrustum})
                    for (int k = 0; k < 400; ++k) {
                        rb::Instance instance;
                        instance.shape = shape;
                        instance.setTransform(randomTransform(rng));
                        const rb::CsgLeaf leaf = rb::CsgLeaf::from(instance);
                        // A line through a random point of the (world) bounds.
                        const rb::AABB& b = instance.worldBounds;
                        const Vec3 target(rng.uniform(b.lo.x, b.hi.x), rng.uniform(b.lo.y, b.hi.y),
                                          rng.uniform(b.lo.z, b.hi.z));
                        const Vec3 d = rng.unitVector();
                        const Ray line{target - 20.0 * d, d};
                        rb::CrossingList listed;
                        leaf.crossings(line, listed);
                        const Ray local{rb::transformPoint(instance.worldToObject, line.o),
                                        rb::transformVector(instance.worldToObject, line.d)};
                        std::array<ObjectHit, 2> hits;
                        const int n = shape->allHits(local, hits);
                        // A solid gives 0 or 2; an open surface crossed once gives none.
                        const int expected = n == 2 ? 2 : 0;
                        CAPTURE(k, n, listed.size());
                        REQUIRE(static_cast<int>(listed.size()) == expected);
                        for (int i = 0; i < expected; ++i) {
                            REQUIRE(listed[i].hit.t == hits[i].t);
                            REQUIRE(listed[i].entering == (i == 0));
                            // Normals point out of the solid: against the line on entry.
                            REQUIRE((glm::dot(listed[i].hit.n, line.d) < 0.0) == (i == 0));
                        }
                        crossingsSeen += expected;
                    }
                CHECK(crossingsSeen > 1000);
            }
        }
    }
}
// [ch15-csg-operand]

// [ch15-csg-off]
SCENARIO("with quadrics switched off, a quadric operand of a CSG node is left out, with a warning",
         "[ch15][ex15.1][ex15.3]") {
    GIVEN("a sphere minus a cylinder, and the same sphere minus an empty node") {
        auto scene = [](const std::string& b) {
            return "root = gr.node('root')\n"
                   "local s = gr.sphere('s')\n"
                   "local b = " +
                   b +
                   "\nb:scale(0.8, 2, 0.8)\n"
                   "root:add_child(gr.difference(s, b))\n" +
                   rbtest::renderLine();
        };
        const auto off =
            rbtest::worldFromLua(scene("gr.cylinder('c')"), rbtest::chapters(15, "all,-quadrics"));
        const auto empty =
            rbtest::worldFromLua(scene("gr.node('c')"), rbtest::chapters(15, "all,-quadrics"));
        const auto on = rbtest::worldFromLua(scene("gr.cylinder('c')"), rbtest::chapters(15));
        THEN("the image is the sphere minus nothing, and rt warns as for a top-level cylinder") {
            REQUIRE(off->warnings.size() == 1);
            REQUIRE_THAT(off->warnings[0], Contains("1 shape of the 'quadrics' feature not drawn"));
            REQUIRE(empty->warnings.empty());
            REQUIRE(rbtest::bitIdentical(rbtest::renderSmall(*off), rbtest::renderSmall(*empty)));
        }
        THEN("with the chapter on, the cylinder is cut out of the sphere") {
            REQUIRE(on->warnings.empty());
            REQUIRE_FALSE(
                rbtest::bitIdentical(rbtest::renderSmall(*on), rbtest::renderSmall(*empty)));
        }
    }
}
// [ch15-csg-off]

// [ch15-uv]
SCENARIO("a texture wraps round a cylinder or cone by the shape's own (u, v)",
         "[ch15][ex15.1][ex15.2][ex15.3][ex15.4]") {
    GIVEN("capped cylinders, cones and frustums under random transforms, hit by random rays") {
        const Cylinder cylinder;
        const Cone cone, frustum(0.4);
        rbtest::Rng rng(seed());
        THEN(
            "chapter 10's 'surface' mapping gives the hit's (u, v): angle and height on the "
            "side, the disk on the caps") {
            int sides = 0, caps = 0;
            for (const Quadric* shape : std::vector<const Quadric*>{&cylinder, &cone, &frustum})
                for (int k = 0; k < 500; ++k) {
                    rb::Instance instance;
                    instance.shape = shape;
                    instance.setTransform(randomTransform(rng));
                    const rb::AABB& b = instance.worldBounds;
                    const Vec3 target(rng.uniform(b.lo.x, b.hi.x), rng.uniform(b.lo.y, b.hi.y),
                                      rng.uniform(b.lo.z, b.hi.z));
                    const Vec3 d = rng.unitVector();
                    const Ray ray{target - 30.0 * d, d};
                    ObjectHit oh;
                    if (!instance.intersect(ray, kInf, oh)) continue;
                    const rb::Hit hit = instance.toWorld(ray, oh);
                    const Vec3 p = rb::transformPoint(instance.worldToObject, hit.p);
                    const auto part = static_cast<QuadricPart>(hit.primitive);
                    // Source: chapter 15's parameterisation, u = atan2(x, z)/2π, v = (y + 1)/2
                    // on the side; u = (x + 1)/2, v = (z + 1)/2 on a cap.
                    const Vec2 expected =
                        part == QuadricPart::Side
                            ? Vec2(std::atan2(p.x, p.z) / (2 * glm::pi<double>()) +
                                       (p.x < 0 ? 1.0 : 0.0),
                                   0.5 * (p.y + 1.0))
                            : Vec2(0.5 * (p.x + 1.0), 0.5 * (p.z + 1.0));
                    const rb::SurfaceUV s = rb::surfaceUV(hit);
                    CAPTURE(k, p.x, p.y, p.z, s.uv.x, s.uv.y, expected.x, expected.y);
                    REQUIRE(std::abs(s.uv.x - expected.x) < 1e-9);
                    REQUIRE(std::abs(s.uv.y - expected.y) < 1e-9);
                    // The world tangents lie in the surface: across the world normal.
                    const Vec3 n = glm::normalize(hit.ng);
                    REQUIRE(std::abs(cosAngle(s.dpdu, n)) < 1e-6);
                    REQUIRE(std::abs(cosAngle(s.dpdv, n)) < 1e-6);
                    ++(part == QuadricPart::Side ? sides : caps);
                }
            CHECK(sides > 300);
            CHECK(caps > 100);
        }
        THEN("dp/du and dp/dv are the derivatives of the surface point along u and v") {
            // The point at (u, v) on the side of a shape with radius r(y): Source: inverting
            // u = atan2(x, z)/2π, v = (y + 1)/2 gives p = (r sin 2πu, 2v − 1, r cos 2πu).
            const double h = 1e-6;
            for (const double r1 : {1.0, 0.0, 0.4}) {
                const Cone asCone(r1);
                const Quadric& shape = r1 == 1.0 ? static_cast<const Quadric&>(cylinder) : asCone;
                auto at = [&](double u, double v) {
                    const double y = 2 * v - 1, r = coneRadius(r1, y);
                    const double phi = 2 * glm::pi<double>() * u;
                    return Vec3(r * std::sin(phi), y, r * std::cos(phi));
                };
                for (int k = 0; k < 200; ++k) {
                    const double u = rng.uniform(0.05, 0.95), v = rng.uniform(0.05, 0.9);
                    Vec2 uv;
                    Vec3 dpdu, dpdv;
                    REQUIRE(shape.surfaceCoordinates(at(u, v), 0, uv, dpdu, dpdv));
                    const Vec3 du = (at(u + h, v) - at(u - h, v)) / (2 * h);
                    const Vec3 dv = (at(u, v + h) - at(u, v - h)) / (2 * h);
                    CAPTURE(r1, u, v);
                    REQUIRE(glm::length(dpdu - du) < 1e-6 * glm::length(du) + 1e-9);
                    REQUIRE(glm::length(dpdv - dv) < 1e-6 * glm::length(dv));
                }
            }
        }
    }
}
// [ch15-uv]
