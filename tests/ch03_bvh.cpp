/// \file
/// Chapter 3 tests: watertight ray–triangle intersection and the two-level BVH.
///
/// Chapter 3 claims that the watertight triangle test leaves no gap between triangles that
/// share an edge or a vertex, reports barycentric coordinates that rebuild the hit point, sees
/// both sides of a triangle and never hits a degenerate one; that a BVH is only a faster way of
/// getting the answer brute force gives (the same closest hit, the same triangle or instance,
/// the same shadow-ray verdict); that the tree is well formed; and that the work per ray grows
/// like log n rather than n. The tests sweep rays exactly through shared edges and vertices,
/// compare the BVH with a loop over every triangle (Stanford bunny) and over every instance
/// (a scene of spheres, boxes and meshes) on thousands of random rays with fixed seeds, in every
/// layout this processor runs (binary, four-wide SSE, eight-wide AVX2), walk every tree to check
/// its invariants, and count the triangle tests and the BVH nodes pierced by rays hitting meshes
/// of 2 048 to 524 288 triangles.
#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "bvh/bvh.h"
#include "bvh/bvh_aggregate.h"
#include "bvh/mesh.h"
#include "bvh/obj.h"
#include "bvh/triangle.h"
#include "bvh/triangle4.h"
#include "bvh/wide_bvh.h"
#include "bvh/wide_bvh8.h"
#include "core/aggregate.h"
#include "core/box.h"
#include "core/error.h"
#include "core/sphere.h"
#include "scene/lua_scene.h"
#include "test_helpers.h"

using rb::Vec3;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kPi = 3.14159265358979323846;

/// The bunny that chapter 3's scene uses: 3 674 triangles.
const std::string kBunnyPath = rbtest::sourceDir() + "/scenes/assets/bunny.obj";

/// A BVH layout and its --bvh name.
struct NamedLayout {
    rb::BVHLayout layout;
    const char* name;
};

/// Every layout one binary can take on this machine: binary, wide4, and wide8 where the CPU has
/// AVX2 (a warning says when it has not, and the eight-wide path goes untested).
std::vector<NamedLayout> layoutsHere() {
    std::vector<NamedLayout> layouts = {{rb::BVHLayout::Binary, "binary"},
                                        {rb::BVHLayout::Wide4, "wide4"}};
    if (rb::wide8Available())
        layouts.push_back({rb::BVHLayout::Wide8, "wide8"});
    else
        WARN("this CPU has no AVX2: the eight-wide BVH is not tested here");
    return layouts;
}

/// The wide layouts of layoutsHere().
std::vector<NamedLayout> wideLayoutsHere() {
    std::vector<NamedLayout> layouts = layoutsHere();
    layouts.erase(layouts.begin());
    return layouts;
}

/// Does the ray hit triangle (p0, p1, p2) anywhere along t in (0, ∞)?
bool hitsTriangle(const rb::Ray& ray, const Vec3& p0, const Vec3& p1, const Vec3& p2) {
    rb::TriangleHit th;
    return rb::intersectTriangle(rb::WatertightRay(ray), p0, p1, p2, kInf, th);
}

/// The closest hit of a ray on a mesh's triangles by testing every one, in double precision:
/// the reference the BVH must reproduce. Among triangles hit at exactly the same distance the
/// lowest OBJ index wins, the mesh's rule. Returns that OBJ index, or -1.
long bruteForceClosest(const std::vector<rb::Mesh::Triangle>& triangles, const rb::Ray& ray,
                       double& tClosest, double tMax = kInf) {
    const rb::WatertightRay wray(ray);
    long best = -1;
    tClosest = tMax;
    for (const rb::Mesh::Triangle& tri : triangles) {
        rb::TriangleHit th;
        const double limit = best >= 0 ? std::nextafter(tClosest, kInf) : tClosest;
        if (!rb::intersectTriangle(wray, tri.v[0], tri.v[1], tri.v[2], limit, th)) continue;
        if (th.t == tClosest && static_cast<long>(tri.source) >= best) continue;
        tClosest = th.t;
        best = tri.source;
    }
    return best;
}

/// A BVH of the given layout over the triangles' boxes; its slots index `triangles` through
/// primitiveOrder().
rb::BVH bvhOver(const std::vector<rb::Mesh::Triangle>& triangles, rb::BVHLayout layout) {
    std::vector<rb::AABB> boxes;
    for (const rb::Mesh::Triangle& tri : triangles) {
        rb::AABB b;
        for (const Vec3& p : tri.v) b.extend(p);
        boxes.push_back(b);
    }
    rb::BVH bvh;
    rb::BVHBuildOptions options;
    options.layout = layout;
    bvh.build(boxes, options);
    return bvh;
}

/// A random ray aimed into a box: from a random point on a sphere twice the box's diagonal
/// around it, towards a random point inside it (most such rays hit what is inside, some miss).
rb::Ray rayInto(const rb::AABB& b, rbtest::Rng& rng) {
    const Vec3 centre = b.centre();
    const double radius = glm::length(b.hi - b.lo);
    const Vec3 origin = centre + 2.0 * radius * rng.unitVector();
    const Vec3 target(rng.uniform(b.lo.x, b.hi.x), rng.uniform(b.lo.y, b.hi.y),
                      rng.uniform(b.lo.z, b.hi.z));
    return rb::Ray{origin, target - origin};
}

/// True when box `outer` contains box `inner`.
bool contains(const rb::AABB& outer, const rb::AABB& inner) {
    return outer.lo.x <= inner.lo.x && outer.lo.y <= inner.lo.y && outer.lo.z <= inner.lo.z &&
           outer.hi.x >= inner.hi.x && outer.hi.y >= inner.hi.y && outer.hi.z >= inner.hi.z;
}

/// What a walk over a BVH found wrong with it.
struct TreeReport {
    size_t nodesReached = 0;
    size_t badChildBounds = 0;  ///< Interior nodes whose box misses part of a child's box.
    size_t badLeafBounds = 0;   ///< Leaves whose box misses part of a primitive's box.
    std::vector<int> slotSeen;  ///< How many leaves refer to each primitive slot.
};

/// Walk every node reachable from the root; primitiveBounds(slot) is the box of the primitive
/// in leaf slot `slot`.
template <class SlotBounds>
TreeReport walkTree(const rb::BVH& bvh, size_t primitiveCount, SlotBounds primitiveBounds) {
    TreeReport report;
    report.slotSeen.assign(primitiveCount, 0);
    std::vector<std::uint32_t> stack = {0};
    while (!stack.empty()) {
        const std::uint32_t index = stack.back();
        stack.pop_back();
        const rb::BVHNode& node = bvh.nodes().at(index);
        ++report.nodesReached;
        if (node.count > 0) {
            for (std::uint32_t slot = node.offset; slot < node.offset + node.count; ++slot) {
                ++report.slotSeen.at(slot);
                if (!contains(node.bounds, primitiveBounds(slot))) ++report.badLeafBounds;
            }
        } else {
            // The first child follows its parent; the second is at `offset`.
            for (const std::uint32_t child : {index + 1, node.offset}) {
                if (!contains(node.bounds, bvh.nodes().at(child).bounds)) ++report.badChildBounds;
                stack.push_back(child);
            }
        }
    }
    return report;
}

/// Walk the nodes of a wide BVH (four- or eight-wide) from the root: every child's float box
/// must contain the double boxes of everything below it (they were rounded outwards), and every
/// slot must be in one leaf.
template <int N, class SlotBounds>
TreeReport walkWideNodes(const std::vector<rb::WideNodeN<N>>& nodes, size_t primitiveCount,
                         SlotBounds primitiveBounds) {
    TreeReport report;
    report.slotSeen.assign(primitiveCount, 0);
    // Returns the bounds of the subtree under node `index`.
    auto walk = [&](auto&& self, std::uint32_t index) -> rb::AABB {
        const rb::WideNodeN<N>& node = nodes.at(index);
        ++report.nodesReached;
        rb::AABB all;
        for (int c = 0; c < N; ++c) {
            rb::AABB childBox;
            for (int axis = 0; axis < 3; ++axis) {
                childBox.lo[axis] = node.lo[axis][c];
                childBox.hi[axis] = node.hi[axis][c];
            }
            if (childBox.empty()) continue;  // an unused child
            rb::AABB inside;
            if (node.count[c] > 0) {
                for (std::uint32_t slot = node.child[c]; slot < node.child[c] + node.count[c];
                     ++slot) {
                    ++report.slotSeen.at(slot);
                    if (!contains(childBox, primitiveBounds(slot))) ++report.badLeafBounds;
                    inside.extend(primitiveBounds(slot));
                }
            } else {
                inside = self(self, node.child[c]);
                if (!contains(childBox, inside)) ++report.badChildBounds;
            }
            all.extend(inside);
        }
        return all;
    };
    walk(walk, 0);
    return report;
}

/// walkWideNodes over the wide nodes of bvh, whichever width it was built with.
template <class SlotBounds>
TreeReport walkWide(const rb::BVH& bvh, size_t primitiveCount, SlotBounds primitiveBounds) {
    if (bvh.layout() == rb::BVHLayout::Wide8)
        return walkWideNodes(bvh.wide8Nodes(), primitiveCount, primitiveBounds);
    return walkWideNodes(bvh.wideNodes(), primitiveCount, primitiveBounds);
}

/// The nodes of bvh's wide layout.
size_t wideNodeCount(const rb::BVH& bvh) {
    return bvh.wideNodes().size() + bvh.wide8Nodes().size();
}

/// The number of BVH nodes whose box the segment of `ray` up to `tHit` enters: the nodes that
/// any closest-hit traversal has to open, whatever order it visits children in.
long nodesPierced(const rb::BVH& bvh, const rb::RayInverse& ri, double tHit,
                  std::uint32_t index = 0) {
    const rb::BVHNode& node = bvh.nodes()[index];
    double tEntry;
    if (!rb::intersectBox(node.bounds, ri, tHit, tEntry)) return 0;
    if (node.count > 0) return 1;
    return 1 + nodesPierced(bvh, ri, tHit, index + 1) + nodesPierced(bvh, ri, tHit, node.offset);
}

/// A wavy height field z = 0.05·sin(6πx)·cos(4πy) over the unit square, cut into k × k quads
/// of two triangles each: a surface, like the meshes people render.
std::shared_ptr<rb::Mesh> heightField(int k) {
    std::vector<Vec3> positions;
    std::vector<std::array<int, 3>> triangles;
    for (int j = 0; j <= k; ++j)
        for (int i = 0; i <= k; ++i) {
            const double x = static_cast<double>(i) / k, y = static_cast<double>(j) / k;
            positions.emplace_back(x, y, 0.05 * std::sin(6 * kPi * x) * std::cos(4 * kPi * y));
        }
    for (int j = 0; j < k; ++j)
        for (int i = 0; i < k; ++i) {
            const int a = j * (k + 1) + i, b = a + 1, c = a + k + 1, d = c + 1;
            triangles.push_back({a, b, d});
            triangles.push_back({a, d, c});
        }
    return rbtest::makeMesh(positions, triangles, "height-field");
}

}  // namespace

// ---- Ray–triangle -----------------------------------------------------------------------------

// [ch03-watertight]
SCENARIO("a ray through the shared edge or vertex of two triangles hits at least one of them",
         "[ch03][ex3.1]") {
    GIVEN("the unit square split along its diagonal into (p0, p1, p2) and (p0, p2, p3)") {
        const Vec3 p0(0, 0, 0), p1(1, 0, 0), p2(1, 1, 0), p3(0, 1, 0);
        // Directions with small integer components: with a dyadic point s on the diagonal, the
        // origin (s, s, 0) − d is exact, so each ray passes exactly through the shared edge.
        const Vec3 directions[] = {Vec3(0, 0, -1),  Vec3(1, 2, -3),  Vec3(-3, 1, -2),
                                   Vec3(2, -5, 1),  Vec3(-1, -1, 4), Vec3(7, 3, -1),
                                   Vec3(1, -1, -1), Vec3(-2, 2, 1)};
        WHEN("1023 points (i/1024, i/1024, 0) on the diagonal are shot at from 8 directions") {
            int missedBoth = 0;
            for (int i = 1; i < 1024; ++i) {
                const Vec3 onEdge(i / 1024.0, i / 1024.0, 0.0);
                for (const Vec3& d : directions) {
                    const rb::Ray ray{onEdge - d, d};
                    if (!hitsTriangle(ray, p0, p1, p2) && !hitsTriangle(ray, p0, p2, p3))
                        ++missedBoth;
                }
            }
            THEN("no ray slips between the two triangles") {
                CHECK(missedBoth == 0);
            }
        }
        WHEN(
            "the square is turned and moved to a general position, and 20 000 random rays are "
            "aimed at random points of the shared edge (fixed seed)") {
            rbtest::Rng rng(31);
            int missedBoth = 0;
            for (int k = 0; k < 20000; ++k) {
                const rb::Mat4 m =
                    glm::rotate(glm::translate(rb::Mat4(1.0), 10.0 * rng.unitVector()),
                                rng.uniform(0.0, 6.28), rng.unitVector());
                const Vec3 q0 = rb::transformPoint(m, p0), q1 = rb::transformPoint(m, p1),
                           q2 = rb::transformPoint(m, p2), q3 = rb::transformPoint(m, p3);
                const double s = rng.uniform();
                const Vec3 onEdge = (1.0 - s) * q0 + s * q2;
                const Vec3 origin = onEdge + 3.0 * rng.unitVector();
                const rb::Ray ray{origin, onEdge - origin};
                if (!hitsTriangle(ray, q0, q1, q2) && !hitsTriangle(ray, q0, q2, q3)) ++missedBoth;
            }
            THEN("every one hits at least one triangle") {
                CHECK(missedBoth == 0);
            }
        }
    }
    GIVEN("a fan of 6 triangles around the apex (0, 0, 0.3) of a hexagonal pyramid") {
        const Vec3 apex(0, 0, 0.3);
        std::vector<Vec3> rim;
        for (int i = 0; i < 6; ++i)
            rim.emplace_back(std::cos(i * kPi / 3), std::sin(i * kPi / 3), 0.0);
        const auto hitsFan = [&](const rb::Ray& ray) {
            for (int i = 0; i < 6; ++i)
                if (hitsTriangle(ray, apex, rim[i], rim[(i + 1) % 6])) return true;
            return false;
        };
        // Each ray descends at least 30° below the horizontal, steeper than every face
        // (atan(0.3 / cos 30°) ≈ 19.1°), so a ray through the apex or a spoke enters the solid
        // there instead of just touching it: it must hit, whatever rounding does.
        const auto steepDirection = [](rbtest::Rng& rng) {
            for (;;) {
                const Vec3 d = rng.hemisphere(Vec3(0, 0, 1));
                if (d.z >= 0.5) return d;
            }
        };
        WHEN(
            "10 000 rays from random points above are aimed at the apex, and 10 000 at random "
            "points of the six spokes (fixed seed)") {
            rbtest::Rng rng(47);
            int missedApex = 0, missedSpoke = 0;
            for (int k = 0; k < 10000; ++k) {
                const Vec3 origin = apex + 2.0 * steepDirection(rng);
                if (!hitsFan(rb::Ray{origin, apex - origin})) ++missedApex;
                const int spoke = static_cast<int>(rng.uniform() * 6);
                const double s = rng.uniform();
                const Vec3 onSpoke = (1.0 - s) * apex + s * rim[spoke];
                const Vec3 from = onSpoke + 2.0 * steepDirection(rng);
                if (!hitsFan(rb::Ray{from, onSpoke - from})) ++missedSpoke;
            }
            THEN("none of them misses the fan") {
                CHECK(missedApex == 0);
                CHECK(missedSpoke == 0);
            }
        }
    }
}
// [ch03-watertight]

SCENARIO("the barycentric coordinates of a hit rebuild the hit point", "[ch03][ex3.1]") {
    GIVEN("the triangle (0,0,0), (1,0,0), (0,1,0) and a ray down from (0.25, 0.5, 1)") {
        rb::TriangleHit th;
        REQUIRE(
            rb::intersectTriangle(rb::WatertightRay(rb::Ray{Vec3(0.25, 0.5, 1), Vec3(0, 0, -1)}),
                                  Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), kInf, th));
        THEN("t = 1 and (b0, b1, b2) = (0.25, 0.25, 0.5)") {
            // Source: hand derivation: (0.25, 0.5) = b1·(1,0) + b2·(0,1), b0 = 1 − b1 − b2.
            CHECK(th.t == Approx(1.0).epsilon(1e-15));
            CHECK(th.b0 == Approx(0.25).epsilon(1e-15));
            CHECK(th.b1 == Approx(0.25).epsilon(1e-15));
            CHECK(th.b2 == Approx(0.5).epsilon(1e-15));
        }
    }
    GIVEN(
        "10 000 random triangles in [−1, 1]³, each shot at a random interior point "
        "w·p0 + u·p1 + v·p2 from 3 units away, with d = target − origin (fixed seed)") {
        // Rays within 6° of the triangle's plane and slivers of area < 0.1 are skipped: there
        // the problem itself is ill-conditioned. For the rest the edge functions lose at most a
        // factor ~100 over double rounding (|p| ≤ 1, area ≥ 0.1, |cos| ≥ 0.1), so errors stay
        // below ~1e-13; we allow 1e-12.
        rbtest::Rng rng(5);
        int tested = 0, missed = 0;
        double worstT = 0, worstB = 0, worstPoint = 0;
        while (tested < 10000) {
            const auto corner = [&] {
                return Vec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
            };
            const Vec3 p0 = corner(), p1 = corner(), p2 = corner();
            double u = rng.uniform(0.01, 0.98), v = rng.uniform(0.01, 0.98);
            if (u + v > 0.99) continue;
            const double w = 1.0 - u - v;
            const Vec3 target = w * p0 + u * p1 + v * p2;
            const Vec3 origin = target + 3.0 * rng.unitVector();
            const Vec3 normal = glm::cross(p1 - p0, p2 - p0);
            const Vec3 d = target - origin;
            if (glm::length(normal) < 0.1 ||
                std::abs(glm::dot(glm::normalize(d), glm::normalize(normal))) < 0.1)
                continue;
            ++tested;
            rb::TriangleHit th;
            if (!rb::intersectTriangle(rb::WatertightRay(rb::Ray{origin, d}), p0, p1, p2, kInf,
                                       th)) {
                ++missed;
                continue;
            }
            worstT = std::max(worstT, std::abs(th.t - 1.0));
            worstB =
                std::max({worstB, std::abs(th.b0 - w), std::abs(th.b1 - u), std::abs(th.b2 - v)});
            const Vec3 rebuilt = th.b0 * p0 + th.b1 * p1 + th.b2 * p2;
            worstPoint = std::max(worstPoint, glm::length(rebuilt - (origin + th.t * d)));
        }
        THEN(
            "every ray hits at t = 1 with the barycentrics it was aimed with, and "
            "b0·p0 + b1·p1 + b2·p2 is the point o + t·d") {
            // Source: d = target − o, so the target is at t = 1, and it was built from (w, u, v).
            CHECK(missed == 0);
            CHECK(worstT < 1e-12);
            CHECK(worstB < 1e-12);
            CHECK(worstPoint < 1e-12);
        }
    }
}

SCENARIO("a triangle is hit from either side", "[ch03][ex3.1]") {
    GIVEN("the triangle (0,0,0), (1,0,0), (0,1,0), whose winding makes +z its front") {
        const Vec3 p0(0, 0, 0), p1(1, 0, 0), p2(0, 1, 0);
        THEN("a ray from above and a ray from below both hit it at t = 1") {
            // Source: DESIGN §4.1: never cull back faces.
            rb::TriangleHit above, below;
            REQUIRE(
                rb::intersectTriangle(rb::WatertightRay(rb::Ray{Vec3(0.2, 0.2, 1), Vec3(0, 0, -1)}),
                                      p0, p1, p2, kInf, above));
            REQUIRE(
                rb::intersectTriangle(rb::WatertightRay(rb::Ray{Vec3(0.2, 0.2, -1), Vec3(0, 0, 1)}),
                                      p0, p1, p2, kInf, below));
            CHECK(above.t == Approx(1.0).epsilon(1e-15));
            CHECK(below.t == Approx(1.0).epsilon(1e-15));
            CHECK(below.b1 == Approx(0.2).epsilon(1e-15));
        }
        THEN("a mesh of it is hit from below too, with the winding's normal (0, 0, 1)") {
            const auto mesh = rbtest::makeMesh({p0, p1, p2}, {{0, 1, 2}});
            rb::ObjectHit oh;
            REQUIRE(mesh->intersect(rb::Ray{Vec3(0.2, 0.2, -1), Vec3(0, 0, 1)}, kInf, oh));
            CHECK(oh.t == Approx(1.0).epsilon(1e-15));
            CHECK(glm::normalize(oh.n) == Vec3(0, 0, 1));
        }
    }
}

SCENARIO("a degenerate triangle is never hit", "[ch03][ex3.1]") {
    GIVEN("a triangle with three collinear corners and one with two equal corners") {
        const Vec3 a(0, 0, 0), b(1, 1, 0), c(2, 2, 0);
        WHEN("rays pass exactly through their corners and along and across their line") {
            const rb::Ray rays[] = {
                {Vec3(1, 1, 1), Vec3(0, 0, -1)},      // through the middle corner, from above
                {Vec3(0, 0, 1), Vec3(0, 0, -1)},      // through the first corner
                {Vec3(0.5, 0.5, 3), Vec3(0, 0, -1)},  // through a point of the segment
                {Vec3(-1, -1, 0), Vec3(1, 1, 0)},     // along the segment itself
                {Vec3(1, 0, 0), Vec3(-1, 1, 0)},      // across it, in its plane
                {Vec3(3, -2, 5), Vec3(-2, 3, -5)},    // obliquely through (1, 1, 0)
            };
            THEN("no ray hits either triangle, and nothing is reported with a NaN") {
                for (const rb::Ray& ray : rays) {
                    CAPTURE(ray.o.x, ray.o.y, ray.o.z);
                    rb::TriangleHit th{};
                    CHECK_FALSE(rb::intersectTriangle(rb::WatertightRay(ray), a, b, c, kInf, th));
                    CHECK_FALSE(rb::intersectTriangle(rb::WatertightRay(ray), a, b, b, kInf, th));
                    CHECK_FALSE(rb::intersectTriangle(rb::WatertightRay(ray), b, b, b, kInf, th));
                }
            }
        }
    }
    GIVEN("OBJ data with one good triangle and two degenerate ones") {
        THEN("the mesh keeps the good one and counts the two it dropped") {
            const auto mesh =
                rbtest::makeMesh({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(2, 0, 0)},
                                 {{0, 1, 3}, {0, 1, 2}, {2, 2, 2}});
            CHECK(mesh->triangleCount() == 1);
            CHECK(mesh->droppedCount() == 2);
            CHECK(mesh->triangles().at(0).source == 1);
        }
        THEN("a mesh with no good triangle at all is an InputError naming it") {
            CHECK_THROWS_AS(
                rbtest::makeMesh({Vec3(0), Vec3(1, 0, 0), Vec3(2, 0, 0)}, {{0, 1, 2}}, "flat.obj"),
                rb::InputError);
            CHECK_THROWS_WITH(
                rbtest::makeMesh({Vec3(0), Vec3(1, 0, 0), Vec3(2, 0, 0)}, {{0, 1, 2}}, "flat.obj"),
                Catch::Contains("flat.obj"));
        }
    }
}

// ---- The float triangle test ------------------------------------------------------------------

/// A pack of four triangles, as the mesh builds it (vertex indices and sources left 0): each
/// vertex rounded to float, each lane's largest |coordinate| rounded up.
rb::Triangle4 packOf(const std::array<std::array<Vec3, 3>, 4>& triangles) {
    rb::Triangle4 pack{};
    for (int lane = 0; lane < 4; ++lane) {
        double extent = 0.0;
        for (int vertex = 0; vertex < 3; ++vertex)
            for (int axis = 0; axis < 3; ++axis) {
                const double c = triangles[lane][vertex][axis];
                pack.p[vertex][axis][lane] = static_cast<float>(c);
                extent = std::max(extent, std::abs(c));
            }
        pack.extent[lane] = rb::roundUpToFloat(extent);
    }
    return pack;
}

// [ch03-float-triangle-bound]
SCENARIO("the float triangle test decides only what the exact test decides",
         "[ch03][ex3.1][stability]") {
    // testTriangle4 runs the watertight test in float with an error bound on every value it
    // computes (triangle4.h derives them), and decides a lane only when the bound leaves no
    // doubt: a certain miss is dropped, and a shadow ray stops at a certain hit without the
    // exact test. If a bound were too small, some lane would be decided the wrong way. These
    // rays are built to sit where the float values are least accurate: they aim within a hair
    // of a triangle's edges (barycentrics in [−0.01, 1.01], half of them exactly on an edge);
    // they start close to the triangle's plane (10⁻¹ to 10⁻⁶ of its size), either far from the
    // point they hit, so that they graze the triangle and det is small, or close to it, so that
    // the distance T = U·z₀ + V·z₁ + W·z₂ is a small difference of large terms; and their limit
    // tMax lies on the exact hit distance or 2⁻³⁰ to 2⁻⁴ of it to either side. Planting a bound
    // too small, one at a time, makes this test fail: e_T = 0 gives 15 147 wrong misses and
    // 5 511 wrong hits; E a hundred times too small, 1 311 and 484. The bounds are not tight:
    // E ten times too small, or e_det = 0, still pass here (the float errors these rays meet
    // stay 10 to 100 times below the worst case the bounds allow); e_det matters only when all
    // three edge functions are barely larger than E, a sliver of a triangle seen edge-on.
    GIVEN("20 000 rays grazing random triangles near (±100, ±100, ±100), with limits near t") {
        rbtest::Rng rng(2024);
        int wrongMiss = 0, wrongHit = 0, certainHits = 0, certainMisses = 0, exactHits = 0;
        const double steps[] = {-0x1p-4, -0x1p-7, -0x1p-10, -0x1p-21, -0x1p-24, -0x1p-30, 0.0,
                                0x1p-30, 0x1p-24, 0x1p-21,  0x1p-10,  0x1p-7,   0x1p-4};
        for (int k = 0; k < 20000; ++k) {
            // Four triangles of size about 1 around a random centre; the ray aims at lane 0.
            const Vec3 centre(rng.uniform(-100, 100), rng.uniform(-100, 100),
                              rng.uniform(-100, 100));
            std::array<std::array<Vec3, 3>, 4> triangles;
            for (auto& tri : triangles)
                for (Vec3& v : tri)
                    v = centre + Vec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
            const auto& t0 = triangles[0];
            auto pointAt = [&](double b1, double b2) {
                return t0[0] + b1 * (t0[1] - t0[0]) + b2 * (t0[2] - t0[0]);
            };
            // Aim at a point near the edges. Half the rays start near the plane but far from
            // the point, and graze the triangle (det is small); half start a short distance h
            // before the point, in a random direction, as a shadow ray leaving a surface does
            // (T = h·det is small against its terms).
            // One ray in two aims exactly at an edge (b₂ = 0), as a ray through the edge two
            // triangles share does: there the exact edge function is 0, and only the bound E
            // keeps the float test from deciding on the rounding of its value.
            const double b1 = rng.uniform(-0.01, 1.01);
            const double b2 = k % 4 == 1 || k % 4 == 2 ? 0.0 : rng.uniform(-0.01, 1.01 - b1);
            const Vec3 target = pointAt(b1, b2);
            const Vec3 n = glm::normalize(glm::cross(t0[1] - t0[0], t0[2] - t0[0]));
            const double h = std::pow(10.0, -rng.uniform(1.0, 6.0));
            Vec3 start;
            if (k % 2 == 0) {
                start = pointAt(rng.uniform(-1, 2), rng.uniform(-1, 2)) +
                        (rng.uniform() < 0.5 ? h : -h) * n;
            } else {
                start = target - h * rng.unitVector();
            }
            const rb::Ray ray{start, target - start};
            const rb::WatertightRay wray(ray);
            const rb::FilterRay fray(wray);
            const rb::Triangle4 pack = packOf(triangles);
            rb::TriangleHit exact;
            const bool hits = rb::intersectTriangle(wray, t0[0], t0[1], t0[2], kInf, exact);
            exactHits += hits;
            // Limits: unlimited, and a few ulps around the hit distance (or 1 for a miss).
            const double tRef = hits ? exact.t : 1.0;
            for (const double step : steps)
                for (const double tMax : {kInf, tRef * (1.0 + step)}) {
                    const rb::Triangle4Verdict verdict =
                        rb::testTriangle4(fray, pack, 4, rb::FloatLimit(tMax));
                    for (int lane = 0; lane < 4; ++lane) {
                        const auto& v = triangles[lane];
                        rb::TriangleHit h;
                        const bool exactHit =
                            rb::intersectTriangle(wray, v[0], v[1], v[2], tMax, h);
                        const bool maybe = verdict.maybe >> lane & 1, hit = verdict.hit >> lane & 1;
                        wrongMiss += exactHit && !maybe;
                        wrongHit += hit && !exactHit;
                        certainHits += hit;
                        certainMisses += !maybe;
                    }
                }
        }
        THEN("a lane it drops is missed by the exact test, and a lane it calls hit is hit") {
            CAPTURE(exactHits, certainHits, certainMisses);
            // The float test must decide most lanes, or it would save nothing.
            REQUIRE(exactHits > 12000);
            REQUIRE(certainHits > 100000);
            CHECK(wrongMiss == 0);
            CHECK(wrongHit == 0);
        }
    }
}
// [ch03-float-triangle-bound]

// ---- The BVH ----------------------------------------------------------------------------------

// [ch03-fast-equals-simple]
SCENARIO("the wide traversals find exactly what the binary traversal finds",
         "[ch03][ex3.1][ex3.2]") {
    for (const NamedLayout& layout : wideLayoutsHere())
        GIVEN(std::string("binary and ") + layout.name +
              " BVHs over the bunny's triangles and 5 000 random rays into its bounds") {
            const rb::Mesh bunny(rb::loadObj(kBunnyPath), "bunny.obj");
            const auto triangles = bunny.triangles();
            const rb::BVH binary = bvhOver(triangles, rb::BVHLayout::Binary);
            const rb::BVH wide = bvhOver(triangles, layout.layout);
            REQUIRE(wide.layout() == layout.layout);
            REQUIRE(binary.primitiveOrder() == wide.primitiveOrder());  // one build, two layouts
            const auto& order = wide.primitiveOrder();
            rbtest::Rng rng(31337);
            int closestMismatch = 0, anyMismatch = 0, hits = 0;
            for (int k = 0; k < 5000; ++k) {
                const rb::Ray ray = rayInto(bunny.bounds(), rng);
                const rb::WatertightRay wray(ray);
                // The same leaf test for both traversals: the nearest triangle so far.
                auto leafFor = [&](long& best) {
                    return [&](std::uint32_t first, std::uint32_t count, double& tMax) {
                        bool found = false;
                        for (std::uint32_t slot = first; slot < first + count; ++slot) {
                            const auto& v = triangles[order[slot]].v;
                            rb::TriangleHit th;
                            if (!rb::intersectTriangle(wray, v[0], v[1], v[2], tMax, th)) continue;
                            tMax = th.t;
                            best = slot;
                            found = true;
                        }
                        return found;
                    };
                };
                long bestBinary = -1, bestWide = -1;
                double tBinary = kInf, tWide = kInf;
                const bool foundBinary = binary.closest(ray, tBinary, leafFor(bestBinary));
                const bool foundWide = wide.closest(ray, tWide, leafFor(bestWide));
                hits += foundWide;
                if (foundBinary != foundWide || tBinary != tWide) ++closestMismatch;
                auto anyLeaf = [&](std::uint32_t first, std::uint32_t count, double tMax) {
                    for (std::uint32_t slot = first; slot < first + count; ++slot) {
                        const auto& v = triangles[order[slot]].v;
                        rb::TriangleHit th;
                        if (rb::intersectTriangle(wray, v[0], v[1], v[2], tMax, th)) return true;
                    }
                    return false;
                };
                if (binary.any(ray, kInf, anyLeaf) != wide.any(ray, kInf, anyLeaf)) ++anyMismatch;
            }
            THEN("every closest hit (to the bit) and every any-hit answer agree") {
                // Source: both walk boxes that contain their primitives (the wide boxes are the
                // build boxes rounded outwards, tested conservatively) and run the same leaf test,
                // so the nearest distance cannot differ; only the order of visits does.
                REQUIRE(hits > 1000);
                CHECK(closestMismatch == 0);
                CHECK(anyMismatch == 0);
            }
        }
}
// [ch03-fast-equals-simple]

/// OBJ data for a grid of unit squares, `side` by `side`, in the plane z = z0, with its corner
/// at (x0, y0): integer coordinates, exact in float as in double.
rb::ObjData gridObj(int side, double x0, double y0, double z0) {
    rb::ObjData data;
    for (int j = 0; j <= side; ++j)
        for (int i = 0; i <= side; ++i) data.positions.emplace_back(x0 + i, y0 + j, z0);
    for (int j = 0; j < side; ++j)
        for (int i = 0; i < side; ++i) {
            const int a = j * (side + 1) + i, b = a + 1, c = a + side + 1, d = c + 1;
            data.triangles.push_back({rb::ObjCorner{a}, rb::ObjCorner{b}, rb::ObjCorner{d}});
            data.triangles.push_back({rb::ObjCorner{a}, rb::ObjCorner{d}, rb::ObjCorner{c}});
        }
    return data;
}

/// OBJ data for the surface of the cube [0, side]³ cut into unit squares.
rb::ObjData cubeObj(int side) {
    rb::ObjData data;
    for (int axis = 0; axis < 3; ++axis)
        for (const double level : {0.0, static_cast<double>(side)}) {
            // A grid in the plane (u, v) of this face, lifted to coordinate `level` on `axis`.
            const rb::ObjData face = gridObj(side, 0, 0, 0);
            const int base = static_cast<int>(data.positions.size());
            for (const Vec3& p : face.positions) {
                Vec3 q;
                q[axis] = level;
                q[(axis + 1) % 3] = p.x;
                q[(axis + 2) % 3] = p.y;
                data.positions.push_back(q);
            }
            for (auto t : face.triangles) {
                for (auto& corner : t) corner.v += base;
                data.triangles.push_back(t);
            }
        }
    return data;
}

// [ch03-robust-traversal]
SCENARIO("the float traversal never misses a hit that the exact double test finds",
         "[ch03][stability][ex3.1][ex3.2]") {
    // The wide BVH tests float boxes in float arithmetic; the binary one double boxes in double.
    // Both stretch the far end of each slab interval (kFarWidening; the 1 + 8ε of
    // intersectBox) so that rounding cannot make a box look missed. Random rays almost never
    // need that: they pass boxes with room to spare. These rays were built to need it: they
    // pass exactly through the corner of a box, where the entry and exit distances are equal
    // and any rounding can put them the wrong way round. All coordinates are small integers, or
    // integers near 2²⁰, so vertices and origins are exact in float and in double, and only the
    // slab arithmetic rounds. This test no longer shows that any one margin is needed: with
    // kFarWidening set to 1, or without intersectBox's far-plane stretch, it still passes,
    // because the padding of every primitive's box (padded() in bvh.cpp) rounds each node box
    // outwards by more than those roundings. Each margin has a test of its own below, on
    // inputs where no other margin can help (planted and run).
    struct Case {
        const char* name;
        rb::ObjData data;
    };
    Case cases[] = {
        {"a 24 x 24 grid at z = 3", gridObj(24, 0, 0, 3)},
        {"the same grid near (2^20, 2^20, 2^20)", gridObj(24, 1048576, 1048576, 1048576)},
        {"a 6 x 6 x 6 cube", cubeObj(6)}};
    for (Case& c : cases) {
        GIVEN(c.name) {
            std::vector<std::unique_ptr<rb::Mesh>> meshes;
            std::vector<const char*> names;
            for (const NamedLayout& layout : layoutsHere()) {
                meshes.push_back(std::make_unique<rb::Mesh>(c.data, "test.obj", layout.layout));
                names.push_back(layout.name);
            }
            const auto triangles = meshes[0]->triangles();
            rbtest::Rng rng(4242);
            auto smallInt = [&](int lo, int hi) {
                return static_cast<double>(lo + static_cast<int>(rng.uniform() * (hi - lo + 1)));
            };
            std::vector<rb::Ray> rays;
            // Through every vertex from an integer origin a few units away: the hit is at
            // t = 1 exactly, on the corner of the boxes around the vertex.
            for (const Vec3& v : c.data.positions)
                for (int k = 0; k < 12; ++k) {
                    const Vec3 offset(smallInt(-9, 9), smallInt(-9, 9), smallInt(1, 9));
                    rays.push_back({v + offset, -offset});
                }
            // Along the planes of the boxes' faces (a zero direction component), from origins
            // on such a plane.
            for (int k = 0; k < 3000; ++k) {
                const Vec3& v = c.data.positions[static_cast<size_t>(
                    rng.uniform() * static_cast<double>(c.data.positions.size()))];
                Vec3 d(smallInt(-9, 9), smallInt(-9, 9), smallInt(-9, 9));
                d[k % 3] = 0.0;
                if (d == Vec3(0.0)) continue;
                rays.push_back({v - smallInt(1, 5) * d, d});
            }
            int hits = 0, mismatches = 0;
            for (const rb::Ray& ray : rays) {
                double tBrute;
                const long source = bruteForceClosest(triangles, ray, tBrute);
                hits += source >= 0;
                for (size_t m = 0; m < meshes.size(); ++m) {
                    const rb::Mesh* mesh = meshes[m].get();
                    rb::ObjectHit oh;
                    const bool found = mesh->intersect(ray, kInf, oh);
                    const bool same =
                        found == (source >= 0) &&
                        (!found ||
                         (oh.t == tBrute && oh.primitive == static_cast<std::uint32_t>(source)));
                    // Shadow rays over the whole ray, and ending just past the hit.
                    const bool shadowSame =
                        mesh->occluded(ray, kInf) == found &&
                        (!found || mesh->occluded(ray, std::nextafter(tBrute, kInf)));
                    if (!same || !shadowSame) {
                        ++mismatches;
                        UNSCOPED_INFO("o = (" << ray.o.x << ", " << ray.o.y << ", " << ray.o.z
                                              << "), d = (" << ray.d.x << ", " << ray.d.y << ", "
                                              << ray.d.z << "), layout " << names[m]);
                    }
                }
            }
            THEN(
                "every traversal agrees with brute force on every ray: hit, distance, triangle, "
                "shadow") {
                CAPTURE(rays.size(), hits);
                REQUIRE(hits > static_cast<int>(rays.size()) / 3);
                CHECK(mismatches == 0);
            }
        }
    }
}
// [ch03-robust-traversal]

// ---- Each robustness margin, on its own -------------------------------------------------------
//
// The traversals carry four safety margins: the far-plane widening of the wide (float) slab
// test (kFarWidening), the far-plane widening of the binary (double) slab test (the 1 + 8ε of
// intersectBox), the float ray origin moved outwards (WideRay), and the padding of every
// primitive's box (padded() in bvh.cpp). On most inputs they cover for each other, so each test
// below builds inputs on which only one of them can help, and fails when that one alone is
// removed (numbers checked by planting each removal).

/// One wide node whose N children are box b, rounded outwards to float.
template <int N = 4>
rb::WideNodeN<N> wideNodeOf(const rb::AABB& b) {
    rb::WideNodeN<N> n{};
    for (int c = 0; c < N; ++c)
        for (int axis = 0; axis < 3; ++axis) {
            n.lo[axis][c] = rb::roundDownToFloat(b.lo[axis]);
            n.hi[axis][c] = rb::roundUpToFloat(b.hi[axis]);
        }
    return n;
}

/// The children of node n (eight-wide) that the ray enters with tMax = ∞, as a mask: the AVX2
/// slab test, intersectChildren8. Returns -1 where the eight-wide path is not available (no
/// AVX2 here, or not an x86-64 build); it is compiled for AVX2, and runs only after that check.
#if RB_HAVE_WIDE8
[[gnu::target("avx2")]] int childrenEntered8(const rb::WideNode8& n, const rb::Ray& ray) {
    __m256 tEntry;
    return rb::intersectChildren8(n, rb::WideRay8(ray), rb::wideTMax8(kInf), tEntry);
}
#endif
int childrenEntered8IfAvailable(const rb::WideNode8& n, const rb::Ray& ray) {
#if RB_HAVE_WIDE8
    if (rb::wide8Available()) return childrenEntered8(n, ray);
#endif
    return -1;
}

/// A flat box that the ray from 0 towards c touches only at its corner c, at t = 1: flat on
/// axis `flat` (lo = hi = c there), and reaching `size` away from 0 on the other two axes.
rb::AABB flatBoxAtCorner(const Vec3& c, int flat, double size) {
    rb::AABB b;
    b.extend(c);
    Vec3 far = c;
    for (int axis = 0; axis < 3; ++axis)
        if (axis != flat) far[axis] += std::copysign(size, c[axis]);
    b.extend(far);
    return b;
}

/// A random float in ±[1, 1000), with a random sign: a corner coordinate exact in float.
double randomFloatCoordinate(rbtest::Rng& rng) {
    const double magnitude = static_cast<float>(rng.uniform(1.0, 1000.0));
    return rng.uniform() < 0.5 ? -magnitude : magnitude;
}

// [ch03-margin-wide-far]
SCENARIO("the float slab test enters a flat box that a ray touches only at its corner",
         "[ch03][stability]") {
    // A ray from the origin through corner c of a flat box touches the box at t = 1 and nowhere
    // else: the near plane of one axis and the far plane of the flat axis both sit at t = 1
    // exactly. The origin is 0, so moving it outwards (WideRay's other margin) moves it by
    // 2⁻¹⁴⁹ only, and the boxes are not padded: the float slab test sees t₀ = c_x·fl(1/c_x)
    // and t₁ = c_z·fl(1/c_z), each rounded, and t₀ > t₁ happens often. Only the far-plane
    // stretch kFarWidening (1 + 2⁻²⁰, more than the 1 + 2γ₃ the roundings need) puts them in
    // order. With kFarWidening = 1, 577 of these 4 000 rays miss their box (planted and run).
    // The eight-wide AVX2 test (intersectChildren8) runs the same arithmetic lane for lane with
    // the same stretch, carried by WideRay8's far reciprocals: with those left unstretched
    // (invDFar = invDNear in WideRay8 alone), the same 577 rays miss their box there (planted
    // and run).
    GIVEN("4 000 flat boxes with float corners in ±[1, 1000), and the rays from 0 to the corner") {
        rbtest::Rng rng(2013);
        int misses = 0, misses8 = 0;
        for (int k = 0; k < 4000; ++k) {
            const Vec3 c(randomFloatCoordinate(rng), randomFloatCoordinate(rng),
                         randomFloatCoordinate(rng));
            const rb::AABB box = flatBoxAtCorner(c, k % 3, 10.0);
            const rb::Ray r{Vec3(0.0), c};
            const rb::WideRay ray(r);
            __m128 tEntry;
            const int mask =
                rb::intersectChildren4(wideNodeOf(box), ray, rb::wideTMax(kInf), tEntry);
            misses += mask != 0xF;
            const int mask8 = childrenEntered8IfAvailable(wideNodeOf<8>(box), r);
            misses8 += mask8 != 0xFF && mask8 != -1;
        }
        THEN("every ray enters its box (all four lanes of the SSE test)") {
            CHECK(misses == 0);
        }
        THEN("and all eight lanes of the AVX2 test, where the CPU has it") {
            if (!rb::wide8Available()) WARN("this CPU has no AVX2: the eight-wide test is skipped");
            CHECK(misses8 == 0);
        }
    }
}
// [ch03-margin-wide-far]

// [ch03-margin-binary-far]
SCENARIO("the double slab test enters a flat box that a ray touches only at its corner",
         "[ch03][stability]") {
    // The same rays as above in double, for intersectBox, the binary traversal's test: from 0
    // through a corner c with double coordinates, so t₀ = c_x·fl(1/c_x) and t₁ = c_z·fl(1/c_z),
    // each rounded in double. Only the far-plane stretch 1 + 8ε puts them in order. Without it
    // (tFar not multiplied by `widen`), 605 of these 4 000 rays miss their box (planted and
    // run).
    GIVEN("4 000 flat boxes with random double corners in ±[1, 1000), and the rays from 0") {
        rbtest::Rng rng(2014);
        int misses = 0;
        for (int k = 0; k < 4000; ++k) {
            Vec3 c;
            for (int axis = 0; axis < 3; ++axis)
                c[axis] = (rng.uniform() < 0.5 ? -1.0 : 1.0) * rng.uniform(1.0, 1000.0);
            const rb::AABB box = flatBoxAtCorner(c, k % 3, 10.0);
            double tEntry;
            misses += !rb::intersectBox(box, rb::RayInverse(rb::Ray{Vec3(0.0), c}), kInf, tEntry);
        }
        THEN("every ray enters its box") {
            CHECK(misses == 0);
        }
    }
}
// [ch03-margin-binary-far]

// [ch03-margin-origin]
SCENARIO("the float slab test keeps a ray whose origin rounds onto a far face of a box",
         "[ch03][stability]") {
    // The origin lies inside a box, 10⁻¹² (relative) short of its far face on axis a, which is a
    // float plane X; the direction is nearly parallel to that face, so the ray leaves through it
    // only at t = 2, after entering through a face of axis b at t = 1. Rounded to float, the
    // origin lands exactly on X, and the far face then looks 0 away: t₁ = 0 < t₀ = 1, a miss.
    // No widening can stretch 0; only moving the float origin outwards (away from the far face,
    // by more than rounding moved it: WideRay's err) keeps the ray. Without that move (err = 0),
    // all 2 000 of these rays miss their box (planted and run), in the four-wide test and in
    // the eight-wide one alike (WideRay8 moves its origins by the same err, computed again for
    // itself, and this test counts its misses apart).
    GIVEN("2 000 boxes with a float face X, and rays from 10⁻¹²·|X| inside it, nearly parallel") {
        rbtest::Rng rng(2015);
        int misses = 0, misses8 = 0;
        for (int k = 0; k < 2000; ++k) {
            const int a = k % 3, b = (a + 1) % 3, c = (a + 2) % 3;
            const double X = randomFloatCoordinate(rng);
            const double side = rng.uniform() < 0.5 ? -1.0 : 1.0;  // which way the ray leaves
            // The box: on axis a from X − 10·side to X (the far face), on b from 1 to 2, on c
            // from −1 to 1.
            rb::AABB box;
            Vec3 lo(0.0), hi(0.0);
            lo[a] = X - 10.0 * side;
            hi[a] = X;
            lo[b] = 1.0;
            hi[b] = 2.0;
            lo[c] = -1.0;
            hi[c] = 1.0;
            box.extend(lo);
            box.extend(hi);
            Vec3 o(0.0), d(0.0);
            const double gap = 1e-12 * std::abs(X);
            o[a] = X - side * gap;
            d[a] = side * gap / 2.0;  // leaves through X at t = 2
            o[b] = 0.0;
            d[b] = 1.0;  // enters at t = 1
            o[c] = 0.0;
            d[c] = 0.0;
            REQUIRE(static_cast<float>(o[a]) == static_cast<float>(X));  // rounds onto the face
            const rb::WideRay ray(rb::Ray{o, d});
            __m128 tEntry;
            const int mask =
                rb::intersectChildren4(wideNodeOf(box), ray, rb::wideTMax(kInf), tEntry);
            misses += mask != 0xF;
            const int mask8 = childrenEntered8IfAvailable(wideNodeOf<8>(box), rb::Ray{o, d});
            misses8 += mask8 != 0xFF && mask8 != -1;
        }
        THEN("every ray enters its box, in the four-wide test and the eight-wide one") {
            if (!rb::wide8Available()) WARN("this CPU has no AVX2: the eight-wide test is skipped");
            CHECK(misses == 0);
            CHECK(misses8 == 0);
        }
    }
}
// [ch03-margin-origin]

// [ch03-margin-padding]
SCENARIO("the BVH over instances finds a box hit by a ray that grazes its world bounds",
         "[ch03][stability]") {
    // A ray in the plane of a face of an instance's world bounds, one or two ulps outside it,
    // with no direction component across that face: the slab test of the world box says miss,
    // exactly (the far-plane widening stretches t, and t is ±∞ here). But the instance tests
    // its shape in object space, after the inverse transform has rounded the origin, and that
    // can land it on the unit box's face, where a ray parallel to a face counts as inside: a
    // hit, which testing every instance (LinearAggregate) reports. The world bounds are
    // computed with rounding too. Only the padding of every primitive's box (padded() in
    // bvh.cpp, 64 ulps of its largest coordinate) lets the binary traversal find those hits;
    // the wide traversal's float boxes are rounded outwards, which pads them by more. Without
    // the padding, the binary traversal misses all 337 of these hits, in its closest-hit and
    // its shadow query alike (planted and run).
    GIVEN("2 000 unit boxes, scaled and moved by random doubles, and rays along their faces") {
        const rb::Box box;
        rbtest::Rng rng(2016);
        const std::vector<NamedLayout> layouts = layoutsHere();
        int hits = 0, mismatches = 0;
        for (int k = 0; k < 2000; ++k) {
            const Vec3 scale(rng.uniform(0.5, 3.0), rng.uniform(0.5, 3.0), rng.uniform(0.5, 3.0));
            const Vec3 move(rng.uniform(-5.0, 5.0), rng.uniform(-5.0, 5.0), rng.uniform(-5.0, 5.0));
            const rb::Mat4 m = glm::scale(glm::translate(rb::Mat4(1.0), move), scale);
            const std::vector<rb::Instance> instances = {rbtest::makeInstance(box, m)};
            const rb::AABB world = instances[0].worldBounds;
            // A face: axis a, high or low side; the origin 1 or 2 ulps outside its plane, in
            // the middle of the face, the direction in the plane.
            const int a = k % 3, b = (a + 1) % 3, c = (a + 2) % 3;
            const bool high = (k / 3) % 2 == 0;
            Vec3 o = world.centre(), d(0.0);
            o[a] = high ? world.hi[a] : world.lo[a];
            for (int step = 0; step < 1 + (k / 6) % 2; ++step)
                o[a] = std::nextafter(o[a], high ? kInf : -kInf);
            o[b] -= 10.0;
            d[b] = 1.0;
            d[c] = rng.uniform(-0.1, 0.1);
            const rb::Ray ray{o, d};
            rb::Hit linearHit;
            const bool found = rb::LinearAggregate(instances).intersect(ray, kInf, linearHit);
            hits += found;
            for (const NamedLayout& layout : layouts) {
                // binaryUpTo 0, flatUpTo 0: the tree has this layout even over one instance.
                const rb::BVHAggregate bvh(instances, layout.layout, 0, 0);
                rb::Hit hit;
                if (bvh.intersect(ray, kInf, hit) != found) ++mismatches;
                if (bvh.occluded(ray, kInf) != found) ++mismatches;
            }
        }
        THEN("every traversal finds every hit that testing the instance finds") {
            CAPTURE(hits);
            REQUIRE(hits > 100);  // the rays are built to be found this way often
            CHECK(mismatches == 0);
        }
    }
}
// [ch03-margin-padding]

// [ch03-bvh-equals-brute-force]
SCENARIO("the BVH finds the same closest triangle as testing every triangle",
         "[ch03][ex3.1][ex3.2]") {
    GIVEN(
        "the Stanford bunny (3 674 triangles) and 2 000 random rays aimed into its bounds "
        "(fixed seed)") {
        for (const NamedLayout& layout : layoutsHere())
            WHEN(std::string("the mesh's BVH is ") + layout.name) {
                const rb::Mesh bunny(rb::loadObj(kBunnyPath), "bunny.obj", layout.layout);
                REQUIRE(bunny.bvh().layout() == layout.layout);
                REQUIRE(bunny.triangleCount() > 3000);
                const auto triangles = bunny.triangles();
                rbtest::Rng rng(2718);
                int hits = 0, hitMismatch = 0, tMismatch = 0, triangleMismatch = 0,
                    shadowMismatch = 0;
                for (int k = 0; k < 2000; ++k) {
                    const rb::Ray ray = rayInto(bunny.bounds(), rng);
                    double tBrute;
                    const long source = bruteForceClosest(triangles, ray, tBrute);
                    rb::ObjectHit oh;
                    const bool found = bunny.intersect(ray, kInf, oh);
                    if (found != (source >= 0)) {
                        ++hitMismatch;
                        continue;
                    }
                    // The shadow query over the whole ray agrees with the closest-hit query.
                    if (bunny.occluded(ray, kInf) != found) ++shadowMismatch;
                    if (!found) continue;
                    ++hits;
                    // Both run the same triangle test on the same triangle, so t agrees to the last
                    // bits; 1e-12 relative still allows for a different but equally close triangle.
                    if (std::abs(oh.t - tBrute) > 1e-12 * tBrute) ++tMismatch;
                    if (oh.primitive != static_cast<std::uint32_t>(source)) ++triangleMismatch;
                    // A shadow ray that stops just short of the hit is free; one just past it is
                    // not.
                    if (bunny.occluded(ray, tBrute * (1 - 1e-9))) ++shadowMismatch;
                    if (!bunny.occluded(ray, tBrute * (1 + 1e-9))) ++shadowMismatch;
                }
                THEN("hit or miss, the distance, the triangle and the shadow verdict all agree") {
                    CHECK(hits > 500);  // the comparison is about hits, so enough rays must hit
                    CHECK(hitMismatch == 0);
                    CHECK(tMismatch == 0);
                    CHECK(triangleMismatch == 0);
                    CHECK(shadowMismatch == 0);
                }
            }
    }
}
// [ch03-bvh-equals-brute-force]

// It needs exercise 3.1 as well as 3.2: its meshes' shadow queries stop at a hit the float
// triangle test is sure of, without the exact test, so with 3.1 blank the shadow and the
// closest-hit answers on a mesh disagree.
SCENARIO("a two-level BVH over instances finds the same hits as testing every instance",
         "[ch03][ex3.1][ex3.2]") {
    GIVEN(
        "400 spheres, 400 boxes and 12 bunnies, each randomly scaled, turned and placed in a "
        "40-unit cube (fixed seed)") {
        const rb::Sphere sphere;
        const rb::Box box;
        const rb::Mesh bunny(rb::loadObj(kBunnyPath), "bunny.obj");
        rbtest::Rng rng(161);
        std::vector<rb::Instance> instances;
        for (int i = 0; i < 812; ++i) {
            const rb::Shape& shape = i < 400   ? static_cast<const rb::Shape&>(sphere)
                                     : i < 800 ? static_cast<const rb::Shape&>(box)
                                               : static_cast<const rb::Shape&>(bunny);
            const double size = i < 800 ? rng.uniform(0.2, 1.5) : rng.uniform(0.3, 1.0);
            rb::Mat4 m = glm::translate(
                rb::Mat4(1.0),
                Vec3(rng.uniform(-20, 20), rng.uniform(-20, 20), rng.uniform(-20, 20)));
            m = glm::rotate(m, rng.uniform(0.0, 6.28), rng.unitVector());
            m = glm::scale(
                m, size * Vec3(rng.uniform(0.5, 2), rng.uniform(0.5, 2), rng.uniform(0.5, 2)));
            instances.push_back(rbtest::makeInstance(shape, m, nullptr, "i" + std::to_string(i)));
        }
        const rb::LinearAggregate linear(instances);
        const rb::BVHAggregate bvh(instances);
        const rb::BVHAggregate binary(instances, rb::BVHLayout::Binary);
        // Every other layout this machine runs, checked against `bvh` (the default, the widest).
        std::vector<std::unique_ptr<rb::BVHAggregate>> others;
        for (const NamedLayout& layout : layoutsHere())
            if (layout.layout != rb::BVHLayout::Binary && layout.layout != bvh.bvh().layout())
                others.push_back(std::make_unique<rb::BVHAggregate>(instances, layout.layout));
        rb::AABB world;
        for (const rb::Instance& i : instances) world.extend(i.worldBounds);
        WHEN("3 000 random rays are traced through all of them") {
            int hits = 0, hitMismatch = 0, instanceMismatch = 0, tMismatch = 0, shadowMismatch = 0;
            for (int k = 0; k < 3000; ++k) {
                const rb::Ray ray = rayInto(world, rng);
                rb::Hit a, b;
                const bool foundLinear = linear.intersect(ray, kInf, a);
                const bool foundBvh = bvh.intersect(ray, kInf, b);
                rb::Hit c;
                if (binary.intersect(ray, kInf, c) != foundBvh ||
                    (foundBvh && (c.instance != b.instance || c.t != b.t)))
                    ++hitMismatch;
                for (const auto& other : others)
                    if (other->intersect(ray, kInf, c) != foundBvh ||
                        (foundBvh &&
                         (c.instance != b.instance || c.t != b.t || c.primitive != b.primitive)))
                        ++hitMismatch;
                if (foundLinear != foundBvh) {
                    ++hitMismatch;
                    continue;
                }
                // A random segment length: the shadow verdicts must agree with the closest hit.
                const double tMax = rng.uniform(0.0, 2.0);
                const bool blocked = foundLinear && a.t < tMax;
                if (bvh.occluded(ray, tMax) != blocked || linear.occluded(ray, tMax) != blocked ||
                    binary.occluded(ray, tMax) != blocked)
                    ++shadowMismatch;
                for (const auto& other : others)
                    if (other->occluded(ray, tMax) != blocked) ++shadowMismatch;
                if (!foundLinear) continue;
                ++hits;
                if (a.instance != b.instance || a.primitive != b.primitive) ++instanceMismatch;
                if (std::abs(a.t - b.t) > 1e-12 * a.t) ++tMismatch;
            }
            THEN(
                "hit or miss, the instance, the triangle, the distance and the shadow verdict "
                "all agree") {
                CHECK(hits > 500);
                CHECK(hitMismatch == 0);
                CHECK(instanceMismatch == 0);
                CHECK(tMismatch == 0);
                CHECK(shadowMismatch == 0);
            }
        }
        THEN(
            "the top-level trees are well formed: each node's box holds its children and each "
            "instance sits in exactly one leaf, in every layout") {
            const auto& order = binary.bvh().primitiveOrder();
            const auto bounds = [&](std::uint32_t slot) {
                return instances[order[slot]].worldBounds;
            };
            const TreeReport report = walkTree(binary.bvh(), instances.size(), bounds);
            CHECK(report.nodesReached == binary.bvh().nodes().size());
            CHECK(report.badChildBounds == 0);
            CHECK(report.badLeafBounds == 0);
            CHECK(std::all_of(report.slotSeen.begin(), report.slotSeen.end(),
                              [](int n) { return n == 1; }));
            std::vector<const rb::BVH*> wideTrees = {&bvh.bvh()};
            for (const auto& other : others) wideTrees.push_back(&other->bvh());
            for (const rb::BVH* tree : wideTrees) {
                CAPTURE(rb::bvhLayoutDescription(tree->layout()));
                REQUIRE(tree->primitiveOrder() == order);  // one build, several layouts
                const TreeReport wide = walkWide(*tree, instances.size(), bounds);
                CHECK(wide.nodesReached == wideNodeCount(*tree));
                CHECK(wide.badChildBounds == 0);
                CHECK(wide.badLeafBounds == 0);
                CHECK(std::all_of(wide.slotSeen.begin(), wide.slotSeen.end(),
                                  [](int n) { return n == 1; }));
            }
        }
    }
}

SCENARIO("a BVH is well formed: boxes nest, and every primitive is in exactly one leaf",
         "[ch03][ex3.2]") {
    for (const NamedLayout& layout : wideLayoutsHere())
        GIVEN(std::string("binary and ") + layout.name + " BVHs over the bunny's triangles") {
            const rb::Mesh bunny(rb::loadObj(kBunnyPath), "bunny.obj");
            const auto triangles = bunny.triangles();
            const rb::BVH bvh = bvhOver(triangles, rb::BVHLayout::Binary);
            const rb::BVH wide = bvhOver(triangles, layout.layout);
            REQUIRE(wide.layout() == layout.layout);
            const auto bounds = [&](std::uint32_t slot) {
                rb::AABB b;
                for (const Vec3& p : triangles[bvh.primitiveOrder()[slot]].v) b.extend(p);
                return b;
            };
            const TreeReport report = walkTree(bvh, triangles.size(), bounds);
            const TreeReport wideReport = walkWide(wide, triangles.size(), bounds);
            THEN("every node is reached once from the root, and no node is orphaned") {
                CHECK(report.nodesReached == bvh.nodes().size());
                CHECK(wideReport.nodesReached == wideNodeCount(wide));
            }
            THEN(
                "every node's box contains its children's boxes, and every leaf's box its "
                "triangles; the wide nodes' float boxes too") {
                CHECK(report.badChildBounds == 0);
                CHECK(report.badLeafBounds == 0);
                CHECK(wideReport.badChildBounds == 0);
                CHECK(wideReport.badLeafBounds == 0);
            }
            THEN("every triangle slot appears in exactly one leaf") {
                CHECK(std::all_of(report.slotSeen.begin(), report.slotSeen.end(),
                                  [](int n) { return n == 1; }));
                CHECK(std::all_of(wideReport.slotSeen.begin(), wideReport.slotSeen.end(),
                                  [](int n) { return n == 1; }));
            }
            THEN("primitiveOrder() is a permutation of 0 … n−1") {
                std::vector<std::uint32_t> order = bvh.primitiveOrder();
                std::sort(order.begin(), order.end());
                bool permutation = order.size() == bunny.triangleCount();
                for (size_t i = 0; permutation && i < order.size(); ++i)
                    permutation = order[i] == i;
                CHECK(permutation);
            }
            THEN("the tree fits the traversal's fixed stack (one entry per level descended)") {
                CHECK(bvh.depth() <= rb::BVH::kStackSize);
            }
        }
}

// [ch03-log-cost]
SCENARIO("the cost of a ray grows like log n with the number of triangles",
         "[ch03][ex3.1][ex3.2]") {
    // We count work instead of timing it. For meshes of n = 2 048, 32 768 and 524 288 triangles
    // (a wavy height field cut ever finer) we trace 2 000 rays that hit the surface (fixed
    // seed), and count per ray
    //  - the triangle tests the real traversal (BVH::closest) asks for, through a counting leaf
    //    callback, and
    //  - the nodes whose boxes the ray pierces before its hit: the nodes any closest-hit
    //    traversal must open.
    // Why log n: the tree halves the triangles at each level, so it has about log2(n/4) levels,
    // and a ray crossing a surface pierces only a few boxes per level (the ones along its path
    // near the hit); the leaves it reaches hold at most 4 triangles each. So the work per ray is
    // about c·log2(n) for a small c. Brute force would be n tests; a uniform grid about n^(1/2).
    // Each step multiplies n by 16, which adds 4 to log2(n): at most a factor 15/11 ≈ 1.4.
    GIVEN("meshes of 2 048, 32 768 and 524 288 triangles") {
        struct Level {
            int gridSide;
            double n = 0, triangleTests = 0, nodes = 0;
        };
        Level levels[] = {{32}, {128}, {512}};
        WHEN("2 000 rays per mesh are traced and their work counted") {
            for (Level& level : levels) {
                const auto triangles = heightField(level.gridSide)->triangles();
                const rb::BVH bvh = bvhOver(triangles, rb::BVHLayout::Binary);
                level.n = static_cast<double>(triangles.size());
                rbtest::Rng rng(8);
                long tests = 0, nodes = 0, hits = 0;
                constexpr int kRays = 2000;
                for (int k = 0; k < kRays; ++k) {
                    // From 2 units away, above the surface, to a point of its interior.
                    const Vec3 target(rng.uniform(0.1, 0.9), rng.uniform(0.1, 0.9), 0.0);
                    Vec3 up = rng.hemisphere(Vec3(0, 0, 1));
                    up.z = std::max(up.z, 0.3);
                    const rb::Ray ray{target + 2.0 * up, -up};
                    const rb::WatertightRay wray(ray);
                    double tMax = kInf;
                    const bool found = bvh.closest(
                        ray, tMax, [&](std::uint32_t first, std::uint32_t count, double& t) {
                            bool foundHere = false;
                            for (std::uint32_t slot = first; slot < first + count; ++slot) {
                                ++tests;
                                const auto& v = triangles[bvh.primitiveOrder()[slot]].v;
                                rb::TriangleHit th;
                                if (!rb::intersectTriangle(wray, v[0], v[1], v[2], t, th)) continue;
                                t = th.t;
                                foundHere = true;
                            }
                            return foundHere;
                        });
                    hits += found;
                    nodes += nodesPierced(bvh, rb::RayInverse(ray), tMax);
                }
                REQUIRE(hits > kRays * 99 / 100);  // the rays are aimed at the surface
                level.triangleTests = static_cast<double>(tests) / kRays;
                level.nodes = static_cast<double>(nodes) / kRays;
            }
            THEN(
                "16 times the triangles costs less than 3 times the work (linear: 16 times), "
                "and the work per ray stays below 4·log2(n)") {
                for (int i = 0; i < 3; ++i) {
                    const double work = levels[i].triangleTests + levels[i].nodes;
                    CAPTURE(levels[i].n, levels[i].triangleTests, levels[i].nodes);
                    CHECK(work < 4.0 * std::log2(levels[i].n));
                    if (i > 0) {
                        const double before = levels[i - 1].triangleTests + levels[i - 1].nodes;
                        CHECK(work < 3.0 * before);
                    }
                }
            }
        }
    }
}
// [ch03-log-cost]

SCENARIO("--bvh names a layout, and wide is the widest this processor runs", "[ch03]") {
    GIVEN("the names --bvh takes") {
        THEN(
            "binary and wide4 are always there; wide, and no name, are wide8 exactly when AVX2 "
            "is") {
            CHECK(rb::bvhLayoutNamed("binary") == rb::BVHLayout::Binary);
            CHECK(rb::bvhLayoutNamed("wide4") == rb::BVHLayout::Wide4);
            const rb::BVHLayout widest =
                rb::wide8Available() ? rb::BVHLayout::Wide8 : rb::BVHLayout::Wide4;
            CHECK(rb::bestWideLayout() == widest);
            CHECK(rb::bvhLayoutNamed("wide") == widest);
            CHECK(rb::bvhLayoutNamed("") == widest);
        }
        THEN("wide8 is refused where AVX2 is not, and any other name always") {
            if (rb::wide8Available())
                CHECK(rb::bvhLayoutNamed("wide8") == rb::BVHLayout::Wide8);
            else
                CHECK_THROWS_WITH(rb::bvhLayoutNamed("wide8"), Catch::Contains("AVX2"));
            CHECK_THROWS_AS(rb::bvhLayoutNamed("wide16"), rb::InputError);
            CHECK_THROWS_WITH(rb::bvhLayoutNamed("Wide"), Catch::Contains("wide4 or wide8"));
        }
        THEN("--stats names each path") {
            CHECK(std::string(rb::bvhLayoutDescription(rb::BVHLayout::Binary)) == "binary");
            CHECK(std::string(rb::bvhLayoutDescription(rb::BVHLayout::Wide4)) == "wide4 (SSE)");
            CHECK(std::string(rb::bvhLayoutDescription(rb::BVHLayout::Wide8)) == "wide8 (AVX2)");
        }
    }
}

SCENARIO("a top level of a handful of instances is a binary tree, of one or two no tree, and "
         "finds what the others find",
         "[ch03][ex3.2]") {
    // For a few instances the wide node's ray set-up costs more than the box tests it saves:
    // spheres.lua (4 instances), 1 thread, render phase, 3 runs each: wide8 0.054 s, wide4
    // 0.050 s, binary 0.049 s; and for one or two, any tree costs more than their boxes: the
    // mesh benchmark (a bunny on a ground plane), 195.8 -> 189.6 million instructions (chapter
    // 3, "Two levels and instancing").
    const rb::Sphere sphere;
    rbtest::Rng rng(24);
    for (const size_t count : {size_t{1}, rb::kFlatTopLevel, rb::kFlatTopLevel + 1,
                               rb::kBinaryTopLevel, rb::kBinaryTopLevel + 1}) {
        GIVEN(std::to_string(count) + " spheres at random places") {
            std::vector<rb::Instance> instances;
            for (size_t i = 0; i < count; ++i)
                instances.push_back(rbtest::makeInstance(
                    sphere,
                    glm::translate(rb::Mat4(1.0), Vec3(rng.uniform(-3, 3), rng.uniform(-3, 3),
                                                       rng.uniform(-3, 3)))));
            for (const NamedLayout& layout : layoutsHere()) {
                WHEN("the top level is built with --bvh=" + std::string(layout.name)) {
                    const rb::BVHAggregate bvh(instances, layout.layout);
                    const rb::BVHAggregate asked(instances, layout.layout, 0, 0);
                    THEN("no tree up to kFlatTopLevel instances, binary up to kBinaryTopLevel, "
                         "else the layout asked") {
                        if (count <= rb::kFlatTopLevel) {
                            CHECK(bvh.bvh().nodeCount() == 0);
                            CHECK(bvh.outsideCount() == count);
                            CHECK_THAT(bvh.statistics(), Catch::Contains("no top-level tree"));
                        } else {
                            CHECK(bvh.outsideCount() == 0);
                            CHECK(bvh.bvh().layout() == (count <= rb::kBinaryTopLevel
                                                             ? rb::BVHLayout::Binary
                                                             : asked.bvh().layout()));
                        }
                        CHECK(asked.bvh().layout() == layout.layout);
                    }
                    THEN("both find the same instance at the same distance on 500 rays") {
                        int mismatches = 0;
                        for (int k = 0; k < 500; ++k) {
                            const rb::Ray ray{
                                Vec3(rng.uniform(-6, 6), rng.uniform(-6, 6), 8.0),
                                Vec3(rng.uniform(-0.5, 0.5), rng.uniform(-0.5, 0.5), -1.0)};
                            rb::Hit a, b;
                            const bool hitA = bvh.intersect(ray, kInf, a);
                            if (hitA != asked.intersect(ray, kInf, b) ||
                                (hitA && (a.t != b.t || a.instance != b.instance)))
                                ++mismatches;
                            if (bvh.occluded(ray, kInf) != hitA) ++mismatches;
                        }
                        CHECK(mismatches == 0);
                    }
                }
            }
        }
    }
}

/// The closest hit by testing every instance in scene order, the first one winning a tie:
/// what any top level must find.
const rb::Instance* closestInSceneOrder(const std::vector<rb::Instance>& instances,
                                        const rb::Ray& ray, double& t) {
    const rb::Instance* winner = nullptr;
    t = kInf;
    for (const rb::Instance& instance : instances) {
        rb::ObjectHit oh;
        if (instance.intersect(ray, t, oh)) {  // strictly nearer only: the first keeps a tie
            t = oh.t;
            winner = &instance;
        }
    }
    return winner;
}

SCENARIO("a ground plane far wider than the rest is tested outside the tree, with the same hits",
         "[ch03][ex3.2]") {
    // POV-Ray keeps unbounded objects out of its bounding hierarchy; raybook keeps out an
    // instance whose box has kLargeInstanceArea times the area of the box around the others
    // (chapter 3, "Two levels and instancing": spheres.lua's render 490 -> 471 million
    // instructions, soft.lua's 2,340 -> 2,157 million at 256 x 256).
    const rb::Box box;
    const rb::Sphere sphere;
    rbtest::Rng rng(41);
    // The benchmark scenes' ground: a unit box scaled to 2e5 x 1 x 2e5, its top face at y = 0.
    const rb::Mat4 ground = glm::translate(rb::Mat4(1.0), Vec3(-1e5, -1, -1e5)) *
                            glm::scale(rb::Mat4(1.0), Vec3(2e5, 1, 2e5));
    // A tile whose top face is the ground's, so the two are hit at the same t.
    const rb::Mat4 tile = glm::translate(rb::Mat4(1.0), Vec3(-1, -0.5, -1)) *
                          glm::scale(rb::Mat4(1.0), Vec3(2, 0.5, 2));
    for (const bool tileFirst : {true, false}) {
        GIVEN(std::string("a ground plane, a flush tile ") + (tileFirst ? "before" : "after") +
              " it in the scene, and 12 spheres above it") {
            std::vector<rb::Instance> instances;
            if (tileFirst) instances.push_back(rbtest::makeInstance(box, tile));
            instances.push_back(rbtest::makeInstance(box, ground));
            if (!tileFirst) instances.push_back(rbtest::makeInstance(box, tile));
            for (int i = 0; i < 12; ++i)
                instances.push_back(rbtest::makeInstance(
                    sphere,
                    glm::translate(rb::Mat4(1.0), Vec3(rng.uniform(-4, 4), rng.uniform(1, 3),
                                                       rng.uniform(-4, 4)))));
            for (const NamedLayout& layout : layoutsHere()) {
                WHEN("the top level is built with --bvh=" + std::string(layout.name)) {
                    const rb::BVHAggregate bvh(instances, layout.layout);
                    THEN("the ground alone is kept out of the tree") {
                        CHECK(bvh.largeInstanceCount() == 1);
                        CHECK_THAT(bvh.statistics(),
                                   Catch::Contains("1 large instance outside the tree"));
                    }
                    THEN(
                        "2,000 camera and shadow rays find what testing every instance in scene "
                        "order finds") {
                        int mismatches = 0, ties = 0;
                        for (int k = 0; k < 1000; ++k) {
                            // Camera rays from above, most of them down onto the tile.
                            const rb::Ray down{
                                Vec3(rng.uniform(-2, 2), 6.0, rng.uniform(-2, 2)),
                                Vec3(rng.uniform(-0.2, 0.2), -1.0, rng.uniform(-0.2, 0.2))};
                            // Shadow rays from just above the ground towards a light.
                            const Vec3 from(rng.uniform(-6, 6), 1e-9, rng.uniform(-6, 6));
                            const rb::Ray up{from, Vec3(-5, 8, 6) - from};
                            for (const rb::Ray& ray : {down, up}) {
                                double tExpected;
                                const rb::Instance* expected =
                                    closestInSceneOrder(instances, ray, tExpected);
                                rb::Hit hit;
                                const bool found = bvh.intersect(ray, kInf, hit);
                                if (found != (expected != nullptr) ||
                                    (found && (hit.t != tExpected || hit.instance != expected)))
                                    ++mismatches;
                                if (bvh.occluded(ray, 1.0) !=
                                    (expected != nullptr && tExpected < 1.0))
                                    ++mismatches;
                                rb::ObjectHit onGround, onTile;
                                const rb::Instance& groundInstance = instances[tileFirst ? 1 : 0];
                                const rb::Instance& tileInstance = instances[tileFirst ? 0 : 1];
                                if (groundInstance.intersect(ray, kInf, onGround) &&
                                    tileInstance.intersect(ray, kInf, onTile) &&
                                    onGround.t == onTile.t)
                                    ++ties;
                            }
                        }
                        CHECK(mismatches == 0);
                        // The tie rule was put to work: rays met the tile and the ground at
                        // the same t.
                        CHECK(ties > 50);
                    }
                }
            }
        }
    }
    GIVEN("twelve spheres alone, none much larger than the box around the others") {
        std::vector<rb::Instance> instances;
        for (int i = 0; i < 12; ++i)
            instances.push_back(rbtest::makeInstance(
                sphere, glm::translate(rb::Mat4(1.0), Vec3(rng.uniform(-4, 4), rng.uniform(-4, 4),
                                                           rng.uniform(-4, 4)))));
        THEN("every one is in the tree") {
            CHECK(rb::BVHAggregate(instances).largeInstanceCount() == 0);
        }
    }
}

SCENARIO("a mesh is built once, however many nodes show it, with the layout --bvh asks for",
         "[ch03][ex3.2]") {
    GIVEN("a scene that names one OBJ file in two gr.mesh calls and shows it under 40 nodes") {
        rbtest::TempDir dir;
        dir.write("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 2 4\n");
        std::string lua =
            "root = gr.node('root')\n"
            "local a = gr.mesh('a', 'tri.obj')\n"
            "local b = gr.mesh('b', 'tri.obj')\n"
            "root:add_child(b)\n"
            "for i = 1, 40 do\n"
            "  local n = gr.node('n' .. i)\n"
            "  n:translate(2 * i, 0, 0)\n"
            "  n:add_child(a)\n"
            "  root:add_child(n)\n"
            "end\n" +
            rbtest::renderLine();
        const std::string scene = dir.write("scene.lua", lua);
        std::vector<std::pair<std::string, rb::BVHLayout>> layouts = {
            {"wide", rb::bestWideLayout()}};
        for (const NamedLayout& layout : layoutsHere())
            layouts.emplace_back(layout.name, layout.layout);
        for (const auto& [name, expected] : layouts) {
            WHEN("it is loaded with --bvh=" + name) {
                rb::SceneLoadOptions options;
                options.featureOptions["bvh"] = name;
                const auto renders = rb::loadScene(scene, rbtest::chapters(3), options);
                const auto& instances = renders.at(0).instances;
                THEN("all 41 instances share one mesh, built with that layout") {
                    REQUIRE(instances.size() == 41);
                    for (const rb::Instance& i : instances) CHECK(i.shape == instances[0].shape);
                    const rb::Mesh* mesh = instances[0].shape->triangleMesh();
                    REQUIRE(mesh != nullptr);
                    CHECK(mesh->bvh().layout() == expected);
                }
            }
        }
    }
}

SCENARIO("a mesh counts the work of its queries: nodes visited, packs filtered, exact tests",
         "[ch03][ex3.1]") {
    // The benchmarks (tests/perf/bvh_vs_embree --counts) report this work per ray. One triangle,
    // (0,0,0), (1,0,0), (0,1,0), makes a wide tree of one node whose one child is a leaf of one
    // pack, so every count is known from the construction: a query visits the root, tests the
    // leaf's box, and filters the pack if the box is entered. A ray down the z axis through the
    // triangle's interior point (1/4, 1/4) is a certain hit for the float test: its edge
    // functions are 1/4, 1/4 and 1/2 (twice the areas the point makes with the edges), far above
    // their error bound (of order 2⁻²⁰). So a closest-hit query runs the exact test once (it
    // must measure the hit), and a shadow query never (the float test answers).
    GIVEN("a mesh of one triangle, in every wide layout") {
        rb::ObjData data;
        data.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
        data.triangles.push_back({rb::ObjCorner{0}, rb::ObjCorner{1}, rb::ObjCorner{2}});
        for (const NamedLayout& layout : wideLayoutsHere()) {
            const rb::Mesh mesh(data, "triangle", layout.layout);
            CAPTURE(layout.name);
            REQUIRE(mesh.bvh().nodeCount() == 1);
            const rb::Ray through{Vec3(0.25, 0.25, 1.0), Vec3(0, 0, -1)};
            const rb::Ray beside{Vec3(5.0, 5.0, 1.0), Vec3(0, 0, -1)};
            WHEN("one closest-hit ray passes beside its box, another through the triangle") {
                rb::TraversalCounts besideCounts, throughCounts;
                rb::ObjectHit hit;
                const bool besideHits = mesh.intersect(beside, kInf, hit, besideCounts);
                const bool throughHits = mesh.intersect(through, kInf, hit, throughCounts);
                THEN(
                    "the first visits the root and filters nothing; the second visits the root, "
                    "filters the pack and measures the hit once") {
                    CHECK_FALSE(besideHits);
                    CHECK(besideCounts.nodes == 1);
                    CHECK(besideCounts.packs == 0);
                    CHECK(besideCounts.exactTests == 0);
                    CHECK(throughHits);
                    CHECK(hit.t == 1.0);
                    CHECK(throughCounts.nodes == 1);
                    CHECK(throughCounts.packs == 1);
                    CHECK(throughCounts.exactTests == 1);
                }
            }
            WHEN("a shadow ray passes through the triangle") {
                rb::TraversalCounts counts;
                THEN("the float test answers it: no exact test") {
                    CHECK(mesh.occluded(through, 2.0, counts));
                    CHECK(counts.nodes == 1);
                    CHECK(counts.packs == 1);
                    CHECK(counts.exactTests == 0);
                }
            }
            WHEN("both queries are counted into one tally") {
                rb::TraversalCounts counts;
                rb::ObjectHit hit;
                mesh.intersect(through, kInf, hit, counts);
                mesh.occluded(through, 2.0, counts);
                THEN("the tally is their sum") {
                    CHECK(counts.nodes == 2);
                    CHECK(counts.packs == 2);
                    CHECK(counts.exactTests == 1);
                }
            }
        }
    }
}

#if RB_HAVE_WIDE8
/// How many of `rays` WideRay8 prepares with other bits than WideRay (every value of every
/// lane, and the plane offsets, twice WideRay's). Compiled for AVX2; run only after the check.
[[gnu::target("avx2")]] int wideRay8Differences(const std::vector<rb::Ray>& rays) {
    int differences = 0;
    for (const rb::Ray& ray : rays) {
        const rb::WideRay w(ray);
        const rb::WideRay8 w8(ray);
        bool same = true;
        for (int axis = 0; axis < 3; ++axis) {
            const __m128* four[] = {&w.oNear[axis], &w.oFar[axis], &w.invDNear[axis],
                                    &w.invDFar[axis]};
            const __m256* eight[] = {&w8.oNear[axis], &w8.oFar[axis], &w8.invDNear[axis],
                                     &w8.invDFar[axis]};
            for (int value = 0; value < 4; ++value) {
                alignas(32) float a[4], b[8];
                _mm_store_ps(a, *four[value]);
                _mm256_store_ps(b, *eight[value]);
                for (int lane = 0; lane < 8; ++lane)
                    same &= std::memcmp(&a[lane % 4], &b[lane], sizeof(float)) == 0;
            }
            same &= w8.nearPlane[axis] == 2 * w.nearPlane[axis] &&
                    w8.farPlane[axis] == 2 * w.farPlane[axis];
        }
        differences += !same;
    }
    return differences;
}
#endif

SCENARIO("the eight-wide traversal prepares a ray exactly as the four-wide one does",
         "[ch03][stability]") {
    // WideRay8 computes the values of WideRay (origins moved outwards, reciprocals, the far
    // ones stretched, plane offsets by the direction's signs) for x, y and z at once instead of
    // axis by axis, with the same operations on the same numbers. So they must agree to the
    // bit, lane by lane, or the two paths could enter different boxes. The rays: origins and
    // directions of every size from 2⁻⁴⁰ to 2⁴⁰ and both signs, and directions with zero
    // components of either sign (infinite reciprocals), which pick their planes by the sign
    // of the zero.
    GIVEN("rays of every size and sign, some with ±0 direction components") {
        rbtest::Rng rng(41);
        std::vector<rb::Ray> rays;
        const auto any = [&] {
            const double sign = rng.uniform() < 0.5 ? -1.0 : 1.0;
            return sign * std::ldexp(rng.uniform(1.0, 2.0), static_cast<int>(rng.uniform(-40, 40)));
        };
        for (int k = 0; k < 20000; ++k) {
            Vec3 d(any(), any(), any());
            if (k % 4 == 1) d[k % 3] = (k / 4) % 2 ? -0.0 : 0.0;
            rays.push_back({Vec3(any(), any(), any()), d});
        }
        THEN("every value of every lane is WideRay's, bit for bit") {
#if RB_HAVE_WIDE8
            if (!rb::wide8Available())
                WARN("this CPU has no AVX2: WideRay8 is not checked here");
            else
                CHECK(wideRay8Differences(rays) == 0);
#else
            WARN("this build has no eight-wide path: WideRay8 is not checked here");
#endif
        }
    }
}
