/// \file
/// Chapter 1 tests: rays, the pinhole camera, spheres and boxes, the image, the sampler and the
/// parallel render loop.
///
/// Chapter 1 claims that a ray meets the unit sphere and the unit cube exactly where algebra
/// says it does; that the cancellation-free form of the quadratic keeps a sphere hit accurate
/// when the ray starts 1e8 radii away, where the textbook formula loses every digit; that the
/// pinhole camera aims its rays by A4's rules (vertical fovy, a view direction that need not be
/// unit length, an up vector that need not be orthogonal); that the sampler's numbers depend
/// only on (seed, pixel, sample, dimension) and are uniform; that the image is bit-identical
/// for any thread count; and that PNGs are written whole or not at all. Every expected value
/// below is worked out by hand or from a closed form, and says where it comes from.
#include <stb_image.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <functional>
#include <limits>
#include <vector>

#include "core/aabb.h"
#include "core/box.h"
#include "core/camera.h"
#include "core/error.h"
#include "core/image.h"
#include "core/integrator.h"
#include "core/render.h"
#include "core/sampler.h"
#include "core/sphere.h"
#include "test_helpers.h"

using Catch::Contains;
using rb::Vec3;
using rbtest::bitIdentical;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

/// Tolerance for results of a handful of double operations on numbers of order 1: each
/// operation rounds by at most 2^-53 ≈ 1.1e-16 relative, so 1e-14 leaves a margin of ~100 ulps
/// while still catching any wrong formula (which errs by far more).
constexpr double kTight = 1e-14;

/// True when a and b agree component-wise within tol.
bool near(const Vec3& a, const Vec3& b, double tol = kTight) {
    return std::abs(a.x - b.x) <= tol && std::abs(a.y - b.y) <= tol && std::abs(a.z - b.z) <= tol;
}

/// The textbook root t = (−b − √(b² − 4ac)) / 2a of |o + t·d|² = 1, computed as most first ray
/// tracers do. Kept here to show what the stable form in sphere.cpp protects against.
double naiveNearRoot(const Vec3& o, const Vec3& d) {
    const double a = glm::dot(d, d);
    const double b = 2.0 * glm::dot(o, d);
    const double c = glm::dot(o, o) - 1.0;
    return (-b - std::sqrt(b * b - 4.0 * a * c)) / (2.0 * a);
}

/// A point light at `position` with colour and falloff (c0, c1, c2).
rb::PointLight pointLight(const Vec3& position, const rb::Colour& colour, const Vec3& falloff) {
    rb::PointLight light;
    light.position = position;
    light.colour = colour;
    light.falloff = falloff;
    return light;
}

/// One hand-worked ray–cube case.
struct BoxCase {
    const char* what;
    Vec3 o, d;
    bool hit;
    double t;  ///< Expected distance (when hit).
    Vec3 n;    ///< Expected outward normal of the face hit (when hit).
};

/// A small scene built in code for the render-loop tests: spheres and boxes under Phong with two
/// lights, through the chapter 1–3 pipeline (headlight replaced by Phong, BVH aggregate).
struct CodeScene {
    rbtest::TestWorld world;
    CodeScene() {
        const rb::Material* red =
            world.material(rb::Material{rb::Colour(0.8, 0.2, 0.1), rb::Colour(0.5), 20.0, {}, {}});
        const rb::Material* grey =
            world.material(rb::Material{rb::Colour(0.6), rb::Colour(0.0), 1.0, {}, {}});
        world.addBox(
            glm::scale(glm::translate(rb::Mat4(1.0), Vec3(-5, -1.5, -5)), Vec3(10, 0.5, 10)), grey,
            "floor");
        for (int i = 0; i < 3; ++i)
            world.addSphere(
                glm::scale(glm::translate(rb::Mat4(1.0), Vec3(-1.5 + 1.5 * i, -0.4, -i)),
                           Vec3(0.6)),
                red, "ball");
        world.scene.lights.push_back(pointLight(Vec3(-4, 5, 4), rb::Colour(0.9), Vec3(1, 0, 0)));
        world.scene.lights.push_back(pointLight(Vec3(3, 2, 5), rb::Colour(0.4), Vec3(1, 0.1, 0)));
        world.scene.ambient = rb::Colour(0.1);
        world.build(rbtest::coreFeatures());
    }
    rb::Image render(int threads, int spp, std::uint64_t seed, int width = 64, int height = 48,
                     std::vector<int>* tileThreads = nullptr,
                     std::function<bool()> shouldStop = {}) const {
        const rb::PinholeCamera camera(
            rb::CameraSpec{Vec3(0, 1, 6), Vec3(0, -0.2, -1), Vec3(0, 1, 0), 45.0}, width, height);
        rb::RenderSettings settings;
        settings.threads = threads;
        settings.samplesPerPixel = spp;
        settings.seed = seed;
        settings.tileThreads = tileThreads;
        settings.shouldStop = std::move(shouldStop);
        rb::RayCounters counters;
        return rb::render(world.scene, world.pipeline, camera, width, height, settings, counters);
    }
};

/// A scene whose every camera ray meets one flat face lit only by ambient light: a grey box
/// (kd = 0.6) whose face z = 0 spans [-50, 50]² in front of a camera at z = 5 looking down −z,
/// ambient 0.25, no lights. Source: Phong shading with no lights is kd·ambient, the same at
/// every point of the face, so every sample of every pixel has radiance 0.6 · 0.25 = 0.15.
struct AmbientWall {
    rbtest::TestWorld world;
    static constexpr double kRadiance = 0.6 * 0.25;
    AmbientWall() {
        const rb::Material* grey =
            world.material(rb::Material{rb::Colour(0.6), rb::Colour(0.0), 1.0, {}, {}});
        world.addBox(rbtest::boxFromTo(Vec3(-50, -50, -1), Vec3(50, 50, 0)), grey, "wall");
        world.scene.ambient = rb::Colour(0.25);
        world.build(rbtest::coreFeatures());
    }
    rb::Image render(int spp) const {
        const rb::PinholeCamera camera(
            rb::CameraSpec{Vec3(0, 0, 5), Vec3(0, 0, -1), Vec3(0, 1, 0), 40.0}, 20, 14);
        rb::RenderSettings settings;
        settings.threads = 1;
        settings.samplesPerPixel = spp;
        settings.seed = 3;
        rb::RayCounters counters;
        return rb::render(world.scene, world.pipeline, camera, 20, 14, settings, counters);
    }
};

}  // namespace

// ---- Ray–sphere -------------------------------------------------------------------------------

// [ch01-sphere-hit]
SCENARIO("a ray from outside meets the unit sphere at the nearer root of |o + t·d|² = 1",
         "[ch01][ex1.1]") {
    const rb::Sphere sphere;
    rb::ObjectHit hit;
    GIVEN("a ray from (0, 0, 5) straight at the centre") {
        const rb::Ray ray{Vec3(0, 0, 5), Vec3(0, 0, -1)};
        THEN("it hits at t = 5 − 1 = 4 with normal (0, 0, 1)") {
            // Source: hand derivation: the front pole (0,0,1) is 4 units from the origin.
            REQUIRE(sphere.intersect(ray, kInf, hit));
            CHECK(hit.t == Approx(4.0).epsilon(kTight));
            CHECK(near(glm::normalize(hit.n), Vec3(0, 0, 1)));
        }
    }
    GIVEN("a ray parallel to the axis at height x = 0.6") {
        const rb::Ray ray{Vec3(0.6, 0, 5), Vec3(0, 0, -1)};
        THEN("it hits at t = 5 − √(1 − 0.6²) = 4.2 with normal (0.6, 0, 0.8)") {
            // Source: hand derivation: z² = 1 − x² = 0.64 on the sphere, so z = 0.8.
            REQUIRE(sphere.intersect(ray, kInf, hit));
            CHECK(hit.t == Approx(4.2).epsilon(kTight));
            CHECK(near(glm::normalize(hit.n), Vec3(0.6, 0, 0.8)));
        }
    }
    GIVEN("the same ray with a direction of length 2") {
        const rb::Ray ray{Vec3(0.6, 0, 5), Vec3(0, 0, -2)};
        THEN("t halves to 2.1: t is measured in units of the direction, which is not normalised") {
            // Source: o + t·(2d) = o + (2t)·d, so the root for 2d is half the root for d.
            REQUIRE(sphere.intersect(ray, kInf, hit));
            CHECK(hit.t == Approx(2.1).epsilon(kTight));
        }
    }
    GIVEN("the front pole 4 units away") {
        const rb::Ray ray{Vec3(0, 0, 5), Vec3(0, 0, -1)};
        THEN("tMax cuts the ray: no hit when tMax ≤ 4, a hit when tMax > 4") {
            CHECK_FALSE(sphere.intersect(ray, 3.9, hit));
            CHECK_FALSE(sphere.intersect(ray, 4.0, hit));  // the interval is open: t < tMax
            CHECK(sphere.intersect(ray, 4.1, hit));
        }
    }
}
// [ch01-sphere-hit]

SCENARIO("a ray that starts inside the sphere meets it on the way out", "[ch01][ex1.1]") {
    const rb::Sphere sphere;
    rb::ObjectHit hit;
    GIVEN("a ray from the centre along +x") {
        THEN("it hits at t = 1, with the outward normal (1, 0, 0)") {
            // Source: hand derivation: the sphere has radius 1.
            REQUIRE(sphere.intersect(rb::Ray{Vec3(0), Vec3(1, 0, 0)}, kInf, hit));
            CHECK(hit.t == Approx(1.0).epsilon(kTight));
            CHECK(near(glm::normalize(hit.n), Vec3(1, 0, 0)));
        }
    }
    GIVEN("a ray from (0.5, 0, 0) along −x") {
        THEN("it hits the far wall at t = 1.5, normal (−1, 0, 0)") {
            // Source: hand derivation: from x = 0.5 to x = −1 is 1.5.
            REQUIRE(sphere.intersect(rb::Ray{Vec3(0.5, 0, 0), Vec3(-1, 0, 0)}, kInf, hit));
            CHECK(hit.t == Approx(1.5).epsilon(kTight));
            CHECK(near(glm::normalize(hit.n), Vec3(-1, 0, 0)));
        }
    }
}

SCENARIO("a ray that passes beside or away from the sphere misses it", "[ch01][ex1.1]") {
    const rb::Sphere sphere;
    rb::ObjectHit hit;
    GIVEN("rays parallel to z at distances just over and just under the radius") {
        THEN("x = 1 + 1e-12 misses") {
            CHECK_FALSE(
                sphere.intersect(rb::Ray{Vec3(1 + 1e-12, 0, 5), Vec3(0, 0, -1)}, kInf, hit));
        }
        THEN("x = 1 − 1e-6 grazes it at t = 5 − √(1 − x²)") {
            const double x = 1 - 1e-6;
            // Source: hand derivation; 1 − x² = 2e-6 − 1e-12 is formed without cancellation.
            const double expected = 5.0 - std::sqrt(2e-6 - 1e-12);
            REQUIRE(sphere.intersect(rb::Ray{Vec3(x, 0, 5), Vec3(0, 0, -1)}, kInf, hit));
            // The grazing root is ill-conditioned: an error of 1 ulp in |f|² ≈ 1 moves √(1−|f|²)
            // ≈ 1.4e-3 by about 1.1e-16 / (2·1.4e-3) ≈ 4e-14; allow 1e-12 absolute.
            CHECK(hit.t == Approx(expected).margin(1e-12));
        }
    }
    GIVEN("a ray pointing away from a sphere behind its origin") {
        THEN("it does not hit: both roots are negative") {
            CHECK_FALSE(sphere.intersect(rb::Ray{Vec3(0, 0, 5), Vec3(0, 0, 1)}, kInf, hit));
        }
    }
}

// [ch01-stable-quadratic]
SCENARIO("the stable quadratic finds a unit sphere 1e8 away to within a few ulps",
         "[ch01][ex1.1]") {
    const rb::Sphere sphere;
    rb::ObjectHit hit;
    GIVEN("a ray from (0, 0, 1e8) towards the centre") {
        const Vec3 o(0, 0, 1e8), d(0, 0, -1);
        WHEN("raybook intersects it") {
            REQUIRE(sphere.intersect(rb::Ray{o, d}, kInf, hit));
            THEN("t = 1e8 − 1 within 4 ulps") {
                // Source: hand derivation: the front pole is at z = 1. 1e8 − 1 is an integer
                // below 2^53, so it is exactly representable.
                CHECK(rbtest::ulpDistance(hit.t, 1e8 - 1.0) <= 4);
            }
        }
        WHEN("the textbook formula (−b − √(b² − 4ac)) / 2a is used instead") {
            const double tNaive = naiveNearRoot(o, d);
            THEN("it is wrong by about 1, i.e. tens of millions of ulps") {
                // Source: hand derivation: b² = 4e16 exactly, but c = 1e16 − 1 needs 54 bits and
                // rounds to 1e16 (ulp 2, ties to even), so b² − 4ac = 0 and t = 1e8: an error of
                // exactly 1, against the ~1.5e-8 spacing of doubles near 1e8.
                CHECK(std::abs(tNaive - (1e8 - 1.0)) > 0.5);
                CHECK(rbtest::ulpDistance(tNaive, 1e8 - 1.0) > 10'000'000);
            }
        }
    }
    GIVEN("a ray from 1e8 away along a skew direction towards the centre") {
        const Vec3 dir = glm::normalize(Vec3(1, -2, 3));
        const Vec3 o = -1e8 * dir;
        THEN("t = |o| − 1 (in units of |d|) within 8 ulps") {
            // Source: for a ray aimed at the centre, the near hit is one radius short of it:
            // t = (|o| − 1) / |d|. Evaluated in long double (64-bit significand) so that the
            // reference is 2048 times finer than the double result. The ray misses the exact
            // centre by ~1e8·1e-16 = 1e-8, which changes t by (1e-8)²/2: negligible.
            const long double lo =
                std::sqrt((long double)o.x * o.x + (long double)o.y * o.y + (long double)o.z * o.z);
            const long double ld =
                std::sqrt((long double)dir.x * dir.x + (long double)dir.y * dir.y +
                          (long double)dir.z * dir.z);
            const double expected = static_cast<double>((lo - 1.0L) / ld);
            REQUIRE(sphere.intersect(rb::Ray{o, dir}, kInf, hit));
            CHECK(rbtest::ulpDistance(hit.t, expected) <= 8);
            // ...where the textbook formula is off by far more than that.
            CHECK(rbtest::ulpDistance(naiveNearRoot(o, dir), expected) > 1000);
        }
    }
}
// [ch01-stable-quadratic]

// ---- Ray–box ----------------------------------------------------------------------------------

SCENARIO("a ray meets the unit cube on the face it enters, or the face it leaves from inside",
         "[ch01][ex1.3]") {
    // Source for every row: hand derivation with the slabs 0 ≤ x, y, z ≤ 1; the entry distance
    // is the largest near-plane distance, the exit the smallest far-plane distance.
    const BoxCase cases[] = {
        {"along +z into the z = 0 face", Vec3(0.5, 0.5, -2), Vec3(0, 0, 1), true, 2.0,
         Vec3(0, 0, -1)},
        {"along −z into the z = 1 face", Vec3(0.5, 0.5, 3), Vec3(0, 0, -1), true, 2.0,
         Vec3(0, 0, 1)},
        {"slanted into the x = 0 face at (0, 0.75, 0.5)", Vec3(-1, 0.25, 0.5), Vec3(1, 0.5, 0),
         true, 1.0, Vec3(-1, 0, 0)},
        {"with |d| = 2 into the x = 1 face", Vec3(2, 0.5, 0.5), Vec3(-2, 0, 0), true, 0.5,
         Vec3(1, 0, 0)},
        {"along +y into the y = 0 face", Vec3(0.5, -3, 0.5), Vec3(0, 1, 0), true, 3.0,
         Vec3(0, -1, 0)},
        {"along −y into the y = 1 face", Vec3(0.2, 2, 0.3), Vec3(0, -1, 0), true, 1.0,
         Vec3(0, 1, 0)},
        {"from the centre out through x = 1", Vec3(0.5, 0.5, 0.5), Vec3(1, 0, 0), true, 0.5,
         Vec3(1, 0, 0)},
        {"from inside out through z = 0 (z is left first: 0.25/2 < 0.25/1)", Vec3(0.25, 0.25, 0.25),
         Vec3(-1, -1, -2), true, 0.125, Vec3(0, 0, -1)},
        {"past a corner: x = 0 reached at y = 2.25, y = 1 at x = −0.625", Vec3(-1, 0.25, 0.5),
         Vec3(1, 2, 0), false, 0, Vec3(0)},
        {"beside the cube", Vec3(2, 2, -1), Vec3(0, 0, 1), false, 0, Vec3(0)},
        {"away from the cube", Vec3(0.5, 0.5, -2), Vec3(0, 0, -1), false, 0, Vec3(0)},
    };
    const rb::Box box;
    for (const BoxCase& c : cases) {
        GIVEN(std::string("a ray ") + c.what) {
            rb::ObjectHit hit;
            const bool found = box.intersect(rb::Ray{c.o, c.d}, kInf, hit);
            THEN(std::string(c.hit ? "it hits at the hand-derived t with that face's outward "
                                     "normal"
                                   : "it misses")) {
                REQUIRE(found == c.hit);
                if (c.hit) {
                    CHECK(hit.t == Approx(c.t).epsilon(kTight));
                    CHECK(near(glm::normalize(hit.n), c.n));
                }
            }
        }
    }
}

SCENARIO("a ray lying in the plane of a box face touches the box without NaN", "[ch01][ex1.3]") {
    const rb::Box box;
    rb::ObjectHit hit;
    GIVEN("rays along +x in the planes of the bottom face (y = 0) and the top face (y = 1)") {
        THEN("each meets the closed cube where it crosses x = 0: t = 1, normal (−1, 0, 0)") {
            // Source: hand derivation: the cube is the closed set [0,1]³, so the edge
            // (0, y, 0.5) belongs to it; the ray reaches x = 0 at t = 1.
            for (double y : {0.0, 1.0}) {
                CAPTURE(y);
                REQUIRE(box.intersect(rb::Ray{Vec3(-1, y, 0.5), Vec3(1, 0, 0)}, kInf, hit));
                CHECK(hit.t == 1.0);
                CHECK(near(glm::normalize(hit.n), Vec3(-1, 0, 0)));
            }
        }
    }
    GIVEN("a ray in the plane y = 0 but beside the face (z = 1.5)") {
        THEN("it misses") {
            CHECK_FALSE(box.intersect(rb::Ray{Vec3(-1, 0, 1.5), Vec3(1, 0, 0)}, kInf, hit));
        }
    }
}

SCENARIO("a ray with zero direction components is handled by the slab tests", "[ch01][ex1.3]") {
    const rb::Box box;
    const rb::AABB unit{Vec3(0), Vec3(1)};
    GIVEN("rays along −z (d = (0, 0, −1)) and along −z with negative zeros (d = (−0, −0, −1))") {
        const Vec3 directions[] = {Vec3(0, 0, -1), Vec3(-0.0, -0.0, -1)};
        THEN("a ray over the middle of the top face hits it at t = 1") {
            // Source: hand derivation: from z = 2 down to z = 1.
            for (const Vec3& d : directions) {
                CAPTURE(std::signbit(d.x));
                rb::ObjectHit hit;
                REQUIRE(box.intersect(rb::Ray{Vec3(0.5, 0.5, 2), d}, kInf, hit));
                CHECK(hit.t == 1.0);
                double tEntry = -1;
                REQUIRE(rb::intersectBox(unit, rb::RayInverse(rb::Ray{Vec3(0.5, 0.5, 2), d}), kInf,
                                         tEntry));
                CHECK(tEntry == 1.0);
            }
        }
        THEN("a ray beside the box (x = 1.5) misses both the cube and its bounding box") {
            for (const Vec3& d : directions) {
                CAPTURE(std::signbit(d.x));
                rb::ObjectHit hit;
                CHECK_FALSE(box.intersect(rb::Ray{Vec3(1.5, 0.5, 2), d}, kInf, hit));
                double tEntry;
                CHECK_FALSE(rb::intersectBox(unit, rb::RayInverse(rb::Ray{Vec3(1.5, 0.5, 2), d}),
                                             kInf, tEntry));
            }
        }
        THEN("the slab test, like the cube, treats all four side faces as closed") {
            // Source: the box is the closed set [0,1]³ (the Box shape and the triangle test
            // include their boundaries), so rays running down the planes x = 0, x = 1, y = 0 and
            // y = 1 touch it. A BVH node that is missed here hides the triangles on its boundary
            // from every axis-aligned ray that grazes them.
            for (const Vec3& d : directions)
                for (const Vec3 o :
                     {Vec3(0, 0.5, 2), Vec3(1, 0.5, 2), Vec3(0.5, 0, 2), Vec3(0.5, 1, 2)}) {
                    CAPTURE(std::signbit(d.x), o.x, o.y);
                    rb::ObjectHit hit;
                    CHECK(box.intersect(rb::Ray{o, d}, kInf, hit));
                    double tEntry;
                    CHECK(rb::intersectBox(unit, rb::RayInverse(rb::Ray{o, d}), kInf, tEntry));
                }
        }
    }
}

// ---- The camera -------------------------------------------------------------------------------

// [ch01-camera-corners]
SCENARIO("camera rays through the image corners and centre follow from fovy and the aspect ratio",
         "[ch01][ex1.2]") {
    GIVEN(
        "A4's conventions: view (0, 0, −7) not normalised, up (0, 1, 1) not orthogonal, "
        "fovy 90°, a 200 × 100 image") {
        const rb::CameraSpec spec{Vec3(1, 2, 3), Vec3(0, 0, -7), Vec3(0, 1, 1), 90.0};
        const rb::PinholeCamera camera(spec, 200, 100);
        // Source: hand derivation. w = view/|view| = (0,0,−1); u = w × up normalised =
        // (1,0,0); v = u × w = (0,1,0). The image plane at distance 1 has half-height
        // tan(90°/2) = 1 and half-width 1 · 200/100 = 2.
        THEN("the frame is w = (0,0,−1), u = (1,0,0), v = (0,1,0) and rays start at the eye") {
            CHECK(near(camera.forward(), Vec3(0, 0, -1)));
            CHECK(near(camera.right(), Vec3(1, 0, 0)));
            CHECK(near(camera.upVector(), Vec3(0, 1, 0)));
            CHECK(camera.generateRay(17.5, 3.25).o == Vec3(1, 2, 3));
        }
        THEN("the centre (100, 50) looks along w") {
            CHECK(near(glm::normalize(camera.generateRay(100, 50).d), Vec3(0, 0, -1)));
        }
        THEN("the top-left corner (0, 0) looks along (−2, 1, −1)/√6") {
            CHECK(
                near(glm::normalize(camera.generateRay(0, 0).d), Vec3(-2, 1, -1) / std::sqrt(6.0)));
        }
        THEN("the top-right corner (200, 0) looks along (2, 1, −1)/√6") {
            CHECK(near(glm::normalize(camera.generateRay(200, 0).d),
                       Vec3(2, 1, -1) / std::sqrt(6.0)));
        }
        THEN("the bottom-right corner (200, 100) looks along (2, −1, −1)/√6") {
            CHECK(near(glm::normalize(camera.generateRay(200, 100).d),
                       Vec3(2, -1, -1) / std::sqrt(6.0)));
        }
    }
    GIVEN("a camera looking along +x with up (0, 5, 0), fovy 60°, a square image") {
        const rb::PinholeCamera camera(rb::CameraSpec{Vec3(0), Vec3(3, 0, 0), Vec3(0, 5, 0), 60.0},
                                       100, 100);
        THEN("the top-left ray is (1, 1/√3, −1/√3)/√(5/3)") {
            // Source: hand derivation: w = (1,0,0), u = w × up = (0,0,1), v = (0,1,0);
            // half-height = half-width = tan 30° = 1/√3; top-left = w − u/√3 + v/√3.
            const double h = 1.0 / std::sqrt(3.0);
            CHECK(near(glm::normalize(camera.generateRay(0, 0).d),
                       Vec3(1, h, -h) / std::sqrt(5.0 / 3.0)));
        }
        THEN("the rays through the top and bottom edge centres are fovy = 60° apart") {
            // Source: the definition of the vertical field of view.
            const Vec3 top = glm::normalize(camera.generateRay(50, 0).d);
            const Vec3 bottom = glm::normalize(camera.generateRay(50, 100).d);
            CHECK(std::acos(glm::dot(top, bottom)) == Approx(glm::radians(60.0)).epsilon(1e-12));
        }
    }
    GIVEN("camera parameters that cannot make a frame") {
        THEN("a zero view, an up parallel to the view, and fovy of 0° or 180° are InputErrors") {
            using rb::CameraSpec;
            CHECK_THROWS_AS(
                rb::PinholeCamera(CameraSpec{Vec3(0), Vec3(0), Vec3(0, 1, 0), 50}, 4, 4),
                rb::InputError);
            CHECK_THROWS_AS(
                rb::PinholeCamera(CameraSpec{Vec3(0), Vec3(0, 2, 0), Vec3(0, 1, 0), 50}, 4, 4),
                rb::InputError);
            CHECK_THROWS_AS(
                rb::PinholeCamera(CameraSpec{Vec3(0), Vec3(0, 0, -1), Vec3(0, 1, 0), 0}, 4, 4),
                rb::InputError);
            CHECK_THROWS_AS(
                rb::PinholeCamera(CameraSpec{Vec3(0), Vec3(0, 0, -1), Vec3(0, 1, 0), 180}, 4, 4),
                rb::InputError);
        }
    }
}
// [ch01-camera-corners]

// ---- The sampler ------------------------------------------------------------------------------

SCENARIO("the sampler's numbers depend only on seed, pixel, sample and dimension", "[ch01]") {
    constexpr int kPixels = 64, kDims = 8;
    GIVEN("every pixel's first 8 numbers, drawn pixel by pixel in order") {
        std::vector<double> inOrder;
        for (int p = 0; p < kPixels; ++p) {
            rb::Sampler s(7, p, 3);
            for (int k = 0; k < kDims; ++k) inOrder.push_back(s.next1D());
        }
        WHEN(
            "they are drawn again in reverse pixel order, one dimension at a time across all "
            "pixels (as threads might interleave)") {
            std::vector<rb::Sampler> samplers;
            for (int p = 0; p < kPixels; ++p) samplers.emplace_back(7, p, 3);
            std::vector<double> interleaved(inOrder.size());
            for (int k = 0; k < kDims; ++k)
                for (int p = kPixels - 1; p >= 0; --p)
                    interleaved[p * kDims + k] = samplers[p].next1D();
            THEN("every number is the same") {
                CHECK(interleaved == inOrder);
            }
        }
        WHEN("the seed, the sample index or the pixel changes") {
            rb::Sampler otherSeed(8, 0, 3), otherSample(7, 0, 4), otherPixel(7, 1, 3);
            THEN("the first number changes") {
                CHECK(otherSeed.next1D() != inOrder[0]);
                CHECK(otherSample.next1D() != inOrder[0]);
                CHECK(otherPixel.next1D() != inOrder[0]);
            }
        }
        THEN("every number lies in [0, 1) and the sampler counts its dimensions") {
            CHECK(*std::min_element(inOrder.begin(), inOrder.end()) >= 0.0);
            CHECK(*std::max_element(inOrder.begin(), inOrder.end()) < 1.0);
            rb::Sampler s(7, 0, 3);
            (void)s.next2D();
            CHECK(s.dimension() == 2);
        }
    }
}

SCENARIO("the sampler's numbers are uniform on the unit interval and the unit square", "[ch01]") {
    // Pearson's chi-square test with 16 equal cells, so 15 degrees of freedom. Two tests run,
    // so by Bonferroni each uses α = 0.01 / 2 = 0.005: the critical value is
    // χ²(15; 0.995) = 32.801. Source: NIST/SEMATECH e-Handbook of Statistical Methods,
    // table 1.3.6.7.4 (critical values of the chi-square distribution). Every expected count is
    // ≥ 5000, far above the rule-of-thumb minimum of 5, so no cells need pooling.
    // Fixed seed 2024; the test was also run locally with seeds 1–40, all of which pass.
    constexpr double kCritical = 32.801;
    constexpr int kCells = 16;
    const auto chiSquare = [](const std::vector<long>& counts, double expected) {
        double x2 = 0.0;
        for (long c : counts) x2 += (c - expected) * (c - expected) / expected;
        return x2;
    };
    GIVEN("160 000 one-dimensional draws: 10 000 pixels × 16 dimensions, seed 2024") {
        std::vector<long> counts(kCells, 0);
        for (int p = 0; p < 10000; ++p) {
            rb::Sampler s(2024, p, 0);
            for (int k = 0; k < 16; ++k) ++counts[static_cast<int>(s.next1D() * kCells)];
        }
        THEN("χ² over 16 equal bins stays below 32.801") {
            const double x2 = chiSquare(counts, 160000.0 / kCells);
            CAPTURE(x2);
            CHECK(x2 < kCritical);
        }
    }
    GIVEN("80 000 two-dimensional draws: 10 000 pixels × 8 pairs, seed 2024") {
        std::vector<long> counts(kCells, 0);
        for (int p = 0; p < 10000; ++p) {
            rb::Sampler s(2024, p, 1);
            for (int k = 0; k < 8; ++k) {
                const rb::Vec2 u = s.next2D();
                ++counts[static_cast<int>(u.x * 4) * 4 + static_cast<int>(u.y * 4)];
            }
        }
        THEN("χ² over a 4 × 4 grid of cells stays below 32.801") {
            const double x2 = chiSquare(counts, 80000.0 / kCells);
            CAPTURE(x2);
            CHECK(x2 < kCritical);
        }
    }
}

// ---- The render loop --------------------------------------------------------------------------

// [ch01-determinism]
SCENARIO("the image is bit-identical for 1 and 2 threads and for every run",
         "[ch01][ex1.1][ex1.2][ex1.3]") {
    GIVEN("a scene of three spheres on a floor, two lights, 64 × 48 pixels, 4 jittered samples") {
        const CodeScene code;
        WHEN("it is rendered with 1 thread, with 2 threads, and with 2 threads again") {
            const rb::Image one = code.render(1, 4, 11);
            const rb::Image two = code.render(2, 4, 11);
            const rb::Image again = code.render(2, 4, 11);
            THEN("the three images hold exactly the same bits") {
                CHECK(bitIdentical(one, two));
                CHECK(bitIdentical(two, again));
            }
            THEN("the image is not trivially black: most pixels see the floor or a sphere") {
                const long lit = std::count_if(one.data().begin(), one.data().end(),
                                               [](float c) { return c > 0.0f; });
                CHECK(lit > static_cast<long>(one.data().size() / 2));
            }
        }
        WHEN("the seed changes") {
            THEN("the jittered image changes too: the seed selects the random stream") {
                CHECK_FALSE(bitIdentical(code.render(2, 4, 11), code.render(2, 4, 12)));
            }
        }
    }
}

SCENARIO("both threads render part of the image and it still matches one thread bit for bit",
         "[ch01][ex1.3]") {
    GIVEN("the same scene at 256 × 192 pixels (192 tiles of 16 × 16) with 4 jittered samples") {
        const CodeScene code;
        std::vector<int> oneThreads;
        const rb::Image one = code.render(1, 4, 11, 256, 192, &oneThreads);
        WHEN("it is rendered with 2 threads, recording which thread rendered each tile") {
            // A run in which one thread takes every tile proves nothing (test_helpers.h).
            std::vector<int> tileThreads;
            const rb::Image two =
                code.render(2, 4, 11, 256, 192, &tileThreads, rbtest::bothThreadsTakeTiles());
            const bool both = std::count(tileThreads.begin(), tileThreads.end(), 0) > 0 &&
                              std::count(tileThreads.begin(), tileThreads.end(), 1) > 0;
            THEN("every tile was rendered once, by thread 0 or 1, and each thread took some") {
                REQUIRE(tileThreads.size() == 12u * 16u);
                REQUIRE(std::all_of(tileThreads.begin(), tileThreads.end(),
                                    [](int t) { return t == 0 || t == 1; }));
                REQUIRE(both);
                REQUIRE(std::all_of(oneThreads.begin(), oneThreads.end(),
                                    [](int t) { return t == 0; }));
            }
            THEN("the 2-thread image holds exactly the bits of the 1-thread image") {
                const long fromThread1 = std::count(tileThreads.begin(), tileThreads.end(), 1);
                INFO("tiles rendered by thread 1: " << fromThread1 << " of " << tileThreads.size());
                REQUIRE(bitIdentical(one, two));
            }
        }
    }
}
// [ch01-determinism]

SCENARIO("the pixel value is the average of its samples: their sum divided by spp",
         "[ch01][ex1.3][needs-ch02]") {
    GIVEN("a wall that fills the view, lit only by ambient light (radiance 0.15 everywhere)") {
        const AmbientWall wall;
        for (int spp : {1, 2, 3, 4, 16}) {
            WHEN("it is rendered with " + std::to_string(spp) + " jittered samples per pixel") {
                const rb::Image image = wall.render(spp);
                THEN("every pixel holds 0.15, to float rounding") {
                    // Source: the mean of spp samples that each equal 0.15 is 0.15; the image
                    // stores floats, so allow a few float ulps (2^-24 relative ≈ 6e-8).
                    float worst = 0.0f;
                    for (float c : image.data())
                        worst = std::max(worst, std::abs(c - float(AmbientWall::kRadiance)));
                    INFO("largest error " << worst << ", first pixel " << image.data()[0]);
                    REQUIRE(image.data().size() == 20u * 14u * 3u);
                    REQUIRE(worst <= 1e-6f);
                }
            }
        }
    }
}

// ---- The image and PNG output ----------------------------------------------------------------

SCENARIO("a PNG holds the clamped colour times 255, truncated, and is written atomically",
         "[ch01]") {
    rbtest::TempDir dir;
    GIVEN("a 4 × 2 image with values inside, above and below [0, 1], NaN and infinity") {
        rb::Image image(4, 2);
        const float nan = std::numeric_limits<float>::quiet_NaN();
        const float inf = std::numeric_limits<float>::infinity();
        const float values[24] = {0.5f, 0.25f, 0.75f, 1.0f,  2.0f,  -1.0f, nan,  inf,
                                  0.0f, 1.0f,  0.5f,  0.25f, 0.75f, 1.0f,  2.0f, -1.0f,
                                  -inf, 0.0f,  1.0f,  0.5f,  0.25f, 0.75f, 0.0f, 0.0f};
        std::copy(std::begin(values), std::end(values), image.data().begin());
        // Source: DESIGN §4.1 (the course framework clamps to [0,1] and writes ⌊255·c⌋) and
        // image.h (non-finite values become 0): 0.5 → 127, 0.25 → 63, 0.75 → 191, 1 and 2 →
        // 255, negatives, NaN and ±∞ → 0.
        const unsigned char expected[24] = {127, 63,  191, 255, 255, 0, 0,   0,   0,  255, 127, 63,
                                            191, 255, 255, 0,   0,   0, 255, 127, 63, 191, 0,   0};
        WHEN("it is written and read back") {
            const std::string path = (dir.path() / "out.png").string();
            rb::writePng(image, path);
            int w = 0, h = 0, channels = 0;
            unsigned char* pixels = stbi_load(path.c_str(), &w, &h, &channels, 3);
            REQUIRE(pixels != nullptr);
            const std::vector<unsigned char> bytes(pixels, pixels + 24);
            stbi_image_free(pixels);
            THEN("it has the same size and the expected bytes, and no temporary file is left") {
                CHECK(w == 4);
                CHECK(h == 2);
                CHECK(bytes ==
                      std::vector<unsigned char>(std::begin(expected), std::end(expected)));
                CHECK(std::distance(std::filesystem::directory_iterator(dir.path()),
                                    std::filesystem::directory_iterator()) == 1);
            }
        }
        WHEN("it is written into a folder that does not exist") {
            const std::string path = (dir.path() / "missing" / "out.png").string();
            THEN("writePng throws an InputError naming the path, and nothing is left behind") {
                CHECK_THROWS_WITH(rb::writePng(image, path), Contains(path));
                CHECK_THROWS_AS(rb::writePng(image, path), rb::InputError);
                CHECK(std::filesystem::is_empty(dir.path()));
            }
        }
        WHEN("it is written to a path that is an existing folder") {
            std::filesystem::create_directory(dir.path() / "taken.png");
            THEN("writePng throws, and the temporary file it wrote first is removed") {
                CHECK_THROWS_AS(rb::writePng(image, (dir.path() / "taken.png").string()),
                                rb::InputError);
                CHECK(std::distance(std::filesystem::directory_iterator(dir.path()),
                                    std::filesystem::directory_iterator()) == 1);
                CHECK(std::filesystem::is_empty(dir.path() / "taken.png"));
            }
        }
    }
}

SCENARIO("an image must have a positive size that the PNG encoder can hold", "[ch01]") {
    GIVEN("the limits kMaxDimension = 2^16 per side and kMaxPixels = 2^29") {
        THEN(
            "zero or negative sides are InputErrors whose message starts with the caller's "
            "prefix") {
            CHECK_THROWS_AS(rb::checkImageSize(0, 10, "x: "), rb::InputError);
            CHECK_THROWS_AS(rb::checkImageSize(10, 0, "x: "), rb::InputError);
            CHECK_THROWS_AS(rb::checkImageSize(-1, 5, "x: "), rb::InputError);
            CHECK_THROWS_WITH(rb::checkImageSize(0, 0, "scene.lua:3: "),
                              Catch::StartsWith("scene.lua:3: "));
            CHECK_THROWS_AS(rb::Image(0, 0), rb::InputError);
        }
        THEN("a side over 2^16, or more than 2^29 pixels, is too large") {
            CHECK_THROWS_AS(rb::checkImageSize(rb::kMaxDimension + 1LL, 1, ""), rb::InputError);
            CHECK_THROWS_AS(rb::checkImageSize(1 << 16, (1 << 13) + 1, ""), rb::InputError);
            CHECK_THROWS_AS(rb::checkImageSize(60000, 60000, ""), rb::InputError);
            CHECK_THROWS_AS(rb::checkImageSize(1LL << 40, 1LL << 40, ""), rb::InputError);
        }
        THEN("1 × 1 and exactly 2^16 × 2^13 = 2^29 pixels are accepted") {
            CHECK_NOTHROW(rb::checkImageSize(1, 1, ""));
            CHECK_NOTHROW(rb::checkImageSize(1 << 16, 1 << 13, ""));
        }
        THEN("the largest accepted image's filtered PNG rows, (3w + 1) h bytes, fit in an int") {
            // Source: stb_image_write sizes its filter buffer as (x * n + 1) * y in int.
            const long long worst =
                (3LL * rb::kMaxDimension + 1) * (rb::kMaxPixels / rb::kMaxDimension);
            CHECK(worst <= std::numeric_limits<int>::max());
        }
    }
}
