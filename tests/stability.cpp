/// \file
/// The stability suite for chapters 1–3: each method where it is known to fail.
///
/// Ray tracers break at the edges of their assumptions: a ray spawned on a surface finds that
/// surface again (shadow acne), most visibly at very small or very large scene scales; a ray
/// through the exact edge or vertex of a mesh slips between its triangles; degenerate
/// triangles and grazing rays produce NaN; rays with zero direction components meet 0·∞ in the
/// slab test; a tree over badly spread objects grows deeper than its traversal stack; NaN and
/// Inf enter through the scene file; coincident surfaces fight. Each scenario below builds one
/// of these situations on purpose and shows that it is handled: no NaN, no Inf, no negative
/// radiance, no crash, and where a result is only approximate, the bound it keeps.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "core/aggregate.h"
#include "core/box.h"
#include "bvh/bvh_aggregate.h"
#include "core/error.h"
#include "phong/phong.h"
#include "core/render.h"
#include "core/sphere.h"
#include "bvh/triangle.h"
#include "test_helpers.h"

using Catch::Contains;
using rb::Vec3;
using rbtest::loadError;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kPi = 3.14159265358979323846;

/// A closed latitude–longitude sphere of radius 1: `bands` rings of `segments` quads, each quad
/// cut into two triangles, with fans at the poles. Every quad is an isosceles trapezoid and so
/// planar, which makes the mesh the convex hull of its vertices: a convex polyhedron.
std::shared_ptr<rb::Mesh> latLongSphere(int bands, int segments) {
    std::vector<Vec3> positions = {Vec3(0, 1, 0), Vec3(0, -1, 0)};  // the poles
    for (int i = 1; i < bands; ++i) {
        const double theta = kPi * i / bands;
        for (int j = 0; j < segments; ++j) {
            const double phi = 2 * kPi * j / segments;
            positions.emplace_back(std::sin(theta) * std::cos(phi), std::cos(theta),
                                   std::sin(theta) * std::sin(phi));
        }
    }
    const auto ring = [&](int i, int j) { return 2 + (i - 1) * segments + (j % segments); };
    std::vector<std::array<int, 3>> triangles;
    for (int j = 0; j < segments; ++j) {
        triangles.push_back({0, ring(1, j + 1), ring(1, j)});
        triangles.push_back({1, ring(bands - 1, j), ring(bands - 1, j + 1)});
        for (int i = 1; i + 1 < bands; ++i) {
            triangles.push_back({ring(i, j), ring(i, j + 1), ring(i + 1, j + 1)});
            triangles.push_back({ring(i, j), ring(i + 1, j + 1), ring(i + 1, j)});
        }
    }
    return rbtest::makeMesh(positions, triangles, "lat-long-sphere");
}

/// Render the first gr.render request of a world on two threads with the given samples per
/// pixel.
rb::Image renderWorld(const rb::World& world, int spp) {
    return rbtest::renderWorld(world, {.threads = 2, .samplesPerPixel = spp});
}

/// A chapter 1–3 scene scaled by s: a floor, a ball resting on it, a crate standing on it
/// (coincident faces), a squashed and turned sphere, a triangle mesh and two lights whose
/// falloff is constant, so that the picture is the same at every scale.
std::string scaledScene(double s) {
    char head[64];
    std::snprintf(head, sizeof head, "local s = %.17g\n", s);
    return std::string(head) +
           "local grey = gr.material({0.6, 0.6, 0.6}, {0.2, 0.2, 0.2}, 10)\n"
           "local red = gr.material({0.8, 0.2, 0.1}, {0.6, 0.6, 0.6}, 40)\n"
           "local root = gr.node('root')\n"
           "local floor = gr.cube('floor')\n"
           "floor:scale(20 * s, s, 20 * s)\n"
           "floor:translate(-10 * s, -2 * s, -10 * s)\n"
           "floor:set_material(grey)\n"
           "root:add_child(floor)\n"
           "local ball = gr.nh_sphere('ball', {-1 * s, -0.2 * s, 0}, 0.8 * s)\n"
           "ball:set_material(red)\n"
           "root:add_child(ball)\n"
           "local crate = gr.nh_box('crate', {0.5 * s, -1 * s, -0.5 * s}, s)\n"
           "crate:set_material(grey)\n"
           "root:add_child(crate)\n"
           "local egg = gr.sphere('egg')\n"
           "egg:scale(0.4 * s, 0.8 * s, 0.4 * s)\n"
           "egg:rotate('z', 30)\n"
           "egg:translate(2.2 * s, -0.2 * s, 0.8 * s)\n"
           "egg:set_material(red)\n"
           "root:add_child(egg)\n"
           "local tri = gr.mesh('tri', {{-3 * s, -1 * s, -2 * s}, {-1 * s, -1 * s, -3 * s},"
           " {-2 * s, 1 * s, -2.5 * s}}, {{0, 1, 2}})\n"
           "tri:set_material(grey)\n"
           "root:add_child(tri)\n"
           "local key = gr.light({-4 * s, 6 * s, 4 * s}, {0.9, 0.9, 0.9}, {1, 0, 0})\n"
           "local fill = gr.light({3 * s, 2 * s, 5 * s}, {0.4, 0.4, 0.4}, {1, 0, 0})\n"
           "gr.render(root, 'scaled.png', 64, 48, {0, 1 * s, 6 * s}, {0, -0.3, -1}, {0, 1, 0},"
           " 50, {0.1, 0.1, 0.1}, {key, fill})\n";
}

}  // namespace

// ---- Self-intersection ------------------------------------------------------------------------

SCENARIO(
    "shadow rays from a convex mesh are never blocked by the mesh itself, at scales from "
    "1e-3 to 1e4",
    "[stability][ch02][ex2.2]") {
    // A convex polyhedron (a latitude–longitude sphere of 16 × 32 quads), stretched, turned and
    // placed a few sizes from the origin, in a two-level BVH. A light anywhere in the outer
    // half-space of the face a point lies on cannot be hidden by a convex solid: the solid lies
    // wholly on the other side of that face's plane. So every shadow ray must get through,
    // including those that leave almost along the surface and those that start on an edge
    // shared by two triangles.
    const auto mesh = latLongSphere(16, 32);
    for (const double scale : rbtest::kSceneScales) {
        GIVEN("the mesh at size " + std::to_string(scale)) {
            std::vector<rb::Instance> instances = {
                rbtest::makeInstance(*mesh, rbtest::placeAtScale(scale, Vec3(1, 0.7, 1.3)))};
            const rb::BVHAggregate aggregate(instances);
            WHEN(
                "each of 1 000 random surface points casts shadow rays to 4 lights in its "
                "face's outer half-space (fixed seed)") {
                rbtest::Rng rng(99);
                const auto points = rbtest::sampleSurface(instances[0], rng, 1000);
                REQUIRE(points.size() == 1000);
                int blocked = 0;
                for (const rbtest::SurfacePoint& sp : points) {
                    const Vec3 outside = rb::faceForward(sp.hit.ng, -sp.probe.d);
                    for (int k = 0; k < 4; ++k) {
                        const Vec3 light =
                            sp.hit.p + scale * rng.uniform(0.1, 5.0) * rng.hemisphere(outside);
                        const Vec3 l = glm::normalize(light - sp.hit.p);
                        const Vec3 origin = rb::offsetRayOrigin(sp.hit.p, sp.hit.ng, l);
                        if (aggregate.occluded(rb::Ray{origin, light - origin}, 1.0)) ++blocked;
                    }
                }
                THEN("none is blocked") {
                    CAPTURE(scale);
                    CHECK(blocked == 0);
                }
            }
        }
    }
}

SCENARIO("a scene scaled from 1e-3 to 1e4 renders the same picture and shows no acne",
         "[stability][ch02][ex2.2][ex2.3]") {
    // With a constant falloff every colour depends only on angles, and raybook's ray offsets
    // scale with the scene, so scaling the whole scene must not change the picture. Shadow acne
    // would show up as speckled lit surfaces at some scales. Rounding may still flip a pixel
    // whose centre lies within ~1e-15 of a silhouette or a shadow edge; we allow 1 % of pixels
    // to differ by more than 1e-5 (well above float storage, 6e-8 relative).
    const auto reference = rbtest::worldFromLua(scaledScene(1.0));
    const rb::Image expected = renderWorld(*reference, 1);
    for (const double scale : {1e-3, 1e-1, 1e2, 1e4}) {
        GIVEN("the scene scaled by " + std::to_string(scale)) {
            const auto world = rbtest::worldFromLua(scaledScene(scale));
            const rb::Image image = renderWorld(*world, 1);
            THEN("every pixel is finite and non-negative, and at most 1 % differ from scale 1") {
                CHECK(rbtest::allFiniteNonNegative(image));
                int differ = 0;
                for (size_t i = 0; i < image.data().size(); i += 3) {
                    for (size_t c = 0; c < 3; ++c)
                        if (std::abs(image.data()[i + c] - expected.data()[i + c]) > 1e-5) {
                            ++differ;
                            break;
                        }
                }
                CAPTURE(scale, differ);
                CHECK(differ <= static_cast<int>(image.data().size() / 3 / 100));
            }
        }
    }
    GIVEN("the same scene at the far ends of double precision's comfort: 1e-8 and 1e12") {
        THEN("every pixel is still finite and non-negative") {
            for (const double scale : {1e-8, 1e12}) {
                CAPTURE(scale);
                const auto world = rbtest::worldFromLua(scaledScene(scale));
                CHECK(rbtest::allFiniteNonNegative(renderWorld(*world, 1)));
            }
        }
    }
}

// ---- Edges, vertices and degenerate triangles ---------------------------------------------

SCENARIO("rays through the edges and vertices of a closed mesh always hit it",
         "[stability][ch03][ex3.1][ex3.2]") {
    GIVEN("the octahedron |x| + |y| + |z| = 1 as an 8-triangle mesh") {
        const auto octahedron = rbtest::makeMesh({Vec3(1, 0, 0), Vec3(-1, 0, 0), Vec3(0, 1, 0),
                                                  Vec3(0, -1, 0), Vec3(0, 0, 1), Vec3(0, 0, -1)},
                                                 {{0, 2, 4},
                                                  {2, 1, 4},
                                                  {1, 3, 4},
                                                  {3, 0, 4},
                                                  {2, 0, 5},
                                                  {1, 2, 5},
                                                  {3, 1, 5},
                                                  {0, 3, 5}});
        // Points on the surface: the 6 vertices, and 63 dyadic points (k/64) along each of
        // the 12 edges: each is exact in binary, so a ray aimed there passes exactly through
        // an edge or a vertex.
        std::vector<Vec3> targets;
        const Vec3 corners[] = {Vec3(1, 0, 0),  Vec3(-1, 0, 0), Vec3(0, 1, 0),
                                Vec3(0, -1, 0), Vec3(0, 0, 1),  Vec3(0, 0, -1)};
        for (const Vec3& c : corners) targets.push_back(c);
        for (int a = 0; a < 6; ++a)
            for (int b = a + 1; b < 6; ++b) {
                if (glm::dot(corners[a], corners[b]) != 0.0) continue;  // opposite corners
                for (int k = 1; k < 64; ++k)
                    targets.push_back(corners[a] + (k / 64.0) * (corners[b] - corners[a]));
            }
        // The mesh the code built is the whole octahedron: all 8 triangles, bounded by the
        // cube [-1, 1]^3, so every target above lies on it.
        REQUIRE(octahedron->triangleCount() == 8);
        REQUIRE(octahedron->bounds().lo == Vec3(-1.0));
        REQUIRE(octahedron->bounds().hi == Vec3(1.0));
        WHEN(
            "a ray leaves the centre towards each point, and another comes in from 3 times "
            "as far out towards the centre") {
            int missedFromInside = 0, missedFromOutside = 0, wrongT = 0;
            for (const Vec3& target : targets) {
                rb::ObjectHit oh;
                if (!octahedron->intersect(rb::Ray{Vec3(0), target}, kInf, oh)) {
                    ++missedFromInside;
                } else if (std::abs(oh.t - 1.0) > 1e-15) {
                    // Source: the target is on the surface and d = target, so t = 1; the
                    // triangle test recovers it within an ulp or two.
                    ++wrongT;
                }
                if (!octahedron->intersect(rb::Ray{3.0 * target, -target}, kInf, oh))
                    ++missedFromOutside;
                else if (std::abs(oh.t - 2.0) > 1e-15)
                    ++wrongT;
            }
            THEN("every ray hits, at the point it was aimed at") {
                CHECK(missedFromInside == 0);
                CHECK(missedFromOutside == 0);
                CHECK(wrongT == 0);
            }
        }
    }
    GIVEN("a closed latitude–longitude sphere of 1 024 triangles") {
        const auto mesh = latLongSphere(16, 32);
        WHEN("rays leave its centre towards every vertex, and in 20 000 random directions") {
            rbtest::Rng rng(12);
            int missed = 0;
            // Vertex directions pass exactly through the vertex where 4 to 32 triangles meet.
            for (const Vec3 d : {Vec3(0, 1, 0), Vec3(0, -1, 0)}) {
                rb::ObjectHit oh;
                if (!mesh->intersect(rb::Ray{Vec3(0), d}, kInf, oh)) ++missed;
            }
            for (const rb::Mesh::Triangle& tri : mesh->triangles())
                for (const Vec3& v : tri.v) {
                    rb::ObjectHit oh;
                    if (!mesh->intersect(rb::Ray{Vec3(0), v}, kInf, oh)) ++missed;
                }
            for (int k = 0; k < 20000; ++k) {
                rb::ObjectHit oh;
                if (!mesh->intersect(rb::Ray{Vec3(0), rng.unitVector()}, kInf, oh)) ++missed;
            }
            THEN("no ray escapes the closed surface") {
                CHECK(missed == 0);
            }
        }
    }
}

SCENARIO("degenerate triangles neither crash, nor produce NaN, nor get hit",
         "[stability][ch03][ex3.1]") {
    GIVEN(
        "a legacy table mesh with a good triangle, a repeated index and three collinear "
        "corners") {
        const auto world = rbtest::worldFromLua(
            "local root = gr.node('root')\n"
            "local m = gr.mesh('m', {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 0, 0}, {0.5, 0.5, 0}},"
            " {{0, 1, 2}, {0, 0, 1}, {0, 1, 3}, {1, 4, 2}})\n"
            "root:add_child(m)\n" +
            rbtest::renderLine());
        THEN("the mesh keeps the one good triangle and rays hit only that") {
            const auto* mesh = dynamic_cast<const rb::Mesh*>(world->scene.instances.at(0).shape);
            REQUIRE(mesh != nullptr);
            CHECK(mesh->triangleCount() == 1);
            CHECK(mesh->droppedCount() == 3);
            rb::Hit hit;
            // Through the middle of the collinear triangle (1,0,0)–(0.5,0.5,0)–(0,1,0), which
            // lies on the good triangle's hypotenuse: it hits the good one, at its edge.
            CHECK(world->scene.aggregate->intersect(rb::Ray{Vec3(0.5, 0.5, 1), Vec3(0, 0, -1)},
                                                    kInf, hit));
            CHECK(hit.t == 1.0);
            CHECK(rb::isFinite(hit.ng));
            // Through the degenerate (0,0,0)–(1,0,0)–(2,0,0) beyond the good triangle: nothing.
            CHECK_FALSE(world->scene.aggregate->intersect(rb::Ray{Vec3(1.5, 0, 1), Vec3(0, 0, -1)},
                                                          kInf, hit));
        }
    }
    GIVEN("a legacy table mesh whose only triangle is degenerate, on line 2") {
        const std::string message = loadError(
            "local root = gr.node('root')\n"
            "local m = gr.mesh('m', {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}}, {{0, 1, 2}})\n"
            "root:add_child(m)\n" +
                rbtest::renderLine(),
            "degenerate.lua");
        THEN("loading fails with an error at degenerate.lua:2") {
            CHECK_THAT(message, Contains("degenerate.lua:2:"));
        }
    }
}

// ---- Grazing and degenerate rays --------------------------------------------------------------

SCENARIO("grazing rays on spheres give no NaN, and hit or miss as the geometry says",
         "[stability][ch01][ex1.1]") {
    // Rays parallel to a tangent of the sphere, at distance b = R·(1 + δ) from the centre, from
    // 10 R away, at every scene scale. The ray's own position is only known to about
    // 1e-16·|origin| ≈ 1e-14·R, so for |δ| ≤ 1e-12 either answer is right; beyond that the
    // answer is fixed: δ ≥ 1e-9 misses and δ ≤ −1e-6 hits.
    const rb::Sphere sphere;
    const double deltas[] = {-1e-6, -1e-9, -1e-12, -1e-15, 0.0, 1e-15, 1e-12, 1e-9, 1e-6};
    for (const double scale : rbtest::kSceneScales) {
        GIVEN("a sphere of radius " + std::to_string(scale) +
              ", and 200 random tangent "
              "directions for each δ (fixed seed)") {
            const rb::Instance instance = rbtest::makeInstance(sphere, rbtest::placeAtScale(scale));
            const Vec3 centre = rb::transformPoint(instance.objectToWorld, Vec3(0));
            rbtest::Rng rng(3);
            int nonFinite = 0, wrongAnswer = 0, offSurface = 0;
            for (int k = 0; k < 200; ++k) {
                const Vec3 u = rng.unitVector();
                const Vec3 w = glm::normalize(glm::cross(u, rng.unitVector()));
                for (const double delta : deltas) {
                    const double b = scale * (1.0 + delta);
                    const rb::Ray ray{centre + b * w + 10.0 * scale * u, -u};
                    rb::ObjectHit oh;
                    const bool found = instance.intersect(ray, kInf, oh);
                    if (delta >= 1e-9 && found) ++wrongAnswer;
                    if (delta <= -1e-6 && !found) ++wrongAnswer;
                    if (!found) continue;
                    const rb::Hit hit = instance.toWorld(ray, oh);
                    if (!std::isfinite(hit.t) || !rb::isFinite(hit.p) || !rb::isFinite(hit.ng) ||
                        std::abs(glm::length(hit.ng) - 1.0) > 1e-12)
                        ++nonFinite;
                    // The hit point is on the sphere to within the ray's own uncertainty
                    // (~1e-14·R) and the rounding of the hit test; allow 1e-9·R.
                    else if (std::abs(glm::length(hit.p - centre) - scale) > 1e-9 * scale)
                        ++offSurface;
                }
            }
            THEN("all hits are finite and on the surface; clear hits and misses are right") {
                CHECK(nonFinite == 0);
                CHECK(wrongAnswer == 0);
                CHECK(offSurface == 0);
            }
        }
    }
    GIVEN("a Phong-shaded sphere lit from the side, seen along grazing rays") {
        const auto world = rbtest::worldFromLua(
            "local m = gr.material({0.7, 0.7, 0.7}, {0.5, 0.5, 0.5}, 100)\n"
            "local root = gr.node('root')\n"
            "local s = gr.nh_sphere('s', {0, 0, 0}, 1)\n"
            "s:set_material(m)\n"
            "root:add_child(s)\n"
            "gr.render(root, 'x.png', 8, 8, {0, 0, 10}, {0, 0, -1}, {0, 1, 0}, 50,"
            " {0.1, 0.1, 0.1}, {gr.light({10, 0, 0}, {1, 1, 1}, {1, 0, 0})})\n");
        THEN("every colour is finite and non-negative") {
            int bad = 0;
            // Rays down −z at heights y = 1 ∓ 2^−k approach the silhouette from both sides.
            for (int k = 1; k <= 60; ++k)
                for (const double y : {1.0 - std::ldexp(1.0, -k), 1.0 + std::ldexp(1.0, -k)}) {
                    const rb::Colour c =
                        rbtest::traceOne(*world, rb::Ray{Vec3(0, y, 10), Vec3(0, 0, -1)});
                    if (!rb::isFinite(c) || c.r < 0 || c.g < 0 || c.b < 0) ++bad;
                }
            CHECK(bad == 0);
        }
    }
}

SCENARIO("a degenerate ray (zero or NaN direction) never reports a hit",
         "[stability][ch01][ex1.3]") {
    // Such a ray has no direction to travel in, so no t describes a hit; a shape that answers
    // "hit" hands NaN to everything downstream (hit point, normal, shading).
    const rb::Sphere sphere;
    const rb::Box box;
    const auto triangle =
        rbtest::makeMesh({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}, {{0, 1, 2}});
    const double nan = std::numeric_limits<double>::quiet_NaN();
    GIVEN(
        "rays with direction (0, 0, 0) or (NaN, 0, 1), starting inside, on or outside each "
        "shape") {
        THEN("the sphere, the cube and the mesh report no hit") {
            for (const Vec3& d : {Vec3(0.0), Vec3(nan, 0, 1)})
                for (const Vec3& o :
                     {Vec3(0.5, 0.5, 0), Vec3(1, 0, 0), Vec3(0, 0, 0), Vec3(3, 0, 0)}) {
                    CAPTURE(d.x, o.x, o.y);
                    rb::ObjectHit oh;
                    CHECK_FALSE(sphere.intersect(rb::Ray{o, d}, kInf, oh));
                    CHECK_FALSE(box.intersect(rb::Ray{o, d}, kInf, oh));
                    CHECK_FALSE(triangle->intersect(rb::Ray{o, d}, kInf, oh));
                    CHECK_FALSE(triangle->occluded(rb::Ray{o, d}, kInf));
                }
        }
    }
}

SCENARIO("rays with zero direction components pass through boxes and BVH nodes correctly",
         "[stability][ch03][ex3.1][ex3.2]") {
    GIVEN(
        "a flat 8 × 8 grid of 128 triangles over the unit square (z = 0), whose BVH nodes "
        "have zero thickness in z and share their x and y faces") {
        std::vector<Vec3> positions;
        std::vector<std::array<int, 3>> triangles;
        for (int j = 0; j <= 8; ++j)
            for (int i = 0; i <= 8; ++i) positions.emplace_back(i / 8.0, j / 8.0, 0.0);
        for (int j = 0; j < 8; ++j)
            for (int i = 0; i < 8; ++i) {
                const int a = j * 9 + i;
                triangles.push_back({a, a + 1, a + 10});
                triangles.push_back({a, a + 10, a + 9});
            }
        const auto grid = rbtest::makeMesh(positions, triangles, "grid");
        WHEN(
            "rays straight down (d = (0, 0, −1)) pass through all 33 × 33 points (i/32, j/32, "
            "0): every vertex, edge and boundary of the grid") {
            int missed = 0, wrongT = 0;
            for (int j = 0; j <= 32; ++j)
                for (int i = 0; i <= 32; ++i) {
                    rb::ObjectHit oh;
                    if (!grid->intersect(rb::Ray{Vec3(i / 32.0, j / 32.0, 1), Vec3(0, 0, -1)}, kInf,
                                         oh))
                        ++missed;
                    else if (oh.t != 1.0)
                        ++wrongT;
                }
            THEN("each hits the closed grid at t = 1 exactly, as the triangle test alone does") {
                // Source: every such point lies in some triangle (edges and borders included:
                // the watertight test counts them), and the drop is exactly 1.
                CHECK(missed == 0);
                CHECK(wrongT == 0);
            }
        }
    }
    GIVEN("a unit cube instance, in a BVH and in a plain list") {
        const rb::Box box;
        const std::vector<rb::Instance> instances = {rbtest::makeInstance(box, rb::Mat4(1.0))};
        const rb::BVHAggregate bvh(instances);
        const rb::LinearAggregate linear(instances);
        THEN("rays down the planes of its four side faces and along its edges hit it in both") {
            for (const Vec3 o : {Vec3(0, 0.5, 2), Vec3(1, 0.5, 2), Vec3(0.5, 0, 2), Vec3(0.5, 1, 2),
                                 Vec3(1, 1, 2), Vec3(0, 0, 2)}) {
                CAPTURE(o.x, o.y);
                rb::Hit a, b;
                CHECK(linear.intersect(rb::Ray{o, Vec3(0, 0, -1)}, kInf, a));
                CHECK(bvh.intersect(rb::Ray{o, Vec3(0, 0, -1)}, kInf, b));
                CHECK(bvh.occluded(rb::Ray{o, Vec3(0, 0, -1)}, kInf));
            }
        }
    }
}

SCENARIO("a BVH over objects at exponentially growing distances fits its traversal stack",
         "[stability][ch03][ex3.2]") {
    // Binned SAH splits off the farthest object or two at each level when objects sit at
    // 1, 2, 4, 8, ... (the bins spread over the whole range, and all but the last are nearly
    // empty), so without a limit the tree's depth grows with the number of objects. The
    // traversal keeps a fixed stack of BVH::kStackSize node indices and pushes at most one per
    // level it descends, so a deeper tree would overflow it.
    GIVEN("300 spheres of radius 0.5 at x = 2^k, k = 0 … 299 (the farthest at about 1e90)") {
        const rb::Sphere sphere;
        std::vector<rb::Instance> instances;
        for (int k = 0; k < 300; ++k)
            instances.push_back(rbtest::makeInstance(
                sphere, glm::scale(glm::translate(rb::Mat4(1.0), Vec3(std::ldexp(1.0, k), 0, 0)),
                                   Vec3(0.5))));
        const rb::BVHAggregate bvh(instances);
        const rb::LinearAggregate linear(instances);
        THEN(
            "the tree is no deeper than the stack, and rays along the row and at single "
            "spheres find what brute force finds") {
            // Guard: traversing a deeper tree would write past the stack.
            REQUIRE(bvh.bvh().depth() <= rb::BVH::kStackSize);
            rb::Hit hit;
            REQUIRE(bvh.intersect(rb::Ray{Vec3(-1, 0, 0), Vec3(1, 0, 0)}, kInf, hit));
            CHECK(hit.t == Approx(1.5));  // Source: the sphere at x = 1 starts at x = 0.5
            // A ray straight down onto sphere k hits its top, at t = 10 − 0.5, whatever k is.
            int mismatched = 0;
            for (int k = 0; k < 300; k += 7) {
                const rb::Ray down{Vec3(std::ldexp(1.0, k), 10, 0), Vec3(0, -1, 0)};
                rb::Hit a, b;
                if (!linear.intersect(down, kInf, a) || !bvh.intersect(down, kInf, b) ||
                    a.instance != b.instance || a.t != b.t)
                    ++mismatched;
            }
            CHECK(mismatched == 0);
        }
    }
}

// ---- Bad numbers and fighting surfaces --------------------------------------------------------

SCENARIO("NaN and Inf from a scene file are rejected with the file and the line",
         "[stability][ch02]") {
    // Each bad call sits on line 2 of nan_inf.lua; line 1 makes a node n.
    const char* calls[] = {
        "gr.nh_sphere('s', {0/0, 0, 0}, 1)",
        "gr.nh_sphere('s', {0, 0, 0}, 1/0)",
        "gr.nh_box('b', {0, -1/0, 0}, 1)",
        "gr.nh_box('b', {0, 0, 0}, 0/0)",
        "n:translate(0, 0/0, 0)",
        "n:scale(math.huge, 1, 1)",
        "n:rotate('x', 0/0)",
        "gr.material({0/0, 0, 0}, {0, 0, 0}, 10)",
        "gr.material({1, 1, 1}, {0, 0, 0}, math.huge)",
        "gr.material{kd = {0.5, 0/0, 0.5}}",
        "gr.light({0, 1/0, 0}, {1, 1, 1}, {1, 0, 0})",
        "gr.light({0, 0, 0}, {1, -1/0, 1}, {1, 0, 0})",
        "gr.light({0, 0, 0}, {1, 1, 1}, {1, 0/0, 0})",
        "gr.joint('j', {0/0, 0, 1}, {0, 0, 1})",
        "gr.mesh('m', {{0, 0, 0}, {1, 0/0, 0}, {0, 1, 0}}, {{0, 1, 2}})",
        "gr.render(n, 'x.png', 8, 8, {0/0, 0, 10}, {0, 0, -1}, {0, 1, 0}, 50, {0, 0, 0},"
        " {gr.light({0, 0, 10}, {1, 1, 1}, {1, 0, 0})})",
        "gr.render(n, 'x.png', 8, 8, {0, 0, 10}, {0, 0, -1/0}, {0, 1, 0}, 50, {0, 0, 0},"
        " {gr.light({0, 0, 10}, {1, 1, 1}, {1, 0, 0})})",
        "gr.render(n, 'x.png', 8, 8, {0, 0, 10}, {0, 0, -1}, {0, 1, 0}, 0/0, {0, 0, 0},"
        " {gr.light({0, 0, 10}, {1, 1, 1}, {1, 0, 0})})",
        "gr.render(n, 'x.png', 8, 8, {0, 0, 10}, {0, 0, -1}, {0, 1, 0}, 50, {0, math.huge, 0},"
        " {gr.light({0, 0, 10}, {1, 1, 1}, {1, 0, 0})})",
    };
    GIVEN("nineteen scenes, each with one NaN or Inf on line 2") {
        THEN("each load throws an InputError at nan_inf.lua:2 that says nan or inf") {
            for (const char* call : calls) {
                CAPTURE(call);
                const std::string message = loadError(
                    std::string("local n = gr.node('n')\n") + call + "\n" + rbtest::renderLine("n"),
                    "nan_inf.lua");
                CAPTURE(message);
                CHECK_THAT(message, Contains("nan_inf.lua:2:"));
                CHECK((message.find("nan") != std::string::npos ||
                       message.find("inf") != std::string::npos ||
                       message.find("finite") != std::string::npos));
            }
        }
    }
}

SCENARIO("coincident surfaces never render NaN, Inf or negative pixels",
         "[stability][ch02][ex2.2][ex2.3]") {
    GIVEN(
        "two spheres in the same place with different materials, a crate whose bottom is the "
        "floor's top, a second floor in the same place, a triangle lying in the floor's top, "
        "a box face touching a sphere, a light on the floor, one inside a sphere and one at "
        "the eye") {
        const std::string scene =
            "local red = gr.material({0.8, 0.1, 0.1}, {0.5, 0.5, 0.5}, 20)\n"
            "local blue = gr.material({0.1, 0.1, 0.8}, {0.9, 0.9, 0.9}, 1000)\n"
            "local root = gr.node('root')\n"
            "local a = gr.nh_sphere('a', {0, 0, 0}, 1)\n"
            "a:set_material(red)\n"
            "root:add_child(a)\n"
            "local b = gr.nh_sphere('b', {0, 0, 0}, 1)\n"
            "b:set_material(blue)\n"
            "root:add_child(b)\n"
            "for i = 1, 2 do\n"
            "  local floor = gr.cube('floor' .. i)\n"
            "  floor:scale(10, 1, 10)\n"
            "  floor:translate(-5, -2, -5)\n"
            "  floor:set_material(i == 1 and red or blue)\n"
            "  root:add_child(floor)\n"
            "end\n"
            "local crate = gr.nh_box('crate', {1, -1, -1}, 1)\n"
            "crate:set_material(blue)\n"
            "root:add_child(crate)\n"
            "local tri = gr.mesh('tri', {{-4, -1, -4}, {4, -1, -4}, {0, -1, 4}}, {{0, 1, 2}})\n"
            "tri:set_material(red)\n"
            "root:add_child(tri)\n"
            "local onFloor = gr.light({-2, -1, 2}, {1, 1, 1}, {0, 0, 1})\n"
            "local inside = gr.light({0, 0, 0}, {1, 1, 1}, {1, 0, 0})\n"
            "local atEye = gr.light({0, 1, 6}, {0.5, 0.5, 0.5}, {1, 0, 0})\n"
            "local key = gr.light({-4, 6, 4}, {0.8, 0.8, 0.8}, {1, 0, 0})\n"
            "gr.render(root, 'outside.png', 48, 36, {0, 1, 6}, {0, -0.3, -1}, {0, 1, 0}, 50,"
            " {0.1, 0.1, 0.1}, {onFloor, inside, atEye, key})\n"
            "gr.render(root, 'inside.png', 48, 36, {0, 0, 0.5}, {0, -0.3, -1}, {0, 1, 0}, 90,"
            " {0.1, 0.1, 0.1}, {onFloor, inside, atEye, key})\n";
        THEN(
            "the views from outside and from inside the spheres, with 1 and 4 samples per "
            "pixel, are finite and non-negative everywhere") {
            for (size_t view = 0; view < 2; ++view) {
                for (const int spp : {1, 4}) {
                    CAPTURE(view, spp);
                    const auto world = rb::buildWorld(
                        std::move(rbtest::loadSceneText(scene).at(view)), rbtest::coreFeatures());
                    const rb::Image image = renderWorld(*world, spp);
                    CHECK(rbtest::allFiniteNonNegative(image));
                }
            }
        }
    }
}
