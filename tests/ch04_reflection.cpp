/// \file
/// Chapter 4 tests: mirror reflection and the recursion limit.
///
/// Chapter 4 claims that a mirror sends a ray on along r = d − 2(d·n)n (the angle out equals
/// the angle in, in the plane of d and n, with the length kept), that a mirror of reflectivity r
/// passes on the fraction r of what it sees, so light that has bounced k times between mirrors
/// carries r^k, and that the recursion stops after `maxDepth` reflections, which truncates the
/// geometric series of a hall of mirrors after exactly that many terms. It also claims that the
/// chapter is free when unused: a depth limit of 0, a reflectivity of 0, a scene without mirrors
/// and `--features=all,-reflection` all give chapter 2's Phong image, bit for bit.
///
/// The tests check the law on many random directions; build a corridor of two parallel mirror
/// slabs with the real integrator and pipeline (chapters 1–4 installed as `rt` installs them),
/// in which a tilted ray zig-zags a known number of times before it reaches a wall lit only by
/// ambient light, so the exact answer is r^k · kd · ambient; compare whole rendered images bit
/// for bit; and load Lua scenes with the chapter's own and the seeds' material calls. The
/// [stability] cases trace 1000 bounces between perfect mirrors, rays that meet a mirror exactly
/// on its edge, and reflections off mirrors from 1e-3 to 1e4 units in size. Nothing here is
/// random except the test directions, which come from std::mt19937_64 with fixed seeds (the
/// tests also pass with 20 other seeds for every stream; checked locally).
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <glm/gtc/matrix_transform.hpp>
#include <memory>
#include <string>
#include <vector>

#include "core/camera.h"
#include "core/error.h"
#include "core/image.h"
#include "scene/lua_scene.h"
#include "bvh/mesh.h"
#include "core/render.h"
#include "core/world.h"
#include "reflection/reflection.h"
#include "test_helpers.h"

using Catch::Contains;
using rb::Colour;
using rb::Mat4;
using rb::Vec3;
using rbtest::bitIdentical;
using rbtest::boxFromTo;
using rbtest::chapters;
using rbtest::finiteNonNegative;
using rbtest::loadSceneText;
using rbtest::materialOf;
using rbtest::oneMaterialScene;
using rbtest::renderSmall;

namespace {

// ---- Helpers --------------------------------------------------------------------------------

/// The shared test world, with materials made from kd, a reflectivity, ks and shininess.
class TestWorld : public rbtest::TestWorld {
  public:
    using rbtest::TestWorld::material;
    /// A material that lives as long as the world: kd, no specular, and reflectivity `reflect`
    /// (not set at all when negative, so the material is plain A4 Phong).
    const rb::Material* material(const Colour& kd, double reflect = -1.0,
                                 const Colour& ks = Colour(0.0), double shininess = 1.0) {
        rb::Material m;
        m.kd = kd;
        m.ks = ks;
        m.shininess = shininess;
        if (reflect >= 0.0) m.params["reflect"] = reflect;
        return material(m);
    }
};

/// Reflection rays counted.
std::uint64_t reflections(const rb::RayCounters& c) {
    return c.count[static_cast<int>(rb::RayKind::Reflection)];
}

/// The ambient light of the corridor tests; kd = 1 turns it into the target's colour.
const Colour kAmbient(0.2, 0.4, 0.8);

/// Two parallel mirror slabs facing each other across x: their inner faces are the planes
/// x = −1 and x = +1, and they reach far along y and z. Mirror material: kd = `mirrorKd`,
/// reflectivity r.
void addCorridor(TestWorld& world, double r, const Colour& mirrorKd = Colour(0.0)) {
    const rb::Material* mirror = world.material(mirrorKd, r);
    world.addBox(boxFromTo({-1.1, -50.0, -2.0}, {-1.0, 50.0, 2.0}), mirror);
    world.addBox(boxFromTo({1.0, -50.0, -2.0}, {1.1, 50.0, 2.0}), mirror);
}

/// Slope of the zig-zag ray: from the origin along (1, s, 0) it meets x = ±1 at
/// y = s, 3s, 5s, ... (one crossing of the corridor, 2 units wide, climbs 2s).
constexpr double kSlope = 0.1;

/// The y of a wall across the corridor that the zig-zag ray reaches after exactly k
/// reflections: halfway up its (k+1)-th leg, which spans y ∈ ((2k−1)s, (2k+1)s) for k ≥ 1
/// and (0, s) for k = 0. Source: hand derivation from the mirror hits at y = (2j−1)s.
double wallHeightAfter(int k) {
    return (2.0 * k + 0.5) * kSlope;
}

/// Load a scene file of the repository and build its first render's world as `rt` does;
/// `maxDepth` ≥ 0 overrides like --max-depth.
std::unique_ptr<rb::World> loadRepoScene(const std::string& relative,
                                         const rb::FeatureSet& features, int maxDepth = -1) {
    auto renders = rb::loadScene(rbtest::sourceDir() + "/" + relative, features,
                                 rb::SceneLoadOptions{});
    REQUIRE(!renders.empty());
    return rb::buildWorld(std::move(renders[0]), features, {}, maxDepth);
}

}  // namespace

// ---- The law of reflection ------------------------------------------------------------------

// [ch04-reflection-law]
SCENARIO("a mirror sends light out at the angle it came in, in the plane of d and n",
         "[ch04][ex4.1]") {
    GIVEN("10,000 random unit directions d and random unit normals n") {
        rbtest::Rng rng(4);
        WHEN("each d is reflected about its n: r = d − 2(d·n)n") {
            THEN(
                "the angle to the normal is mirrored, the tangential part kept, the length "
                "kept, and r lies in the plane of d and n") {
                for (int i = 0; i < 10000; ++i) {
                    const Vec3 d = rng.unitVector();
                    const Vec3 n = rng.unitVector();
                    const Vec3 r = rb::reflect(d, n);
                    // Source: the law of reflection, θ_r = θ_i, with r in the plane of
                    // incidence; |r|² = |d|² − 4(d·n)² + 4(d·n)²|n|² = |d|² for unit n.
                    const double cosTheta_i = glm::dot(d, n);
                    const double cosTheta_r = glm::dot(r, n);
                    REQUIRE(cosTheta_r == Approx(-cosTheta_i).margin(1e-15));
                    const Vec3 tangent_i = d - cosTheta_i * n;
                    const Vec3 tangent_r = r - cosTheta_r * n;
                    REQUIRE(glm::length(tangent_r - tangent_i) < 1e-15);
                    REQUIRE(glm::length(r) == Approx(1.0).epsilon(1e-15));
                    REQUIRE(std::abs(glm::dot(r, glm::cross(d, n))) < 1e-15);
                }
            }
        }
    }
}
// [ch04-reflection-law]

SCENARIO("reflecting twice about the same normal gives the ray back", "[ch04][ex4.1]") {
    GIVEN("random directions of any length and unit normals") {
        rbtest::Rng rng(40);
        THEN("reflect(reflect(d, n), n) = d, and |reflect(d, n)| = |d|") {
            for (int i = 0; i < 1000; ++i) {
                const Vec3 d = rng.uniform(0.01, 100.0) * rng.unitVector();
                const Vec3 n = rng.unitVector();
                // Source: the reflection I − 2nnᵀ is an involution and an isometry.
                const Vec3 back = rb::reflect(rb::reflect(d, n), n);
                REQUIRE(glm::length(back - d) <= 1e-13 * glm::length(d));
                REQUIRE(glm::length(rb::reflect(d, n)) == Approx(glm::length(d)).epsilon(1e-14));
            }
        }
    }
    GIVEN("a ray straight down onto a floor") {
        THEN("it comes straight back up; at 45° it leaves at 45° on the other side") {
            // Source: hand evaluation of d − 2(d·n)n.
            REQUIRE(rb::reflect(Vec3(0, -1, 0), Vec3(0, 1, 0)) == Vec3(0, 1, 0));
            REQUIRE(rb::reflect(Vec3(1, -1, 0), Vec3(0, 1, 0)) == Vec3(1, 1, 0));
            // A grazing ray passes unchanged.
            REQUIRE(rb::reflect(Vec3(1, 0, 0), Vec3(0, 1, 0)) == Vec3(1, 0, 0));
        }
    }
}

// ---- Energy: r^k after k bounces --------------------------------------------------------------

// [ch04-rk]
SCENARIO("light that bounced k times between mirrors of reflectivity r carries r^k",
         "[ch04][ex4.1][ex4.2]") {
    for (const double r : {0.3, 0.5, 0.9, 1.0}) {
        for (int k = 0; k <= 8; ++k) {
            GIVEN("a corridor of two black mirrors (kd = 0, reflect = " + std::to_string(r) +
                  ") and a white wall lit only by ambient light, k = " + std::to_string(k)) {
                TestWorld world;
                addCorridor(world, r);
                // The wall: kd = 1, so its Phong colour with no lights is exactly kd · ambient.
                const double y = wallHeightAfter(k);
                world.addBox(boxFromTo({-0.9, y, -2.0}, {0.9, y + 1.0, 2.0}),
                             world.material(Colour(1.0)));
                world.scene.ambient = kAmbient;
                world.scene.minWeight = 0.0;  // no adaptive depth control: the exact r^k
                world.build(chapters(4), /*maxDepth=*/20);
                WHEN("a ray leaves the middle of the corridor along (1, s, 0)") {
                    rb::RayCounters counters;
                    const Colour L =
                        world.trace(rb::Ray{Vec3(0.0), Vec3(1.0, kSlope, 0.0)}, counters);
                    THEN("it reflects exactly k times and returns r^k · kd · ambient") {
                        // Source: each mirror adds r · (what it sees) to its own colour,
                        // which is kd_mirror · ambient = 0; k nested mirrors give r^k · L_wall.
                        REQUIRE(reflections(counters) == static_cast<std::uint64_t>(k));
                        const Colour expected = std::pow(r, k) * kAmbient;
                        CHECK(L.r == Approx(expected.r).epsilon(1e-12));
                        CHECK(L.g == Approx(expected.g).epsilon(1e-12));
                        CHECK(L.b == Approx(expected.b).epsilon(1e-12));
                    }
                }
            }
        }
    }
}
// [ch04-rk]

SCENARIO("the depth limit cuts off images that need more bounces than it allows",
         "[ch04][ex4.1][ex4.2]") {
    GIVEN("the corridor with r = 0.8 and the wall 5 reflections away") {
        const double r = 0.8;
        const int k = 5;
        for (int maxDepth = 0; maxDepth <= 8; ++maxDepth) {
            TestWorld world;
            addCorridor(world, r);
            const double y = wallHeightAfter(k);
            world.addBox(boxFromTo({-0.9, y, -2.0}, {0.9, y + 1.0, 2.0}),
                         world.material(Colour(1.0)));
            world.scene.ambient = kAmbient;
            world.build(chapters(4), maxDepth);
            WHEN("the depth limit is " + std::to_string(maxDepth)) {
                rb::RayCounters counters;
                const Colour L = world.trace(rb::Ray{Vec3(0.0), Vec3(1.0, kSlope, 0.0)}, counters);
                THEN("the wall is seen (as r^5 · ambient) only when maxDepth ≥ 5; else black") {
                    // Source: the term adds nothing at depth ≥ maxDepth, so at most maxDepth
                    // reflections are traced; the mirrors themselves are black.
                    REQUIRE(reflections(counters) ==
                            static_cast<std::uint64_t>(std::min(maxDepth, k)));
                    const Colour expected = maxDepth >= k ? std::pow(r, k) * kAmbient : Colour(0.0);
                    CHECK(L.r == Approx(expected.r).epsilon(1e-12));
                    CHECK(L.g == Approx(expected.g).epsilon(1e-12));
                    CHECK(L.b == Approx(expected.b).epsilon(1e-12));
                }
            }
        }
    }
}

// [ch04-depth-series]
SCENARIO("a ray trapped between two facing mirrors sums a geometric series cut at maxDepth",
         "[ch04][ex4.2]") {
    for (const double r : {0.5, 0.9, 1.0}) {
        for (int maxDepth = 0; maxDepth <= 12; ++maxDepth) {
            GIVEN("two grey mirrors (kd = 0.5, reflect = " + std::to_string(r) +
                  ") in ambient light, depth limit " + std::to_string(maxDepth)) {
                const Colour kd(0.5);
                TestWorld world;
                addCorridor(world, r, kd);
                world.scene.ambient = kAmbient;
                world.scene.minWeight = 0.0;  // no adaptive depth control: the exact series
                world.build(chapters(4), maxDepth);
                WHEN("a ray runs along the mirrors' normal, bouncing back and forth forever") {
                    rb::RayCounters counters;
                    const Colour L = world.trace(rb::Ray{Vec3(0.0), Vec3(1.0, 0.0, 0.0)}, counters);
                    THEN("L = kd·ambient · (1 − r^(D+1)) / (1 − r), after exactly D reflections") {
                        // Source: L_j = kd·a + r·L_{j+1} with L_D = kd·a unrolls to
                        // kd·a · Σ_{j=0..D} r^j, the geometric series; (D+1)·kd·a for r = 1.
                        const double sum = r == 1.0 ? maxDepth + 1.0
                                                    : (1.0 - std::pow(r, maxDepth + 1)) / (1.0 - r);
                        const Colour expected = sum * kd * kAmbient;
                        REQUIRE(reflections(counters) == static_cast<std::uint64_t>(maxDepth));
                        CHECK(L.r == Approx(expected.r).epsilon(1e-12));
                        CHECK(L.g == Approx(expected.g).epsilon(1e-12));
                        CHECK(L.b == Approx(expected.b).epsilon(1e-12));
                    }
                }
            }
        }
    }
}
// [ch04-depth-series]

// [ch04-adaptive-depth]
SCENARIO("adaptive depth control stops a path once its light could no longer change a pixel",
         "[ch04][ex4.2]") {
    GIVEN("the trapped ray between grey mirrors of reflectivity 1/2, depth limit 20") {
        const double r = 0.5;
        const Colour kd(0.5);
        TestWorld world;
        addCorridor(world, r, kd);
        world.scene.ambient = kAmbient;
        world.build(chapters(4), 20);
        WHEN("the scene keeps the default minimum weight of 1/256") {
            rb::RayCounters counters;
            const Colour L = world.trace(rb::Ray{Vec3(0.0), Vec3(1.0, 0.0, 0.0)}, counters);
            THEN("reflections stop after the 8th, whose weight 2^-8 is the last at or above 1/256") {
                // Source: the j-th reflection has weight r^j = 2^-j in the pixel; it is traced
                // while 2^-j ≥ 1/256, i.e. for j = 1 … 8, so the sum ends at j = 8.
                REQUIRE(world.scene.minWeight == 1.0 / 256.0);
                REQUIRE(reflections(counters) == 8u);
                const double sum = (1.0 - std::pow(r, 9)) / (1.0 - r);
                const Colour expected = sum * kd * kAmbient;
                CHECK(L.r == Approx(expected.r).epsilon(1e-12));
                // What is dropped, r^9/(1 − r)·kd·a, is below one 8-bit level.
                CHECK(std::pow(r, 9) / (1.0 - r) * kd.r * kAmbient.r < 1.0 / 255.0);
            }
        }
    }
}
// [ch04-adaptive-depth]

// ---- When the chapter changes nothing ---------------------------------------------------------

// [ch04-depth0-is-phong]
SCENARIO("with a depth limit of 0 the chapter scene renders exactly as chapter 2 would",
         "[ch04][ex4.2]") {
    GIVEN("scenes/chapter04-reflection.lua, which has mirrors") {
        WHEN("it is rendered with maxDepth 0, and with --features=all,-reflection") {
            const auto depthZero =
                loadRepoScene("scenes/chapter04-reflection.lua", chapters(4, "all"), 0);
            const auto featureOff =
                loadRepoScene("scenes/chapter04-reflection.lua", chapters(4, "all,-reflection"));
            const auto full = loadRepoScene("scenes/chapter04-reflection.lua", chapters(4, "all"));
            REQUIRE(depthZero->pipeline.terms.size() == 1);
            REQUIRE(featureOff->pipeline.terms.empty());
            const rb::Image a = renderSmall(*depthZero);
            const rb::Image b = renderSmall(*featureOff);
            THEN("the two images are bit-identical (and differ from the render with mirrors)") {
                // Source: the term returns its input unchanged at depth ≥ maxDepth = 0.
                REQUIRE(bitIdentical(a, b));
                REQUIRE_FALSE(bitIdentical(a, renderSmall(*full)));
            }
        }
    }
}
// [ch04-depth0-is-phong]

SCENARIO("a scene without mirrors pays nothing for chapter 4", "[ch04]") {
    GIVEN("chapter 2's scene, which uses no `reflect`") {
        const auto withChapter4 = loadRepoScene("scenes/chapter02-phong.lua", chapters(4));
        const auto chapter3Only = loadRepoScene("scenes/chapter02-phong.lua", chapters(3));
        THEN("install() adds no shading term, and the image equals chapter 3's bit for bit") {
            REQUIRE(withChapter4->pipeline.terms.empty());
            REQUIRE(bitIdentical(renderSmall(*withChapter4), renderSmall(*chapter3Only)));
        }
    }
    GIVEN("a material that sets reflect = 0 explicitly") {
        const auto world = rbtest::worldFromLua(
            oneMaterialScene("gr.material{kd = {1, 0, 0}, reflect = 0}"), chapters(4));
        THEN("no term is installed either") {
            REQUIRE(world->pipeline.terms.empty());
        }
    }
    GIVEN("a material with reflect = 0.5") {
        const auto world = rbtest::worldFromLua(
            oneMaterialScene("gr.material{kd = {1, 0, 0}, reflect = 0.5}"), chapters(4));
        THEN("exactly one term, the reflection term, is installed") {
            REQUIRE(world->pipeline.terms.size() == 1);
            REQUIRE(dynamic_cast<const rb::ReflectionTerm*>(world->pipeline.terms[0].get()));
        }
    }
}

namespace {
/// A lit room with a mirror sphere, a sphere with reflect = 0, a floor and a dim blue
/// background: the scene of the next two scenarios. `mirrorReflect` < 0 makes the mirror a plain
/// Phong material.
void addMirrorRoom(TestWorld& world, double mirrorReflect, const rb::Material** zeroOut,
                   const rb::Material** mirrorOut) {
    const rb::Material* mirror =
        world.material(Colour(0.2, 0.3, 0.4), mirrorReflect, Colour(0.6), 40.0);
    const rb::Material* zero = world.material(Colour(0.8, 0.2, 0.1), 0.0, Colour(0.5), 20.0);
    const rb::Material* floor = world.material(Colour(0.5, 0.5, 0.45));
    world.addSphere(glm::scale(glm::translate(Mat4(1.0), Vec3(-1.2, 0.0, -5.0)), Vec3(1.0)),
                    mirror);
    world.addSphere(glm::scale(glm::translate(Mat4(1.0), Vec3(1.3, -0.2, -4.5)), Vec3(0.8)), zero);
    world.addBox(boxFromTo({-10, -2, -20}, {10, -1, 5}), floor);
    world.scene.ambient = Colour(0.15);
    world.scene.background = Colour(0.05, 0.1, 0.2);  // so every reflection adds something
    world.scene.lights.push_back(rb::PointLight{Vec3(-3, 5, 2), Colour(0.9), Vec3(1, 0, 0), {}});
    world.scene.lights.push_back(rb::PointLight{Vec3(4, 3, 0), Colour(0.4), Vec3(1, 0, 0), {}});
    if (zeroOut) *zeroOut = zero;
    if (mirrorOut) *mirrorOut = mirror;
}

/// The colour of every pixel centre whose camera ray first hits a surface of material `m`.
std::vector<Colour> pixelsOf(const TestWorld& world, const rb::Material* m) {
    rb::CameraSpec spec;
    spec.eye = Vec3(0, 0.5, 2);
    spec.view = Vec3(0, -0.2, -1);
    const rb::PinholeCamera camera(spec, 48, 36);
    std::vector<Colour> out;
    for (int y = 0; y < 36; ++y)
        for (int x = 0; x < 48; ++x) {
            const rb::Ray ray = camera.generateRay(x + 0.5, y + 0.5);
            rb::Hit hit;
            if (!world.scene.aggregate->intersect(ray, INFINITY, hit) || hit.material != m)
                continue;
            out.push_back(world.trace(ray));
        }
    return out;
}
}  // namespace

SCENARIO("reflectivity 0 shades exactly as plain Phong", "[ch04]") {
    GIVEN("a room with a mirror (so the reflection term is installed) and a reflect = 0 ball") {
        TestWorld on, off;
        const rb::Material* zeroOn = nullptr;
        const rb::Material* zeroOff = nullptr;
        addMirrorRoom(on, 0.7, &zeroOn, nullptr);
        addMirrorRoom(off, 0.7, &zeroOff, nullptr);
        on.build(chapters(4, "all"), 5);
        off.build(chapters(4, "all,-reflection"), 5);
        REQUIRE(on.pipeline.terms.size() == 1);
        WHEN("the ball is seen with the chapter on and with it off") {
            const auto a = pixelsOf(on, zeroOn);
            const auto b = pixelsOf(off, zeroOff);
            THEN("every pixel of the ball is bit-identical") {
                // Source: the term returns its input unchanged when reflect ≤ 0.
                REQUIRE(a.size() > 50);
                REQUIRE(a.size() == b.size());
                for (size_t i = 0; i < a.size(); ++i) REQUIRE(a[i] == b[i]);
            }
        }
    }
}

// [ch04-feature-off]
SCENARIO("with --features=all,-reflection a mirror shades as plain Phong", "[ch04][ex4.2]") {
    GIVEN("the room with a mirror ball (reflect = 0.7), and the same room with a Phong ball") {
        TestWorld off, phong, on;
        const rb::Material* mirrorOff = nullptr;
        const rb::Material* mirrorPhong = nullptr;
        const rb::Material* mirrorOn = nullptr;
        addMirrorRoom(off, 0.7, nullptr, &mirrorOff);
        addMirrorRoom(phong, -1.0, nullptr, &mirrorPhong);
        addMirrorRoom(on, 0.7, nullptr, &mirrorOn);
        off.build(chapters(4, "all,-reflection"), 5);
        phong.build(chapters(4, "all"), 5);
        on.build(chapters(4, "all"), 5);
        WHEN("the mirror is rendered with the chapter switched off") {
            const auto a = pixelsOf(off, mirrorOff);
            const auto b = pixelsOf(phong, mirrorPhong);
            const auto c = pixelsOf(on, mirrorOn);
            THEN("its pixels equal plain Phong's bit for bit (and differ with the chapter on)") {
                REQUIRE(off.pipeline.terms.empty());
                REQUIRE(a.size() > 50);
                REQUIRE(a.size() == b.size());
                size_t differentWhenOn = 0;
                for (size_t i = 0; i < a.size(); ++i) {
                    REQUIRE(a[i] == b[i]);
                    if (c[i] != a[i]) ++differentWhenOn;
                }
                REQUIRE(differentWhenOn == a.size());
            }
        }
    }
}
// [ch04-feature-off]

SCENARIO("a mirror seen from behind reflects like its front (no back-face culling)",
         "[ch04][ex4.1][ex4.2]") {
    GIVEN("a single mirror triangle in the plane z = 0, its normal along +z") {
        rb::ObjData data;
        data.positions = {Vec3(-5, -5, 0), Vec3(5, -5, 0), Vec3(0, 5, 0)};
        data.triangles.push_back({rb::ObjCorner{0}, rb::ObjCorner{1}, rb::ObjCorner{2}});
        const rb::Mesh mesh(data, "mirror.obj");
        TestWorld world;
        world.add(mesh, Mat4(1.0), world.material(Colour(0.0), 0.5));
        world.scene.background = Colour(0.25, 0.5, 1.0);
        world.build(chapters(4), 5);
        for (const double side : {1.0, -1.0}) {
            WHEN("a ray meets it at 45° from the " + std::string(side > 0 ? "front" : "back")) {
                rb::RayCounters counters;
                const Colour L = world.trace(
                    rb::Ray{Vec3(-1.0, 0.0, side * 1.0), Vec3(1.0, 0.0, -side)}, counters);
                THEN("it reflects once into the open: L = r · background") {
                    // Source: kd = 0, and the mirrored ray escapes to the background.
                    REQUIRE(reflections(counters) == 1);
                    REQUIRE(L == 0.5 * world.scene.background);
                }
            }
        }
    }
}

// ---- Stability ---------------------------------------------------------------------------------

SCENARIO("1000 bounces between perfect mirrors end, with a finite colour",
         "[ch04][stability][ex4.2]") {
    GIVEN("two facing mirrors with r = 1, a faint kd, and maxDepth = 1000") {
        const Colour kd(1e-3);
        TestWorld world;
        addCorridor(world, 1.0, kd);
        world.scene.ambient = kAmbient;
        world.build(chapters(4), 1000);
        WHEN("a ray runs along their normal") {
            rb::RayCounters counters;
            const Colour L = world.trace(rb::Ray{Vec3(0.0), Vec3(1.0, 0.0, 0.0)}, counters);
            THEN("the recursion stops after 1000 reflections with L = 1001 · kd · ambient") {
                // Source: the geometric series with r = 1 is (D + 1) terms of kd·a.
                REQUIRE(reflections(counters) == 1000);
                REQUIRE(finiteNonNegative(L));
                CHECK(L.r == Approx(1001.0 * 1e-3 * kAmbient.r).epsilon(1e-12));
                CHECK(L.b == Approx(1001.0 * 1e-3 * kAmbient.b).epsilon(1e-12));
            }
        }
    }
    GIVEN("black perfect mirrors (kd = 0, r = 1) and a tilted ray, maxDepth = 1000") {
        TestWorld world;
        addCorridor(world, 1.0);
        world.scene.ambient = kAmbient;
        world.build(chapters(4), 1000);
        THEN("the ray zig-zags 1000 times and returns black, not NaN") {
            rb::RayCounters counters;
            // Slope 0.01: 1000 legs climb about 20 units, still inside the 100-unit mirrors.
            const Colour L = world.trace(rb::Ray{Vec3(0.0), Vec3(1.0, 0.01, 0.0)}, counters);
            REQUIRE(reflections(counters) == 1000);
            REQUIRE(L == Colour(0.0));
        }
    }
}

// [ch04-edge]
SCENARIO("a ray that meets a mirror exactly on its edge reflects once, cleanly",
         "[ch04][stability][ex4.1][ex4.2]") {
    GIVEN("a black mirror cube [0,1]³ with r = 0.5 in front of a coloured background") {
        TestWorld world;
        world.addBox(Mat4(1.0), world.material(Colour(0.0), 0.5));
        world.scene.background = Colour(0.25, 0.5, 1.0);
        world.build(chapters(4), 5);
        // Points on edges and corners, and directions towards them: head-on to the edge,
        // oblique, and grazing (parallel to one of the two faces).
        struct Case {
            Vec3 target, direction;
        };
        const std::vector<Case> cases = {
            {{1, 1, 0.5}, {-1, -1, 0}},   {{1, 1, 0.5}, {-1, -2, 0.3}},   {{1, 1, 0.5}, {0, -1, 0}},
            {{1, 1, 0.5}, {-1, 0, 0}},    {{0, 1, 0.5}, {1, -1, 0}},      {{0.5, 0, 0}, {0, 1, 1}},
            {{1, 1, 1}, {-1, -1, -1}},    {{1, 1, 1}, {-1, -0.5, -0.25}}, {{0, 0, 0}, {1, 1, 1}},
            {{1, 0.5, 1}, {-3, 0.1, -1}},
        };
        for (const Case& c : cases) {
            WHEN("the ray is aimed along (" + std::to_string(c.direction.x) + ", " +
                 std::to_string(c.direction.y) + ", " + std::to_string(c.direction.z) +
                 ") at the edge point (" + std::to_string(c.target.x) + ", " +
                 std::to_string(c.target.y) + ", " + std::to_string(c.target.z) + ")") {
                rb::RayCounters counters;
                const rb::Ray ray{c.target - 2.0 * c.direction, c.direction};
                const Colour L = world.trace(ray, counters);
                THEN("it reflects exactly once and escapes: L = r · background") {
                    // Source: a mirrored ray leaves the entry face's half-space, and a convex
                    // box lies entirely inside it, so it can never hit the box again.
                    REQUIRE(finiteNonNegative(L));
                    REQUIRE(reflections(counters) == 1);
                    REQUIRE(L == 0.5 * world.scene.background);
                }
            }
        }
    }
}
// [ch04-edge]

// [ch04-no-self-hit]
SCENARIO("a reflected ray never hits the mirror it leaves, at scene scales 1e-3 to 1e4",
         "[ch04][stability][ex4.1][ex4.2]") {
    for (const double scale : {1e-3, 1e-1, 1.0, 1e2, 1e4}) {
        for (const bool sphere : {true, false}) {
            GIVEN(std::string("a black convex mirror (") + (sphere ? "sphere" : "box") +
                  ", r = 0.5) of size " + std::to_string(scale) + ", turned and moved away") {
                // Stretched, rotated about a skew axis (no face axis-aligned) and placed a few
                // sizes from the origin, so its world coordinates exceed its size.
                Mat4 m(1.0);
                m = glm::translate(m, scale * Vec3(3.0, -2.0, 5.0));
                m = glm::rotate(m, 0.7, glm::normalize(Vec3(1.0, 2.0, -0.5)));
                m = glm::scale(m, scale * Vec3(1.0, 0.6, 1.4));
                TestWorld world;
                const rb::Material* mirror = world.material(Colour(0.0), 0.5);
                if (sphere)
                    world.addSphere(m, mirror);
                else
                    world.addBox(m, mirror);
                world.scene.background = Colour(0.25, 0.5, 1.0);
                world.build(chapters(4), 5);
                const rb::AABB bounds = world.scene.instances[0].worldBounds;
                WHEN("2000 random rays from all around hit it") {
                    // A seed per scale. Through int64 first: a negative double (-2993 at
                    // scale 1e-3) converted straight to uint64 is undefined (UBSan caught it);
                    // int64 to uint64 wraps, giving the seed x86-64 always used.
                    rbtest::Rng rng(static_cast<std::uint64_t>(
                        static_cast<std::int64_t>(1000 * std::log10(scale) + 7)));
                    const Vec3 centre = 0.5 * (bounds.lo + bounds.hi);
                    const double radius = glm::length(bounds.hi - bounds.lo);
                    int hits = 0, clean = 0;
                    for (int i = 0; i < 2000; ++i) {
                        const Vec3 origin = centre + 2.0 * radius * rng.unitVector();
                        const Vec3 target(rng.uniform(bounds.lo.x, bounds.hi.x),
                                          rng.uniform(bounds.lo.y, bounds.hi.y),
                                          rng.uniform(bounds.lo.z, bounds.hi.z));
                        const rb::Ray ray{origin, target - origin};
                        rb::Hit hit;
                        if (!world.scene.aggregate->intersect(ray, INFINITY, hit)) continue;
                        ++hits;
                        rb::RayCounters counters;
                        const Colour L = world.trace(ray, counters);
                        if (reflections(counters) == 1 && L == 0.5 * world.scene.background)
                            ++clean;
                    }
                    THEN("every one reflects exactly once into the open: L = r · background") {
                        // Source: a convex mirror cannot see itself, so a second reflection
                        // can only be a self-hit caused by rounding.
                        REQUIRE(hits > 500);
                        REQUIRE(clean == hits);
                    }
                }
            }
        }
    }
}
// [ch04-no-self-hit]

// ---- Lua: raybook's fields and the seeds' dialects -------------------------------------------

// [ch04-lua]
SCENARIO("the seeds' material calls and raybook's named field all set `reflect`", "[ch04]") {
    const rb::FeatureSet features = chapters(4);
    GIVEN("raybook's gr.material{kd = ..., ks = ..., shininess = 25, reflect = 0.4}") {
        const rb::Material m = materialOf(
            "gr.material{kd = {0.1, 0.2, 0.3}, ks = {0.5, 0.5, 0.5}, shininess = 25, "
            "reflect = 0.4}",
            features);
        THEN("reflect = 0.4 and the Phong fields are set") {
            REQUIRE(m.param("reflect") == 0.4);
            REQUIRE(m.kd == Colour(0.1, 0.2, 0.3));
            REQUIRE(m.ks == Colour(0.5));
            REQUIRE(m.shininess == 25.0);
        }
    }
    GIVEN("seed 000's gr.material(kd, ks, shin, \"reflect\", 0.4)") {
        const rb::Material m = materialOf(
            "gr.material({0.65, 0.05, 0.05}, {0.1, 0.1, 0.1}, 1, \"reflect\", 0.4)", features);
        THEN("reflect = 0.4") {
            REQUIRE(m.param("reflect") == 0.4);
            REQUIRE(m.kd == Colour(0.65, 0.05, 0.05));
            REQUIRE(m.params.size() == 1);
        }
    }
    GIVEN("seed 001's gr.phongMat(kd, ks, shin, 0.3, 0)") {
        const rb::Material m =
            materialOf("gr.phongMat({0.7, 0.7, 0.7}, {0.4, 0.4, 0.4}, 30, 0.3, 0)", features);
        THEN("reflect = 0.3, and glossiness 0 sets nothing") {
            REQUIRE(m.param("reflect") == 0.3);
            REQUIRE(m.params.count("glossiness") == 0);
            REQUIRE(m.shininess == 30.0);
        }
    }
    GIVEN("seed 002's gr.fancy_material(kd, ks, shin, 0.25, 1.0, 0, 0)") {
        const rb::Material m = materialOf(
            "gr.fancy_material({0.3, 0.2, 0.1}, {0.8, 0.8, 0.8}, 60, 0.25, 1.0, 0, 0)", features);
        THEN("reflect = 0.25; with no transparency the ior is not needed and not set") {
            REQUIRE(m.param("reflect") == 0.25);
            REQUIRE(m.params.count("ior") == 0);
            REQUIRE(m.params.count("transparency") == 0);
        }
    }
    GIVEN("a plain A4 gr.material(kd, ks, shin)") {
        const rb::Material m = materialOf("gr.material({1, 0, 0}, {0, 0, 0}, 1)", features);
        THEN("no chapter parameter at all") {
            REQUIRE(m.params.empty());
        }
    }
}
// [ch04-lua]

SCENARIO("a chapter-4 build names the chapter a later material field needs", "[ch04]") {
    const rb::FeatureSet features = chapters(4);
    const auto fails = [&](const std::string& material) {
        return [=] { loadSceneText(oneMaterialScene(material), features); };
    };
    GIVEN("refraction fields (chapter 5)") {
        THEN("each form of asking for them fails with 'needs chapter 5'") {
            REQUIRE_THROWS_WITH(fails("gr.material{kd = {1, 1, 1}, ior = 1.5}")(),
                                Contains("needs chapter 5"));
            REQUIRE_THROWS_WITH(fails("gr.material{kd = {1, 1, 1}, transparency = 0.9}")(),
                                Contains("needs chapter 5"));
            REQUIRE_THROWS_WITH(
                fails("gr.material({0.65, 0.05, 0.05}, {0.1, 0.1, 0.1}, 1, \"refract\", 1.5)")(),
                Contains("needs chapter 5"));
            REQUIRE_THROWS_WITH(
                fails("gr.fancy_material({1, 1, 1}, {1, 1, 1}, 10, 0.1, 1.5, 0.9, 0)")(),
                Contains("needs chapter 5"));
            REQUIRE_THROWS_WITH(fails("gr.transMat({1, 1, 1}, 1.5, 0.9, 0)")(),
                                Contains("needs chapter 5"));
        }
    }
    GIVEN("glossiness (chapter 7)") {
        THEN("each form of asking for it fails with 'needs chapter 7'") {
            REQUIRE_THROWS_WITH(fails("gr.material{kd = {1, 1, 1}, glossiness = 0.2}")(),
                                Contains("needs chapter 7"));
            REQUIRE_THROWS_WITH(
                fails("gr.material({0.3, 0.6, 0.6}, {0.5, 0.7, 0.5}, 35, \"glossy\", 0.1, "
                      "\"reflect\", 0.5)")(),
                Contains("needs chapter 7"));
            REQUIRE_THROWS_WITH(fails("gr.phongMat({1, 1, 1}, {1, 1, 1}, 10, 0.5, 3)")(),
                                Contains("needs chapter 7"));
            REQUIRE_THROWS_WITH(
                fails("gr.fancy_material({1, 1, 1}, {1, 1, 1}, 10, 0.5, 1.0, 0, 0.2)")(),
                Contains("needs chapter 7"));
        }
    }
    GIVEN("a ball light (chapter 6)") {
        THEN("gr.ball_light fails with 'needs chapter 6'") {
            REQUIRE_THROWS_WITH(
                loadSceneText("local l = gr.ball_light({0, 5, 0}, {1, 1, 1}, {1, 0, 0}, 0.5)\n",
                              features),
                Contains("needs chapter 6"));
        }
    }
    GIVEN("the seed dialects with their later parameters left at 0") {
        THEN("they load: a chapter-4 build accepts seed scenes that only use mirrors") {
            REQUIRE_NOTHROW(fails("gr.phongMat({1, 1, 1}, {1, 1, 1}, 10, 0.5, 0)")());
            REQUIRE_NOTHROW(fails("gr.fancy_material({1, 1, 1}, {1, 1, 1}, 10, 0.5, 1.5, 0, 0)")());
            REQUIRE_NOTHROW(
                fails("gr.material({1, 1, 1}, {1, 1, 1}, 10, \"glossy\", 0, "
                      "\"reflect\", 0.5)")());
        }
    }
}

SCENARIO("seed 000's \"refract\", 0 means no refraction, as \"reflect\", 0 means no mirror",
         "[ch04]") {
    // Seed 000 writes every keyword it knows, with 0 for the effects a material lacks (its own
    // example: "glossy", 0.1, "reflect", 0, "refract", 0.6). A 0 after "refract" is "does not
    // refract", not "index of refraction 0": like the other dialect calls, it must set nothing,
    // so a chapter-4 build loads it and later chapters do not see an ior of 0.
    GIVEN("gr.material(kd, ks, shin, \"glossy\", 0, \"reflect\", 0.5, \"refract\", 0)") {
        const std::string material =
            "gr.material({0.1, 0.1, 0.1}, {0.7, 0.7, 0.7}, 50, \"glossy\", 0, \"reflect\", "
            "0.5, \"refract\", 0)";
        WHEN("a chapter-4 build loads it") {
            THEN("it loads, with reflect = 0.5 and no ior or transparency") {
                rb::Material m;
                REQUIRE_NOTHROW(m = materialOf(material, chapters(4)));
                REQUIRE(m.param("reflect") == 0.5);
                REQUIRE(m.params.count("ior") == 0);
                REQUIRE(m.params.count("transparency") == 0);
            }
        }
    }
}

SCENARIO("a chapter-3 build names chapter 4 when a scene asks for a mirror", "[ch04]") {
    const rb::FeatureSet features = chapters(3);
    THEN("reflect, seed 000's keyword form, gr.phongMat and gr.fancy_material name chapter 4") {
        REQUIRE_THROWS_WITH(
            loadSceneText(oneMaterialScene("gr.material{kd = {1, 1, 1}, reflect = 0.5}"), features),
            Contains("needs chapter 4"));
        REQUIRE_THROWS_WITH(
            loadSceneText(
                oneMaterialScene("gr.material({1, 1, 1}, {0, 0, 0}, 1, \"reflect\", 0.5)"),
                features),
            Contains("chapter 4"));
        REQUIRE_THROWS_WITH(
            loadSceneText(oneMaterialScene("gr.phongMat({1, 1, 1}, {0, 0, 0}, 1, 0.5, 0)"),
                          features),
            Contains("needs chapter 4"));
        REQUIRE_THROWS_WITH(
            loadSceneText(
                oneMaterialScene("gr.fancy_material({1, 1, 1}, {0, 0, 0}, 1, 0.5, 1, 0, 0)"),
                features),
            Contains("needs chapter 4"));
    }
}

SCENARIO("seed 000's keyword form rejects what it does not know", "[ch04]") {
    const rb::FeatureSet features = chapters(4);
    const auto load = [&](const std::string& material) {
        loadSceneText(oneMaterialScene(material), features);
    };
    GIVEN("an unknown keyword") {
        THEN("the error names it and lists the known ones") {
            REQUIRE_THROWS_WITH(load("gr.material({1, 1, 1}, {0, 0, 0}, 1, \"mirror\", 0.5)"),
                                Contains("unknown keyword \"mirror\"") &&
                                    Contains("\"reflect\", \"refract\" or \"glossy\""));
        }
    }
    GIVEN("a keyword without its number") {
        THEN("the error says a number must follow") {
            REQUIRE_THROWS_WITH(load("gr.material({1, 1, 1}, {0, 0, 0}, 1, \"reflect\")"),
                                Contains("needs a number after it"));
        }
    }
    GIVEN("a keyword followed by a string instead of a number") {
        THEN("the error names the argument") {
            REQUIRE_THROWS_WITH(load("gr.material({1, 1, 1}, {0, 0, 0}, 1, \"reflect\", \"lots\")"),
                                Contains("must be a number"));
        }
    }
    GIVEN("an unknown named field") {
        THEN("the error names it") {
            REQUIRE_THROWS_WITH(load("gr.material{kd = {1, 1, 1}, reflectivity = 0.5}"),
                                Contains("unknown material field 'reflectivity'"));
        }
    }
    GIVEN("a wrong argument count for gr.phongMat and gr.fancy_material") {
        THEN("the error shows the expected signature") {
            REQUIRE_THROWS_WITH(load("gr.phongMat({1, 1, 1}, {0, 0, 0}, 1, 0.5)"),
                                Contains("gr.phongMat expects 5 arguments"));
            REQUIRE_THROWS_WITH(load("gr.fancy_material({1, 1, 1}, {0, 0, 0}, 1, 0.5)"),
                                Contains("gr.fancy_material expects 7 arguments"));
        }
    }
}

SCENARIO("--lenient reads a material whose reflectivity is out of range without it",
         "[ch04][lenient]") {
    GIVEN("a material with a reflectivity of 1.5, outside raybook's range, in a chapter-4 build") {
        const std::string lua =
            rbtest::oneMaterialScene("gr.material({0.1, 0.8, 0.1}, {0.2, 0.2, 0.2}, 25, 1.5)");
        THEN("without --lenient it is an error, as before") {
            CHECK_THAT(rbtest::loadError(lua, rbtest::chapters(4)),
                       Contains("scene.lua:1: gr.material: argument 4 (reflectivity) must be "
                                "from 0 to 1"));
        }
        THEN("with --lenient the material is read without it: the student's colours, no mirror") {
            rb::SceneLoadOptions lenient;
            lenient.lenient = true;
            rb::SceneLoadReport report;
            rbtest::TempDir dir;
            const auto renders =
                rb::loadScene(dir.write("scene.lua", lua), rbtest::chapters(4), lenient, &report);
            const rb::Material* m = renders.at(0).instances.at(0).material;
            REQUIRE(m != nullptr);
            CHECK(rbtest::near(m->kd, Vec3(0.1, 0.8, 0.1)));
            CHECK(m->shininess == 25);
            CHECK(m->params.count("reflect") == 0);
            REQUIRE(report.unreadable.size() == 1);
            CHECK_THAT(report.unreadable[0], Contains("read with its first 3 arguments)"));
        }
    }
}
