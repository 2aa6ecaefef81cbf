/// \file
/// Chapter 2 tests: the A4 scene language, Phong shading, point lights and hard shadows.
///
/// Chapter 2 claims that a CS488 A4 scene file means exactly what the course says it means:
/// transforms apply in the order they are written (and in reverse for legacy files), one node
/// under several parents is several instances of one shape, gr.nh_box's tuple is its minimum
/// corner; that normals under non-uniform scale follow the inverse transpose; that a pixel's
/// colour is kd·ambient + Σ visible·I(r)·(kd·max(0,n·l) + ks·max(0,r·v)^shininess) with
/// I(r) = colour / (c0 + c1·r + c2·r²); that nothing is culled; that a ray spawned at a
/// surface never re-hits that surface (no shadow acne) at any scene scale from 1e-3 to 1e4;
/// and that bad input stops with an error naming the file and the line. The tests run real Lua
/// scenes through rb::loadScene and compare what comes out with values derived by hand.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <string>

#include "core/box.h"
#include "core/error.h"
#include "core/light.h"
#include "phong/phong.h"
#include "core/render.h"
#include "core/sphere.h"
#include "test_helpers.h"

using Catch::Contains;
using rb::Colour;
using rb::Vec3;
using rbtest::loadError;
using rbtest::loadSceneText;
using rbtest::renderLine;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

/// Tolerance for values that pass through a few 4×4 matrix products and inverses (each entry a
/// sum of a few products of order-1 numbers, about 1e-16 relative error per operation): 1e-12
/// leaves a factor of thousands over the accumulated rounding, and is still far below any
/// error a wrong formula would make.
constexpr double kMatrixTol = 1e-12;

/// True when a and b agree component-wise within tol.
bool near(const Vec3& a, const Vec3& b, double tol = kMatrixTol) {
    return std::abs(a.x - b.x) <= tol && std::abs(a.y - b.y) <= tol && std::abs(a.z - b.z) <= tol;
}

/// Where an instance's transform sends a point of its shape's object space.
Vec3 place(const rb::Instance& instance, const Vec3& pObject) {
    return rb::transformPoint(instance.objectToWorld, pObject);
}

/// The first instance with the given name (or fail the test).
const rb::Instance& instanceNamed(const std::vector<rb::Instance>& instances,
                                  const std::string& name) {
    for (const rb::Instance& i : instances)
        if (i.name == name) return i;
    FAIL("no instance named " << name);
    throw std::logic_error("unreachable");
}

/// Fill a large block of stack with 0xFF bytes, so that anything that still points into a
/// stack frame that has returned reads garbage (NaN for doubles) instead of stale values.
__attribute__((noinline)) void scribbleStack() {
    volatile unsigned char block[1 << 18];
    for (size_t i = 0; i < sizeof block; ++i) block[i] = 0xFF;
}

}  // namespace

// ---- The scene graph --------------------------------------------------------------------------

// [ch02-transform-order]
SCENARIO("transforms apply in the order they are written", "[ch02][ex2.2]") {
    GIVEN("a unit sphere that is scaled by 2 and then translated by (1, 0, 0)") {
        const auto world = rbtest::worldFromLua(
            "local root = gr.node('root')\n"
            "local s = gr.sphere('s')\n"
            "s:scale(2, 2, 2)\n"
            "s:translate(1, 0, 0)\n"
            "root:add_child(s)\n" +
            renderLine());
        const rb::Instance& s = world->scene.instances.at(0);
        THEN("its centre is at (1, 0, 0) and its radius is 2") {
            // Source: pre-multiplication (DESIGN §4.1): M = T(1,0,0)·S(2), so the centre
            // M·(0,0,0) = (1,0,0) and the surface point (1,0,0) goes to (2+1, 0, 0).
            CHECK(near(place(s, Vec3(0)), Vec3(1, 0, 0)));
            CHECK(near(place(s, Vec3(1, 0, 0)), Vec3(3, 0, 0)));
            CHECK(near(place(s, Vec3(0, 0, 1)), Vec3(1, 0, 2)));
        }
        THEN("a ray along −x from (10, 0, 0) meets it at t = 10 − 3 = 7") {
            rb::Hit hit;
            REQUIRE(world->scene.aggregate->intersect(rb::Ray{Vec3(10, 0, 0), Vec3(-1, 0, 0)}, kInf,
                                                      hit));
            CHECK(hit.t == Approx(7.0).epsilon(kMatrixTol));
        }
    }
    GIVEN("the same two calls in the other order: translate, then scale") {
        const auto renders = loadSceneText(
            "local root = gr.node('root')\n"
            "local s = gr.sphere('s')\n"
            "s:translate(1, 0, 0)\n"
            "s:scale(2, 2, 2)\n"
            "root:add_child(s)\n" +
            renderLine());
        THEN("the translation is scaled too: the centre is at (2, 0, 0)") {
            // Source: M = S(2)·T(1,0,0), so M·(0,0,0) = 2·(1,0,0).
            CHECK(near(place(renders.at(0).instances.at(0), Vec3(0)), Vec3(2, 0, 0)));
        }
    }
    GIVEN("a rotation by 90° about z followed by a translation by (1, 0, 0)") {
        const auto renders = loadSceneText(
            "local root = gr.node('root')\n"
            "local s = gr.sphere('s')\n"
            "s:rotate('z', 90)\n"
            "s:translate(1, 0, 0)\n"
            "root:add_child(s)\n" +
            renderLine());
        THEN("the point (1, 0, 0) turns to (0, 1, 0), then moves to (1, 1, 0)") {
            // Source: a right-handed rotation by 90° about z sends x to y.
            CHECK(near(place(renders.at(0).instances.at(0), Vec3(1, 0, 0)), Vec3(1, 1, 0)));
        }
    }
    GIVEN("a child scaled by 2 under a parent translated by (0, 5, 0)") {
        const auto renders = loadSceneText(
            "local root = gr.node('root')\n"
            "local parent = gr.node('parent')\n"
            "parent:translate(0, 5, 0)\n"
            "local s = gr.sphere('s')\n"
            "s:scale(2, 2, 2)\n"
            "parent:add_child(s)\n"
            "root:add_child(parent)\n" +
            renderLine());
        THEN("the child's transform applies first: (1, 0, 0) goes to (2, 5, 0)") {
            // Source: world = parent · child (DESIGN §4.1, scene_graph.h).
            CHECK(near(place(renders.at(0).instances.at(0), Vec3(1, 0, 0)), Vec3(2, 5, 0)));
        }
    }
}
// [ch02-transform-order]

SCENARIO("legacy scenes post-multiply, so they list their transforms in reverse", "[ch02][ex2.2]") {
    GIVEN("the calls scale(2, 2, 2); translate(1, 0, 0) in a legacy (pre-2015) scene") {
        const auto renders = rbtest::loadSceneText(
            "local root = gr.node('root')\n"
            "local s = gr.sphere('s')\n"
            "s:scale(2, 2, 2)\n"
            "s:translate(1, 0, 0)\n"
            "root:add_child(s)\n" +
                renderLine(),
            "legacy.lua", /*legacy=*/true);
        THEN("they mean translate first, then scale: the centre is at (2, 0, 0), radius 2") {
            // Source: post-multiplication (DESIGN §4.2): M = S(2)·T(1,0,0).
            const rb::Instance& s = renders.at(0).instances.at(0);
            CHECK(near(place(s, Vec3(0)), Vec3(2, 0, 0)));
            CHECK(near(place(s, Vec3(1, 0, 0)), Vec3(4, 0, 0)));
        }
    }
}

SCENARIO("one node under several parents becomes several instances of one shape", "[ch02][ex2.2]") {
    GIVEN("a sphere added under three parents translated by (2i, 0, 0)") {
        const auto renders = loadSceneText(
            "local root = gr.node('root')\n"
            "local leg = gr.sphere('leg')\n"
            "for i = 1, 3 do\n"
            "  local p = gr.node('p' .. i)\n"
            "  p:translate(2 * i, 0, 0)\n"
            "  p:add_child(leg)\n"
            "  root:add_child(p)\n"
            "end\n" +
            renderLine());
        const auto& instances = renders.at(0).instances;
        THEN("there are three instances, sharing one Shape, centred at x = 2, 4 and 6") {
            REQUIRE(instances.size() == 3);
            for (int i = 0; i < 3; ++i) {
                CHECK(instances[i].shape == instances[0].shape);
                CHECK(instances[i].name == "leg");
                CHECK(near(place(instances[i], Vec3(0)), Vec3(2.0 * (i + 1), 0, 0)));
            }
        }
    }
    GIVEN("a diamond: root → a, root → b, a → leaf, b → leaf") {
        const auto renders = loadSceneText(
            "local root = gr.node('root')\n"
            "local a = gr.node('a')\n"
            "local b = gr.node('b')\n"
            "a:translate(-1, 0, 0)\n"
            "b:translate(1, 0, 0)\n"
            "local leaf = gr.cube('leaf')\n"
            "a:add_child(leaf)\n"
            "b:add_child(leaf)\n"
            "root:add_child(a)\n"
            "root:add_child(b)\n" +
            renderLine());
        THEN("the leaf is drawn twice, once through each path") {
            const auto& instances = renders.at(0).instances;
            REQUIRE(instances.size() == 2);
            CHECK(near(place(instances[0], Vec3(0)), Vec3(-1, 0, 0)));
            CHECK(near(place(instances[1], Vec3(0)), Vec3(1, 0, 0)));
        }
    }
}

SCENARIO("a node without a material takes its nearest ancestor's, or the default grey",
         "[ch02][ex2.2]") {
    GIVEN("a red group holding a bare sphere, and a bare cube under the plain root") {
        auto renders = loadSceneText(
            "local red = gr.material({0.9, 0.1, 0.1}, {0, 0, 0}, 1)\n"
            "local root = gr.node('root')\n"
            "local group = gr.node('group')\n"
            "group:set_material(red)\n"
            "group:add_child(gr.sphere('ball'))\n"
            "root:add_child(group)\n"
            "root:add_child(gr.cube('crate'))\n" +
            renderLine());
        // Anything that still points into the loader's own stack frame reads 0xFF bytes after
        // this, instead of stale values that happen to look right.
        scribbleStack();
        const auto& instances = renders.at(0).instances;
        THEN("the sphere is red") {
            const rb::Instance& ball = instanceNamed(instances, "ball");
            REQUIRE(ball.material != nullptr);
            CHECK(ball.material->kd == Colour(0.9, 0.1, 0.1));
        }
        THEN("the cube has the default material kd = 0.5, ks = 0, which outlives the loader") {
            // Source: SceneBuilder::defaultMaterial (lua_scene.h): kd 0.5, ks 0, shininess 1.
            const rb::Instance& crate = instanceNamed(instances, "crate");
            REQUIRE(crate.material != nullptr);
            CHECK(crate.material->kd == Colour(0.5));
            CHECK(crate.material->ks == Colour(0.0));
            CHECK(crate.material->shininess == 1.0);
        }
    }
}

SCENARIO("gr.nh_box's tuple is its minimum corner and gr.nh_sphere's is its centre",
         "[ch02][ex2.2]") {
    GIVEN("gr.nh_box('b', {1, 2, 3}, 2) and gr.nh_sphere('s', {-1, -2, -3}, 0.5)") {
        const auto world = rbtest::worldFromLua(
            "local root = gr.node('root')\n"
            "root:add_child(gr.nh_box('b', {1, 2, 3}, 2))\n"
            "root:add_child(gr.nh_sphere('s', {-1, -2, -3}, 0.5))\n" +
            renderLine());
        const rb::Instance& box = instanceNamed(world->scene.instances, "b");
        const rb::Instance& sphere = instanceNamed(world->scene.instances, "s");
        THEN("the box spans (1, 2, 3) to (3, 4, 5)") {
            // Source: DESIGN §4.1: the tuple is the minimum corner; the side is 2.
            CHECK(near(place(box, Vec3(0)), Vec3(1, 2, 3)));
            CHECK(near(place(box, Vec3(1)), Vec3(3, 4, 5)));
            CHECK(near(box.worldBounds.lo, Vec3(1, 2, 3)));
            CHECK(near(box.worldBounds.hi, Vec3(3, 4, 5)));
        }
        THEN("a ray down the box's axis from z = 10 meets its top face at t = 10 − 5 = 5") {
            rb::Hit hit;
            REQUIRE(world->scene.aggregate->intersect(rb::Ray{Vec3(2, 3, 10), Vec3(0, 0, -1)}, kInf,
                                                      hit));
            CHECK(hit.t == Approx(5.0).epsilon(kMatrixTol));
            CHECK(near(hit.ng, Vec3(0, 0, 1)));
        }
        THEN("a ray down the sphere's axis from z = 10 meets it at t = 10 − (−3 + 0.5) = 12.5") {
            rb::Hit hit;
            REQUIRE(world->scene.aggregate->intersect(rb::Ray{Vec3(-1, -2, 10), Vec3(0, 0, -1)},
                                                      kInf, hit));
            CHECK(hit.t == Approx(12.5).epsilon(kMatrixTol));
            CHECK(hit.instance == &sphere);
        }
    }
}

// [ch02-normal-inverse-transpose]
SCENARIO("normals under non-uniform scale follow the inverse transpose", "[ch02][ex2.2]") {
    GIVEN("the ellipsoid x² + (y/2)² + (z/3)² = 1, made as sphere:scale(1, 2, 3)") {
        const auto world = rbtest::worldFromLua(
            "local root = gr.node('root')\n"
            "local e = gr.sphere('e')\n"
            "e:scale(1, 2, 3)\n"
            "root:add_child(e)\n" +
            renderLine());
        // Source: hand derivation. The unit-sphere point q = (1,1,1)/√3 maps to
        // p = (1, 2, 3)/√3. The ellipsoid's gradient there is (x/1², y/2², z/3²) =
        // (1, 1/2, 1/3)/√3 ∝ (6, 3, 2), and |(6, 3, 2)| = 7.
        const Vec3 p = Vec3(1, 2, 3) / std::sqrt(3.0);
        const Vec3 nExpected = Vec3(6, 3, 2) / 7.0;
        WHEN("a ray comes down the normal from p + 5n") {
            rb::Hit hit;
            REQUIRE(world->scene.aggregate->intersect(rb::Ray{p + 5.0 * nExpected, -nExpected},
                                                      kInf, hit));
            THEN("it hits p at t = 5 with the gradient normal (6, 3, 2)/7") {
                CHECK(hit.t == Approx(5.0).epsilon(kMatrixTol));
                CHECK(near(hit.p, p));
                CHECK(near(hit.ng, nExpected));
            }
            THEN("the normal transformed like a point direction, M·q, would be wrong") {
                // M·q ∝ (1, 2, 3): its cosine with the true normal is 18/(7√14) ≈ 0.687.
                const Vec3 wrong = glm::normalize(Vec3(1, 2, 3));
                CHECK(glm::dot(wrong, hit.ng) < 0.7);
            }
        }
    }
    GIVEN("the same ellipsoid turned by 90° about z after the scale") {
        const auto world = rbtest::worldFromLua(
            "local root = gr.node('root')\n"
            "local e = gr.sphere('e')\n"
            "e:scale(1, 2, 3)\n"
            "e:rotate('z', 90)\n"
            "root:add_child(e)\n" +
            renderLine());
        // Source: the rotation (x, y, z) → (−y, x, z) turns p and its normal alike:
        // p = (−2, 1, 3)/√3 and n = (−3, 6, 2)/7.
        const Vec3 p = Vec3(-2, 1, 3) / std::sqrt(3.0);
        const Vec3 nExpected = Vec3(-3, 6, 2) / 7.0;
        THEN("the hit normal is the rotated gradient normal") {
            rb::Hit hit;
            REQUIRE(world->scene.aggregate->intersect(rb::Ray{p + 5.0 * nExpected, -nExpected},
                                                      kInf, hit));
            CHECK(hit.t == Approx(5.0).epsilon(kMatrixTol));
            CHECK(near(hit.ng, nExpected));
        }
    }
}
// [ch02-normal-inverse-transpose]

// ---- Phong shading ----------------------------------------------------------------------------

// [ch02-phong-terms]
SCENARIO("Phong's diffuse and specular terms follow the cosines of known angles", "[ch02][ex2.1]") {
    const rb::Material m{Colour(0.2, 0.4, 0.6), Colour(0.5), 10.0, {}};
    const Vec3 n(0, 0, 1);
    const double s60 = std::sqrt(3.0) / 2.0;  // sin 60° = cos 30°
    GIVEN("light arriving 60° from the normal, l = (sin 60°, 0, cos 60°)") {
        const Vec3 l(s60, 0, 0.5);
        WHEN("the viewer sits exactly in the mirror direction r = (−sin 60°, 0, cos 60°)") {
            THEN("the term is kd·cos 60° + ks·1^10 = kd/2 + ks") {
                // Source: n·l = cos 60° = 1/2; r·v = 1.
                const Colour c = rb::phongBrdfTerm(m, n, l, Vec3(-s60, 0, 0.5));
                CHECK(c.r == Approx(0.1 + 0.5).epsilon(kMatrixTol));
                CHECK(c.g == Approx(0.2 + 0.5).epsilon(kMatrixTol));
                CHECK(c.b == Approx(0.3 + 0.5).epsilon(kMatrixTol));
            }
        }
        WHEN("the viewer is 30° away from the mirror direction: v = (−sin 30°, 0, cos 30°)") {
            THEN("the specular part is ks·cos^10 30° = ks·(3/4)^5 = ks·243/1024") {
                // Source: r = (−sin 60°, 0, cos 60°) and v lie in the xz-plane 30° apart, so
                // r·v = cos 30° = √3/2, and (√3/2)^10 = (3/4)^5 = 243/1024.
                const Vec3 v(-0.5, 0, s60);
                const Colour c = rb::phongBrdfTerm(m, n, l, v);
                const double spec = 0.5 * 243.0 / 1024.0;
                CHECK(c.r == Approx(0.1 + spec).epsilon(kMatrixTol));
                CHECK(c.b == Approx(0.3 + spec).epsilon(kMatrixTol));
            }
        }
        WHEN("the viewer is on the same side as the light (r·v < 0)") {
            THEN("only the diffuse part kd/2 remains") {
                const Colour c = rb::phongBrdfTerm(m, n, l, Vec3(s60, 0, -0.5));
                CHECK(c.r == Approx(0.1).epsilon(kMatrixTol));
                CHECK(c.g == Approx(0.2).epsilon(kMatrixTol));
            }
        }
    }
    GIVEN("light arriving from below the surface (n·l < 0)") {
        THEN("the term is zero, even for a viewer in the mirror direction") {
            const Colour c = rb::phongBrdfTerm(m, n, Vec3(0, s60, -0.5), Vec3(0, -s60, -0.5));
            CHECK(c == Colour(0.0));
        }
    }
}
// [ch02-phong-terms]

SCENARIO("a point light's intensity falls off as 1/(c0 + c1·r + c2·r²)",
         "[ch02][ex2.1][ex2.2][ex2.3]") {
    GIVEN("lights of colour (1, 2, 4) with different falloffs") {
        rb::PointLight light;
        light.colour = Colour(1, 2, 4);
        THEN("{1, 0, 0} is constant; {0, 0, 1} is the inverse square; {1, 2, 3} at r = 2 is /17") {
            // Source: DESIGN §4.1, I(r) = colour / (c0 + c1·r + c2·r²).
            light.falloff = Vec3(1, 0, 0);
            CHECK(light.intensityAt(5.0) == Colour(1, 2, 4));
            light.falloff = Vec3(0, 0, 1);
            CHECK(near(light.intensityAt(2.0), Colour(0.25, 0.5, 1.0)));
            light.falloff = Vec3(1, 2, 3);
            CHECK(near(light.intensityAt(2.0), Colour(1, 2, 4) / 17.0));
        }
    }
    GIVEN(
        "a scene whose only light, {c0, c1, c2} = {1, 0.5, 0.25}, is 5 units from a floor "
        "point") {
        const auto world = rbtest::worldFromLua(
            "local grey = gr.material({0.5, 0.5, 0.5}, {0, 0, 0}, 1)\n"
            "local root = gr.node('root')\n"
            "local floor = gr.cube('floor')\n"
            "floor:scale(20, 1, 20)\n"
            "floor:translate(-10, -1, -10)\n"
            "floor:set_material(grey)\n"
            "root:add_child(floor)\n"
            "local light = gr.light({0, 4, 0}, {1, 1, 1}, {1, 0.5, 0.25})\n"
            "gr.render(root, 'x.png', 8, 8, {3, 5, 5}, {0, -1, -1}, {0, 1, 0}, 50,"
            " {0, 0, 0}, {light})\n");
        THEN("gr.light keeps the falloff in the order c0, c1, c2") {
            REQUIRE(world->scene.lights.size() == 1);
            CHECK(world->scene.lights[0].falloff == Vec3(1, 0.5, 0.25));
        }
        THEN("the point (3, 0, 0) gets kd·(n·l)·I = 0.5 · 0.8 / (1 + 2.5 + 6.25)") {
            // Source: hand derivation: the light is at (0,4,0), so r = |(−3, 4, 0)| = 5 and
            // n·l = 4/5; the falloff is 1 + 0.5·5 + 0.25·25 = 9.75; ks = 0 and no ambient.
            const Colour c = rbtest::traceOne(*world, rb::Ray{Vec3(3, 5, 5), Vec3(0, -1, -1)});
            CHECK(c.r == Approx(0.5 * 0.8 / 9.75).epsilon(kMatrixTol));
        }
    }
}

SCENARIO("a point behind an occluder receives only ambient light",
         "[ch02][ex2.1][ex2.2][ex2.3]") {
    GIVEN("a floor with top y = 0, a light at (0, 4, 0) and a ball of radius 0.5 at (0, 2, 0)") {
        const auto world = rbtest::worldFromLua(
            "local grey = gr.material({0.5, 0.5, 0.5}, {0, 0, 0}, 1)\n"
            "local root = gr.node('root')\n"
            "local floor = gr.cube('floor')\n"
            "floor:scale(20, 1, 20)\n"
            "floor:translate(-10, -1, -10)\n"
            "floor:set_material(grey)\n"
            "root:add_child(floor)\n"
            "root:add_child(gr.nh_sphere('blocker', {0, 2, 0}, 0.5))\n"
            "local light = gr.light({0, 4, 0}, {1, 1, 1}, {1, 0, 0})\n"
            "gr.render(root, 'x.png', 8, 8, {0, 5, 5}, {0, -1, -1}, {0, 1, 0}, 50,"
            " {0.2, 0.2, 0.2}, {light})\n");
        WHEN("the floor point (0, 0, 0), straight below the ball, is seen from (5, 5, 0)") {
            // The eye ray passes √2 from the ball's centre, so it reaches the floor.
            const Colour c = rbtest::traceOne(*world, rb::Ray{Vec3(5, 5, 0), Vec3(-1, -1, 0)});
            THEN("its colour is kd·ambient = 0.5 · 0.2 = 0.1 exactly: no light gets through") {
                CHECK(c.r == Approx(0.1).epsilon(kMatrixTol));
                CHECK(c.g == Approx(0.1).epsilon(kMatrixTol));
            }
        }
        WHEN(
            "the floor point (3, 0, 0), whose segment to the light passes 1.2 from the ball's "
            "centre, is seen from (3, 5, 5)") {
            const Colour c = rbtest::traceOne(*world, rb::Ray{Vec3(3, 5, 5), Vec3(0, -1, -1)});
            THEN("it is lit: 0.1 + kd·(n·l) = 0.1 + 0.5 · 0.8 = 0.5") {
                // Source: hand derivation: l = (−3, 4, 0)/5; the segment's closest point to
                // (0, 2, 0) is (0.96, 2.72, 0), at distance 1.2 > 0.5.
                CHECK(c.r == Approx(0.5).epsilon(kMatrixTol));
            }
        }
    }
}

SCENARIO("nothing is culled: a ray from inside a sphere hits it and is shaded",
         "[ch02][ex2.1][ex2.2][ex2.3]") {
    GIVEN("a sphere of radius 2 at the origin with a light inside it at (0.5, 0, 0)") {
        const auto world = rbtest::worldFromLua(
            "local m = gr.material({0.3, 0.3, 0.3}, {0.2, 0.2, 0.2}, 7)\n"
            "local root = gr.node('root')\n"
            "local s = gr.nh_sphere('s', {0, 0, 0}, 2)\n"
            "s:set_material(m)\n"
            "root:add_child(s)\n"
            "local light = gr.light({0.5, 0, 0}, {1, 1, 1}, {1, 0, 0})\n"
            "gr.render(root, 'x.png', 8, 8, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 50,"
            " {0.5, 0.5, 0.5}, {light})\n");
        WHEN("a ray leaves the centre along +x") {
            const rb::Ray ray{Vec3(0), Vec3(1, 0, 0)};
            rb::Hit hit;
            REQUIRE(world->scene.aggregate->intersect(ray, kInf, hit));
            THEN("it hits the inside of the sphere at t = 2") {
                CHECK(hit.t == Approx(2.0));
            }
            THEN("the inside is shaded as a front face: kd·ambient + kd·1 + ks·1^7") {
                // Source: hand derivation: at (2,0,0) the normal turned to the viewer is
                // (−1,0,0); the light lies along it (n·l = 1) and so does the mirror
                // direction (r·v = 1); I = 1. So 0.3·0.5 + 0.3 + 0.2 = 0.65.
                const Colour c = rbtest::traceOne(*world, ray);
                CHECK(c.r == Approx(0.65).epsilon(kMatrixTol));
            }
        }
    }
}

SCENARIO("a pixel's colour is kd·ambient + Σ visible·I(r)·(kd·max(0,n·l) + ks·max(0,r·v)^s)",
         "[ch02][ex2.1][ex2.2][ex2.3]") {
    GIVEN(
        "a 1 × 1 image of a unit sphere seen from (0, 0, 5), and three lights: one in view, "
        "one behind the sphere, and one hidden by a second ball") {
        const auto world = rbtest::worldFromLua(
            "local mat = gr.material({0.5, 0.6, 0.7}, {0.4, 0.4, 0.4}, 2)\n"
            "local grey = gr.material({0.3, 0.3, 0.3}, {0, 0, 0}, 1)\n"
            "local root = gr.node('root')\n"
            "local ball = gr.sphere('ball')\n"
            "ball:set_material(mat)\n"
            "root:add_child(ball)\n"
            "local blocker = gr.nh_sphere('blocker', {0, -2, 2.5}, 0.5)\n"
            "blocker:set_material(grey)\n"
            "root:add_child(blocker)\n"
            "local l1 = gr.light({0, 4, 4}, {0.8, 0.8, 0.8}, {1, 0, 0.04})\n"
            "local l2 = gr.light({0, 0, -5}, {1, 1, 1}, {1, 0, 0})\n"
            "local l3 = gr.light({0, -4, 4}, {0.8, 0.8, 0.8}, {1, 0, 0.04})\n"
            "gr.render(root, 'pixel.png', 1, 1, {0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 30,"
            " {0.1, 0.2, 0.3}, {l1, l2, l3})\n");
        WHEN("the pixel is rendered") {
            const rb::Image image = rbtest::renderWorld(*world, {.threads = 1});
            THEN("it is (0.2276, 0.3216, 0.4356)") {
                // Source: hand derivation. The pixel centre's ray runs down −z and hits the
                // pole p = (0,0,1): n = v = (0,0,1).
                //  ambient:  kd·(0.1, 0.2, 0.3) = (0.05, 0.12, 0.21)
                //  l1 at (0,4,4): p→l1 = (0,4,3), r = 5, l = (0, 0.8, 0.6), n·l = 0.6;
                //      mirror r = 2(n·l)n − l = (0, −0.8, 0.6), r·v = 0.6, 0.6² = 0.36;
                //      I = 0.8 / (1 + 0.04·25) = 0.4;
                //      0.4·(kd·0.6 + 0.4·0.36) = 0.4·(0.444, 0.504, 0.564)
                //                              = (0.1776, 0.2016, 0.2256)
                //  l2 at (0,0,−5): n·l = −1, so it adds nothing.
                //  l3 at (0,−4,4): the mirror image of l1, which would add as much again, but
                //      its segment from p passes through the blocker's centre (0, −2, 2.5).
                // The image stores floats (24-bit significand): 1e-7 is 4 half-ulps at 0.44.
                const Colour c = image.get(0, 0);
                CHECK(c.r == Approx(0.2276).margin(1e-7));
                CHECK(c.g == Approx(0.3216).margin(1e-7));
                CHECK(c.b == Approx(0.4356).margin(1e-7));
            }
        }
    }
}

// ---- No shadow acne ---------------------------------------------------------------------------

// [ch02-no-acne]
SCENARIO("spawned rays never re-hit their own surface, at scene scales from 1e-3 to 1e4",
         "[ch02][ex2.2]") {
    // A sphere, a box (stretched unevenly) and a single triangle, each turned about a skew axis
    // and placed a few sizes from the origin, at every scale s. At 300 random surface points
    // (fixed seed) we spawn rays the way shading does, with rb::offsetRayOrigin, and count
    // what goes wrong:
    //  - a ray leaving a convex or flat surface (the mirror direction, or any direction into
    //    the outer half-space) can never meet that surface again;
    //  - a ray sent into the sphere must cross it and leave at the chord length 2R·cos θ;
    //    a ray sent into the box must leave by another face; a ray sent through the
    //    triangle must not meet it.
    const rb::Sphere sphere;
    const rb::Box box;
    const auto triangle =
        rbtest::makeMesh({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.3, 1, 0)}, {{0, 1, 2}});
    for (const double scale : rbtest::kSceneScales) {
        GIVEN("objects of size " + std::to_string(scale)) {
            struct Case {
                const char* name;
                rb::Instance instance;
                int outwardRehits = 0;   ///< Rays leaving the surface that met it again.
                int inwardFailures = 0;  ///< Rays sent into it that did not do what they must.
            };
            Case cases[] = {
                {"sphere", rbtest::makeInstance(sphere, rbtest::placeAtScale(scale))},
                {"box", rbtest::makeInstance(box, rbtest::placeAtScale(scale, Vec3(1, 0.6, 1.4)))},
                {"triangle", rbtest::makeInstance(*triangle, rbtest::placeAtScale(scale))},
            };
            WHEN("rays are spawned from 300 random points on each, 5 outwards and 4 inwards") {
                rbtest::Rng rng(1234);
                for (Case& c : cases) {
                    const std::string name = c.name;
                    const auto points = rbtest::sampleSurface(c.instance, rng, 300);
                    REQUIRE(points.size() == 300);
                    for (const rbtest::SurfacePoint& sp : points) {
                        const Vec3 dIn = glm::normalize(sp.probe.d);
                        // The side of the surface the probe came from.
                        const Vec3 outside = rb::faceForward(sp.hit.ng, -dIn);
                        std::vector<Vec3> away = {rbtest::mirror(dIn, outside)};
                        for (int k = 0; k < 4; ++k) away.push_back(rng.hemisphere(outside));
                        for (const Vec3& d : away) {
                            rb::ObjectHit oh;
                            if (c.instance.intersect(rbtest::spawnRay(sp.hit, d), kInf, oh))
                                ++c.outwardRehits;
                        }
                        for (int k = 0; k < 4; ++k) {
                            const Vec3 d = rng.hemisphere(-outside);
                            const rb::Ray spawned = rbtest::spawnRay(sp.hit, d);
                            rb::ObjectHit oh;
                            const bool found = c.instance.intersect(spawned, kInf, oh);
                            bool ok;
                            if (name == "sphere") {
                                // Source: a chord at angle θ to the inward normal of a sphere
                                // of radius R has length 2R·cos θ. The origin sits
                                // 1e-9·|p| ≈ 6e-9·s inside, which lengthens the chord by about
                                // that over cos θ: below 1e-6·s for cos θ > 0.01. Grazier
                                // chords must at least not stop near their starting point.
                                const double cosTheta = glm::dot(d, -outside);
                                const double chord = 2.0 * scale * cosTheta;
                                ok = found && oh.t >= 0.5 * chord &&
                                     (cosTheta < 0.01 || std::abs(oh.t - chord) <= 1e-6 * scale);
                            } else if (name == "box") {
                                // Source: a ray entering a convex box through one face leaves
                                // through another (a plane is crossed at most once).
                                ok = found &&
                                     glm::dot(c.instance.toWorld(spawned, oh).ng, sp.hit.ng) < 0.5;
                            } else {
                                // A flat triangle is crossed at most once: at the start point.
                                ok = !found;
                            }
                            if (!ok) ++c.inwardFailures;
                        }
                    }
                }
                THEN(
                    "no ray leaving a surface meets it again, and every ray sent into one "
                    "behaves as the geometry says") {
                    for (const Case& c : cases) {
                        CAPTURE(c.name, scale);
                        CHECK(c.outwardRehits == 0);
                        CHECK(c.inwardFailures == 0);
                    }
                }
            }
        }
    }
}
// [ch02-no-acne]

// ---- Bad input --------------------------------------------------------------------------------

SCENARIO("adding a node under its own descendant is refused as a cycle", "[ch02]") {
    GIVEN("a → b, then b:add_child(a) on line 4") {
        const std::string message = loadError(
            "local a = gr.node('a')\n"
            "local b = gr.node('b')\n"
            "a:add_child(b)\n"
            "b:add_child(a)\n" +
                renderLine("a"),
            "cycle.lua");
        THEN("loading throws an InputError naming cycle.lua:4 and the cycle") {
            CHECK_THAT(message, Contains("cycle.lua:4:"));
            CHECK_THAT(message, Contains("cycle"));
        }
    }
    GIVEN("a:add_child(a) on line 2") {
        const std::string message =
            loadError("local a = gr.node('a')\na:add_child(a)\n" + renderLine("a"), "self.lua");
        THEN("it is a cycle too, reported at self.lua:2") {
            CHECK_THAT(message, Contains("self.lua:2:"));
            CHECK_THAT(message, Contains("cycle"));
        }
    }
}

SCENARIO("a wrong argument count or type, or a NaN, is an error naming the file and the line",
         "[ch02]") {
    // Each bad call sits on line 2 of bad_args.lua; line 1 makes a node n.
    struct BadCall {
        const char* call;
        const char* mentions;  ///< What the message must name besides the place.
    };
    const BadCall calls[] = {
        {"gr.sphere()", "gr.sphere"},
        {"gr.sphere(42)", "gr.sphere"},
        {"gr.nh_sphere('s', 5, 1)", "gr.nh_sphere"},
        {"gr.nh_sphere('s', {1, 2}, 1)", "gr.nh_sphere"},
        {"gr.nh_sphere('s', {0/0, 0, 0}, 1)", "nan"},
        {"n:translate(1/0, 0, 0)", "inf"},
        {"gr.material({1, 1, 1}, {0, 0, 0}, 'shiny')", "gr.material"},
        {"n:rotate('w', 30)", "node:rotate"},
        {"n:scale(1, 1)", "node:scale"},
        {"gr.light({0, 0, 0}, {1, 1, 1})", "gr.light"},
        {"n:add_child(5)", "node:add_child"},
        {"gr.render(n)", "gr.render"},
    };
    GIVEN("twelve scenes, each with one bad call on line 2") {
        THEN("each load throws an InputError that starts its report with bad_args.lua:2:") {
            for (const BadCall& bad : calls) {
                CAPTURE(bad.call);
                const std::string message = loadError(
                    std::string("local n = gr.node('n')\n") + bad.call + "\n" + renderLine("n"),
                    "bad_args.lua");
                CAPTURE(message);
                CHECK_THAT(message, Contains("bad_args.lua:2:"));
                CHECK_THAT(message, Contains(bad.mentions));
            }
        }
    }
}
