/// \file
/// Chapter 14 tests: constructive solid geometry.
///
/// Chapter 14 claims that a solid is known along a line by its *crossings*, the places where
/// the line goes in and out, and that union, intersection and difference of two solids are
/// then one merge of two sorted lists: walk them in order, keep whether the line is inside A
/// and inside B, and keep a crossing exactly where the Boolean of the two states changes. The
/// tests prove it at three levels. On hand-made lists, the merge returns the intervals worked
/// out by hand for every operation (overlapping, nested and disjoint intervals), with the
/// normals of a difference's subtracted surfaces turned to point out of the result. On real
/// solids (spheres, boxes, a triangle mesh, groups and nested CSG nodes under rotations and
/// non-uniform scales) the crossings agree on thousands of random lines with an independent
/// point-membership test, and every normal points out. In the renderer, a lens made as the
/// intersection of two spheres focuses a paraxial ray where the thick-lens formula says, a
/// hollow glass shell (a difference of spheres) enters and leaves the medium stack at each of
/// its four surfaces, shadows see one solid, and each operand keeps its material. Stability:
/// coplanar faces make no surface inside the result, where A's and B's faces coincide the
/// result's surface there is A's (its material, normal and texture coordinates), and rays may
/// start inside any operand.
#include <catch2/catch.hpp>
#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/error.h"
#include "csg/csg.h"
#include "refraction/refraction.h"
#include "test_helpers.h"

using Catch::Contains;
using rb::Crossing;
using rb::CrossingList;
using rb::CsgOp;
using rb::Mat4;
using rb::Ray;
using rb::Vec3;

namespace {

/// Materials that only name an operand, so a crossing says where it came from.
const rb::Material kMatA{rb::Colour(1, 0, 0), rb::Colour(0), 1.0, {}};
const rb::Material kMatB{rb::Colour(0, 0, 1), rb::Colour(0), 1.0, {}};

/// The crossings of a solid made of the intervals [t0, t1] ∪ ..., each surface with normal
/// ±x (out of the solid for a line along +x) and the given material.
CrossingList intervals(const std::vector<std::pair<double, double>>& spans, const rb::Material* m) {
    CrossingList list;
    for (const auto& [t0, t1] : spans) {
        Crossing in{}, out{};
        in.hit.t = t0, in.hit.n = Vec3(-1, 0, 0), in.hit.material = m, in.entering = true;
        out.hit.t = t1, out.hit.n = Vec3(1, 0, 0), out.hit.material = m, out.entering = false;
        list.push(in);
        list.push(out);
    }
    return list;
}

/// The t of every crossing in a list.
std::vector<double> ts(const CrossingList& list) {
    std::vector<double> t;
    for (size_t i = 0; i < list.size(); ++i) t.push_back(list[i].hit.t);
    return t;
}

/// op(A, B) on lists.
CrossingList combine(CsgOp op, const CrossingList& a, const CrossingList& b) {
    CrossingList out;
    rb::combineCrossings(op, a, b, out);
    return out;
}

/// A CSG world built from Lua with every chapter up to 14.
std::unique_ptr<rb::World> csgWorld(const std::string& lua, const std::string& spec = "all") {
    return rbtest::worldFromLua(lua, rbtest::chapters(14, spec));
}

/// The crossings of a world-space line with a CSG instance, in world terms (t unchanged).
CrossingList worldCrossings(const rb::Instance& instance, const Ray& ray) {
    CrossingList list;
    const Ray local{rb::transformPoint(instance.worldToObject, ray.o),
                    rb::transformVector(instance.worldToObject, ray.d)};
    dynamic_cast<const rb::CsgShape&>(*instance.shape).crossings(local, list);
    for (size_t i = 0; i < list.size(); ++i)
        list[i].hit.n = glm::normalize(instance.normalToWorld * list[i].hit.n);
    return list;
}

}  // namespace

// [ch14-interval-tests]
SCENARIO("the interval algebra: union, intersection and difference of [1,4] and [2,6]",
         "[ch14][ex14.1][ex14.3][ex14.4]") {
    GIVEN("A = [1, 4] and B = [2, 6] along a line") {
        const CrossingList a = intervals({{1, 4}}, &kMatA), b = intervals({{2, 6}}, &kMatB);
        // Source: hand computation on the number line.
        THEN("A ∪ B = [1, 6], A ∩ B = [2, 4], A − B = [1, 2], B − A = [4, 6]") {
            CHECK(ts(combine(CsgOp::Union, a, b)) == std::vector<double>{1, 6});
            CHECK(ts(combine(CsgOp::Intersection, a, b)) == std::vector<double>{2, 4});
            CHECK(ts(combine(CsgOp::Difference, a, b)) == std::vector<double>{1, 2});
            CHECK(ts(combine(CsgOp::Difference, b, a)) == std::vector<double>{4, 6});
        }
        THEN("each surface of the result is the operand's that bounds it there") {
            const CrossingList d = combine(CsgOp::Difference, a, b);
            CHECK(d[0].hit.material == &kMatA);
            CHECK(d[1].hit.material == &kMatB);
            const CrossingList i = combine(CsgOp::Intersection, a, b);
            CHECK(i[0].hit.material == &kMatB);
            CHECK(i[1].hit.material == &kMatA);
        }
        THEN("A − B leaves the result where it enters B, with B's normal turned round") {
            const CrossingList d = combine(CsgOp::Difference, a, b);
            CHECK(d[0].entering);
            CHECK_FALSE(d[1].entering);
            // B's own normal at its entry is −x; out of the result (towards B) is +x.
            CHECK(d[1].hit.n == Vec3(1, 0, 0));
        }
    }
    GIVEN("A = [0, 10] with B = [2, 3] ∪ [5, 7] inside it") {
        const CrossingList a = intervals({{0, 10}}, &kMatA);
        const CrossingList b = intervals({{2, 3}, {5, 7}}, &kMatB);
        THEN("A − B has three pieces and A ∩ B is B, A ∪ B is A") {
            CHECK(ts(combine(CsgOp::Difference, a, b)) == std::vector<double>{0, 2, 3, 5, 7, 10});
            CHECK(ts(combine(CsgOp::Intersection, a, b)) == std::vector<double>{2, 3, 5, 7});
            CHECK(ts(combine(CsgOp::Union, a, b)) == std::vector<double>{0, 10});
        }
        THEN("the hollows' surfaces face into the hollows") {
            const CrossingList d = combine(CsgOp::Difference, a, b);
            for (size_t k = 1; k + 1 < d.size(); ++k)
                CHECK(d[k].hit.n.x == (d[k].entering ? -1.0 : 1.0));
        }
    }
    GIVEN("disjoint A = [0, 1] and B = [2, 3], and an empty B") {
        const CrossingList a = intervals({{0, 1}}, &kMatA), b = intervals({{2, 3}}, &kMatB);
        const CrossingList none{};
        THEN("the union keeps both, the intersection is empty, the difference is A") {
            CHECK(ts(combine(CsgOp::Union, a, b)) == std::vector<double>{0, 1, 2, 3});
            CHECK(combine(CsgOp::Intersection, a, b).empty());
            CHECK(ts(combine(CsgOp::Difference, a, b)) == std::vector<double>{0, 1});
            CHECK(ts(combine(CsgOp::Difference, a, none)) == std::vector<double>{0, 1});
            CHECK(combine(CsgOp::Intersection, a, none).empty());
            CHECK(combine(CsgOp::Difference, none, a).empty());
        }
    }
}
// [ch14-interval-tests]

SCENARIO("the membership rule of each operation is its Boolean", "[ch14][ex14.1]") {
    // Source: the definitions A ∪ B, A ∩ B, A − B = A ∩ complement(B).
    for (int a = 0; a < 2; ++a)
        for (int b = 0; b < 2; ++b) {
            CHECK(rb::csgInside(CsgOp::Union, a, b) == (a || b));
            CHECK(rb::csgInside(CsgOp::Intersection, a, b) == (a && b));
            CHECK(rb::csgInside(CsgOp::Difference, a, b) == (a && !b));
        }
}

// [ch14-sphere-crossings]
SCENARIO("a line crosses the unit sphere twice, entering then leaving, with outward normals",
         "[ch14][ex14.2]") {
    GIVEN("the line (0.3, −0.2, −5) + t·(0, 0, 2)") {
        const Ray ray{Vec3(0.3, -0.2, -5.0), Vec3(0.0, 0.0, 2.0)};
        CrossingList out;
        rb::sphereCrossings(ray, out);
        THEN("it enters at t = (5 − √0.87)/2 and leaves at t = (5 + √0.87)/2") {
            // Source: x² + y² = 0.13 along the line, so z = −5 + 2t = ±√0.87 on the sphere;
            // the point on the unit sphere is its own outward normal.
            const double z = std::sqrt(0.87);
            INFO("expected two crossings, entering then leaving, at t = "
                 << (5.0 - z) / 2.0 << " and " << (5.0 + z) / 2.0 << "; got " << out.size());
            REQUIRE(out.size() == 2);
            CHECK(out[0].entering);
            CHECK_FALSE(out[1].entering);
            CHECK(out[0].hit.t == Approx((5.0 - z) / 2.0).epsilon(1e-14));
            CHECK(out[1].hit.t == Approx((5.0 + z) / 2.0).epsilon(1e-14));
            CHECK(glm::length(out[0].hit.n - Vec3(0.3, -0.2, -z)) < 1e-14);
            CHECK(glm::length(out[1].hit.n - Vec3(0.3, -0.2, z)) < 1e-14);
        }
    }
    GIVEN("a line from inside the sphere, (0, 0, 0.5) + t·(1, 0, 0)") {
        CrossingList out;
        rb::sphereCrossings(Ray{Vec3(0.0, 0.0, 0.5), Vec3(1.0, 0.0, 0.0)}, out);
        THEN("the whole line counts: it entered behind the origin, at t = −√0.75") {
            // Source: x² = 1 − 0.25 on the sphere.
            INFO("expected crossings at t = ±√0.75 = ±" << std::sqrt(0.75) << "; got " << out.size()
                                                        << " crossings");
            REQUIRE(out.size() == 2);
            CHECK(out[0].entering);
            CHECK(out[0].hit.t == Approx(-std::sqrt(0.75)).epsilon(1e-14));
            CHECK(out[1].hit.t == Approx(std::sqrt(0.75)).epsilon(1e-14));
        }
    }
    GIVEN("a line that misses the sphere and one that only touches it") {
        CrossingList missed, touched;
        rb::sphereCrossings(Ray{Vec3(0.0, 2.0, -5.0), Vec3(0.0, 0.0, 1.0)}, missed);
        rb::sphereCrossings(Ray{Vec3(0.0, 1.0, -5.0), Vec3(0.0, 0.0, 1.0)}, touched);
        THEN("neither crosses it: a double root touches the solid without entering it") {
            CHECK(missed.empty());
            CHECK(touched.empty());
        }
    }
}
// [ch14-sphere-crossings]

// [ch14-orient-alone]
SCENARIO("a kept crossing's normal turns round where operand and result differ in direction",
         "[ch14][ex14.3]") {
    GIVEN("B's leaving crossing at t = 2 with its outward normal +z") {
        Crossing c;
        c.hit.t = 2.0;
        c.hit.n = Vec3(0.0, 0.0, 1.0);
        c.entering = false;
        WHEN("it is where A − B is entered (B left, A still inside)") {
            Crossing kept = c;
            rb::orientToResult(kept, true);
            THEN("the result is entered there, and its normal is −z: B's turned round") {
                // Source: the chapter's rule n_result = −n where the directions differ.
                INFO("expected entering with the normal (0, 0, −1), got the normal ("
                     << kept.hit.n.x << ", " << kept.hit.n.y << ", " << kept.hit.n.z << ")");
                CHECK(kept.entering);
                CHECK(kept.hit.n == Vec3(0.0, 0.0, -1.0));
            }
        }
        WHEN("it is where a union is left (B left, A outside)") {
            Crossing kept = c;
            rb::orientToResult(kept, false);
            THEN("the directions agree, and the normal stays +z") {
                CHECK_FALSE(kept.entering);
                CHECK(kept.hit.n == Vec3(0.0, 0.0, 1.0));
                CHECK(kept.hit.t == 2.0);
            }
        }
    }
}
// [ch14-orient-alone]

SCENARIO("a hollow shell, a difference of two transformed spheres, has four crossings",
         "[ch14][ex14.1][ex14.2][ex14.3][ex14.4]") {
    GIVEN("gr.difference of a sphere of radius 2 and one of radius 1, both centred at (1, 0, 0)") {
        auto world = csgWorld(R"(
            local outer = gr.sphere('outer'); outer:scale(2, 2, 2)
            local inner = gr.sphere('inner')
            local shell = gr.difference(outer, inner)
            shell:translate(1, 0, 0)
            root = gr.node('root'); root:add_child(shell)
        )" + rbtest::renderLine());
        REQUIRE(world->scene.instances.size() == 1);
        WHEN("a line along +x from x = −9 crosses it") {
            const CrossingList c =
                worldCrossings(world->scene.instances[0], Ray{{-9, 0, 0}, {1, 0, 0}});
            // Source: surfaces at x = 1 ∓ 2 and 1 ∓ 1, i.e. t = 8, 9, 11, 12.
            THEN("it enters at t = 8, leaves at 9, enters at 11 and leaves at 12") {
                REQUIRE(c.size() == 4);
                const double expected[4] = {8, 9, 11, 12};
                for (int k = 0; k < 4; ++k) {
                    CHECK(c[k].hit.t == Approx(expected[k]).epsilon(1e-12));
                    CHECK(c[k].entering == (k % 2 == 0));
                }
            }
            THEN("every normal points out of the shell: into the hollow on the inner sphere") {
                CHECK(c[0].hit.n.x == Approx(-1.0));
                CHECK(c[1].hit.n.x == Approx(1.0));  // the inner sphere's −x normal turned round
                CHECK(c[2].hit.n.x == Approx(-1.0));
                CHECK(c[3].hit.n.x == Approx(1.0));
            }
        }
    }
}

namespace {

/// An independent description of a solid for point membership: a leaf shape under a
/// transform, or an operation on two solids.
struct Solid {
    enum Kind { Ball, Cube, Op } kind;
    Mat4 toObject{1.0};  ///< World (CSG) space to the leaf's space.
    CsgOp op = CsgOp::Union;
    std::shared_ptr<Solid> a, b;

    /// True when p is strictly inside (the membership test the crossings must agree with).
    bool contains(const Vec3& p) const {
        if (kind == Op) return rb::csgInside(op, a->contains(p), b->contains(p));
        const Vec3 q = rb::transformPoint(toObject, p);
        if (kind == Ball) return glm::dot(q, q) < 1.0;
        return q.x > 0 && q.x < 1 && q.y > 0 && q.y < 1 && q.z > 0 && q.z < 1;
    }
};

/// A random rotation, non-uniform scale and translation.
Mat4 randomPlacement(rbtest::Rng& rng) {
    Mat4 m =
        glm::translate(Mat4(1.0), Vec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)));
    m = glm::rotate(m, rng.uniform(0, 6.28), rng.unitVector());
    return glm::scale(m, Vec3(rng.uniform(0.5, 1.5), rng.uniform(0.5, 1.5), rng.uniform(0.5, 1.5)));
}

/// A random CSG tree of the given depth over spheres, boxes and a box-shaped triangle mesh,
/// built twice: as a Solid for membership, and as CsgShape leaves (shapes kept in `keep`).
std::pair<std::shared_ptr<Solid>, rb::CsgLeaf> randomTree(
    int depth, rbtest::Rng& rng, std::vector<std::shared_ptr<const rb::Shape>>& keep,
    std::vector<rb::Instance>& leaves) {
    static const rb::Sphere sphere;
    static const rb::Box box;
    static const auto mesh = rbtest::makeMesh(
        {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}},
        {{0, 2, 1},
         {0, 3, 2},
         {4, 5, 6},
         {4, 6, 7},
         {0, 1, 5},
         {0, 5, 4},
         {3, 7, 6},
         {3, 6, 2},
         {0, 4, 7},
         {0, 7, 3},
         {1, 2, 6},
         {1, 6, 5}});
    auto solid = std::make_shared<Solid>();
    if (depth == 0) {
        const Mat4 m = randomPlacement(rng);
        const int kind = static_cast<int>(rng.uniform() * 3);
        solid->kind = kind == 0 ? Solid::Ball : Solid::Cube;
        solid->toObject = glm::inverse(m);
        const rb::Shape& shape = kind == 0   ? static_cast<const rb::Shape&>(sphere)
                                 : kind == 1 ? static_cast<const rb::Shape&>(box)
                                             : static_cast<const rb::Shape&>(*mesh);
        leaves.push_back(rbtest::makeInstance(shape, m));
        return {solid, rb::CsgLeaf::from(leaves.back())};
    }
    solid->kind = Solid::Op;
    solid->op = static_cast<CsgOp>(static_cast<int>(rng.uniform() * 3));
    auto [sa, la] = randomTree(depth - 1, rng, keep, leaves);
    auto [sb, lb] = randomTree(depth - 1, rng, keep, leaves);
    solid->a = sa, solid->b = sb;
    auto shape = std::make_shared<const rb::CsgShape>(solid->op, la, lb);
    keep.push_back(shape);
    leaves.push_back(rbtest::makeInstance(*shape, Mat4(1.0)));
    return {solid, rb::CsgLeaf::from(leaves.back())};
}

}  // namespace

// [ch14-membership-test]
SCENARIO("crossings agree with point membership on random lines through random CSG trees",
         "[ch14][ex14.1][ex14.2][ex14.3][ex14.4]") {
    rbtest::Rng rng(rbtest::seedFromEnv("RB_CH14_SEED"));
    int checkedPoints = 0, checkedNormals = 0, nonEmpty = 0;
    for (int tree = 0; tree < 40; ++tree) {
        std::vector<std::shared_ptr<const rb::Shape>> keep;
        std::vector<rb::Instance> leaves;
        leaves.reserve(64);  // CsgLeaf::from reads them; they must not move
        const int depth = 1 + tree % 3;
        auto [solid, leaf] = randomTree(depth, rng, keep, leaves);
        for (int line = 0; line < 100; ++line) {
            // From a sphere of radius 3 towards a random point of the region the leaves sit in,
            // with a direction of random length (t is then not a distance).
            const Vec3 o = 3.0 * rng.unitVector();
            const Vec3 target(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
            const Ray ray{o, (target - o) * rng.uniform(0.2, 2.0)};
            CrossingList c;
            leaf.crossings(ray, c);
            if (!c.empty()) ++nonEmpty;
            INFO("tree " << tree << " line " << line);
            // Crossings come in increasing t and alternate, starting by entering.
            for (size_t k = 0; k < c.size(); ++k) {
                REQUIRE(c[k].entering == (k % 2 == 0));
                if (k > 0) REQUIRE(c[k].hit.t >= c[k - 1].hit.t);
            }
            REQUIRE(c.size() % 2 == 0);
            // Between consecutive crossings (and before and after them) the parity is the
            // membership; skip gaps too thin to sample reliably.
            std::vector<double> t = {-1e3};
            for (size_t k = 0; k < c.size(); ++k) t.push_back(c[k].hit.t);
            t.push_back(1e3);
            for (size_t k = 0; k + 1 < t.size(); ++k) {
                if (t[k + 1] - t[k] < 1e-6) continue;
                const Vec3 p = ray.o + 0.5 * (t[k] + t[k + 1]) * ray.d;
                CHECK(solid->contains(p) == (k % 2 == 1));
                ++checkedPoints;
            }
            // Every normal points out of the result: just outside along it, just inside against.
            for (size_t k = 0; k < c.size(); ++k) {
                const Vec3 p = ray.o + c[k].hit.t * ray.d;
                const Vec3 n = glm::normalize(c[k].hit.n);
                const double eps = 1e-7;
                if (std::abs(glm::dot(n, glm::normalize(ray.d))) < 0.05) continue;  // near grazing
                const bool outside = !solid->contains(p + eps * n),
                           inside = solid->contains(p - eps * n);
                if (outside && inside) ++checkedNormals;
                CHECK(!(solid->contains(p + eps * n) && !solid->contains(p - eps * n)));
            }
        }
    }
    INFO(nonEmpty << " lines met a solid, " << checkedPoints << " points, " << checkedNormals
                  << " normals checked");
    CHECK(nonEmpty > 500);  // enough lines meet a solid for the test to mean something
    CHECK(checkedPoints > 3000);
    CHECK(checkedNormals > 1000);
}
// [ch14-membership-test]

SCENARIO("operands may be groups, transformed hierarchies and other CSG nodes",
         "[ch14][ex14.1][ex14.2][ex14.3][ex14.4]") {
    GIVEN("a group of two unit cubes side by side, minus a nested CSG node") {
        // Operand A: cubes [0,1]³ and [1,2]×[0,1]² in a group moved by (−1, 0, 0).
        // Operand B: (sphere r=0.5 at (0.5, 0.5, 0.5)) ∪ (sphere r=0.5 at (−0.5, 0.5, 0.5)),
        // i.e. balls centred in each cube (in the group's frame, x = 0.5 and 1.5, moved by −1).
        auto world = csgWorld(R"(
            local group = gr.node('pair')
            local c1 = gr.cube('c1'); group:add_child(c1)
            local c2 = gr.cube('c2'); c2:translate(1, 0, 0); group:add_child(c2)
            group:translate(-1, 0, 0)
            local b1 = gr.nh_sphere('b1', {-0.5, 0.5, 0.5}, 0.5)
            local b2 = gr.nh_sphere('b2', {0.5, 0.5, 0.5}, 0.5)
            local cut = gr.difference(group, gr.union(b1, b2))
            root = gr.node('root'); root:add_child(cut)
        )" + rbtest::renderLine());
        WHEN("a line along +x at y = z = 0.5 crosses it") {
            const CrossingList c =
                worldCrossings(world->scene.instances[0], Ray{{-5, 0.5, 0.5}, {1, 0, 0}});
            // Source: solid from x = −1 to 1 with hollow balls [−1, 0] and [0, 1] cut away:
            // the balls touch at x = 0 and fill the line, so nothing is left but the two
            // single points x = −1 and x = 1, which are no solid.
            THEN("nothing is left along it") {
                CHECK(c.empty());
            }
        }
        WHEN("a line along +x at y = 0.5, z = 0.1 (below the balls' reach at x = ±0.5 ± 0.3)") {
            const CrossingList c =
                worldCrossings(world->scene.instances[0], Ray{{-5, 0.5, 0.1}, {1, 0, 0}});
            // Source: each ball meets the line where (x − cx)² + 0.4² = 0.25, x = cx ± 0.3.
            THEN("the solid is [−1, −0.8] ∪ [−0.2, 0.2] ∪ [0.8, 1]") {
                REQUIRE(c.size() == 6);
                const double expected[6] = {-1, -0.8, -0.2, 0.2, 0.8, 1};
                for (int k = 0; k < 6; ++k)
                    CHECK(c[k].hit.t - 5 == Approx(expected[k]).margin(1e-12));
            }
        }
    }
    GIVEN("seed 001's form with a hierarchical right operand: a:csg(group, 'd')") {
        auto world = csgWorld(R"(
            local a = gr.cube('a'); a:scale(4, 1, 1)
            local holes = gr.node('holes')
            local h1 = gr.cube('h1'); h1:scale(0.25, 1, 1); h1:translate(0.25, 0, 0)
            local h2 = gr.cube('h2'); h2:scale(0.25, 1, 1); h2:translate(0.75, 0, 0)
            holes:add_child(h1); holes:add_child(h2)
            root = gr.node('root'); root:add_child(a)
            a:csg(holes, 'd')
            a:translate(1, 0, 0)  -- after the call: moves the result
        )" + rbtest::renderLine());
        REQUIRE(world->scene.instances.size() == 1);
        WHEN("a line along +x crosses it") {
            const CrossingList c =
                worldCrossings(world->scene.instances[0], Ray{{0, 0.5, 0.5}, {1, 0, 0}});
            // Source: the scale written before the call stretches operand A only, so the
            // bar [0, 4] loses the holes [0.25, 0.5] and [0.75, 1] placed beside it.
            THEN("the bar keeps [0, 0.25], [0.5, 0.75] and [1, 4]") {
                REQUIRE(c.size() == 6);
                const double expected[6] = {0, 0.25, 0.5, 0.75, 1, 4};
                for (int k = 0; k < 6; ++k)
                    CHECK(c[k].hit.t - 1 == Approx(expected[k]).margin(1e-12));
            }
        }
    }
}

SCENARIO("each operand keeps its own material, and inherits the node's when it has none",
         "[ch14][ex14.1][ex14.2][ex14.3][ex14.4]") {
    auto world = csgWorld(R"(
        local red = gr.material({1, 0, 0}, {0, 0, 0}, 1)
        local blue = gr.material({0, 0, 1}, {0, 0, 0}, 1)
        local green = gr.material({0, 1, 0}, {0, 0, 0}, 1)
        local block = gr.cube('block'); block:translate(-0.5, -0.5, -0.5); block:scale(2, 2, 2)
        block:set_material(red)
        local bite = gr.sphere('bite'); bite:translate(1, 0, 0); bite:set_material(blue)
        local third = gr.nh_box('third', {-3, -0.2, -0.2}, 0.4)
        local d = gr.union(gr.difference(block, bite), third)
        d:set_material(green)
        root = gr.node('root'); root:add_child(d)
    )" + rbtest::renderLine());
    const rb::Instance& inst = world->scene.instances[0];
    rb::Hit hit;
    REQUIRE(world->scene.aggregate->intersect(Ray{{-9, 0, 0}, {1, 0, 0}}, 1e9, hit));
    CHECK(hit.p.x == Approx(-3.0));
    CHECK(hit.material->kd == rb::Colour(0, 1, 0));  // the third box has none: the node's
    REQUIRE(world->scene.aggregate->intersect(Ray{{-1.5, 0.5, 0.5}, {1, 0, 0}}, 1e9, hit));
    CHECK(hit.p.x == Approx(-1.0));
    CHECK(hit.material->kd == rb::Colour(1, 0, 0));  // the block's face at x = −1
    REQUIRE(world->scene.aggregate->intersect(Ray{{5, 0, 0}, {-1, 0, 0}}, 1e9, hit));
    CHECK(hit.material->kd == rb::Colour(0, 0, 1));  // the bite's surface at x = 0
    CHECK(hit.t == Approx(5.0));
    CHECK(hit.ng.x == Approx(1.0));  // facing out of the result, towards the ray
    CHECK(hit.instance == &inst);
}

// [ch14-lens-test]
SCENARIO("a lens made as the intersection of two spheres focuses like a thick lens",
         "[ch14][ex14.1][ex14.2][ex14.3][ex14.4]") {
    GIVEN("two unit spheres centred at z = ±0.8 intersected, of glass n = 1.5") {
        // The lens is biconvex with R₁ = 1, R₂ = −1 and thickness d = 2·(1 − 0.8) = 0.4.
        auto world = csgWorld(R"(
            local glass = gr.material{kd = {0, 0, 0}, transparency = 1, ior = 1.5}
            local s1 = gr.sphere('s1'); s1:translate(0, 0, 0.8)
            local s2 = gr.sphere('s2'); s2:translate(0, 0, -0.8)
            local lens = gr.intersection(s1, s2); lens:set_material(glass)
            root = gr.node('root'); root:add_child(lens)
        )" + rbtest::renderLine());
        WHEN("a paraxial ray at height h = 0.01 along −z passes through it") {
            const double n = 1.5, R = 1.0, d = 0.4, h = 0.01;
            Ray ray{{h, 0, 10}, {0, 0, -1}};
            rb::MediumStack media;
            for (int surface = 0; surface < 2; ++surface) {
                rb::Hit hit;
                REQUIRE(world->scene.aggregate->intersect(ray, 1e9, hit));
                const rb::DielectricSplit s = rb::splitAtDielectric(
                    glm::normalize(ray.d), hit, n, media, rb::FresnelFormula::Exact);
                REQUIRE_FALSE(s.totalInternalReflection);
                CHECK(s.media.entering == (surface == 0));
                media = s.media.beyond;
                ray = Ray{rb::offsetRayOrigin(hit.p, hit.ng, s.transmitted), s.transmitted};
            }
            // Source: the thick-lens (lensmaker's) equation,
            // 1/f = (n − 1)·(1/R₁ − 1/R₂ + (n − 1)·d / (n·R₁·R₂)), and the back focal distance
            // BFD = f·(1 − (n − 1)·d / (n·R₁)); Hecht, Optics, 4th ed., §6.1. Here f
            // = 15/14 and BFD = 13/14; the paraxial error at h/R = 0.01 is O((h/R)²).
            const double R1 = R, R2 = -R;
            const double f = 1.0 / ((n - 1) * (1 / R1 - 1 / R2 + (n - 1) * d / (n * R1 * R2)));
            const double bfd = f * (1 - (n - 1) * d / (n * R1));
            THEN("it leaves the stack empty and crosses the axis at the back focal distance") {
                CHECK(media.size == 0);
                const double tAxis = -ray.o.x / ray.d.x;
                const double zFocus = ray.o.z + tAxis * ray.d.z;
                CHECK(-d / 2 - zFocus == Approx(bfd).epsilon(1e-3));
                CHECK(bfd == Approx(13.0 / 14.0));
            }
        }
    }
}
// [ch14-lens-test]

SCENARIO("a hollow glass shell enters and leaves the medium stack at each of its surfaces",
         "[ch14][ex14.1][ex14.2][ex14.3][ex14.4]") {
    auto world = csgWorld(R"(
        local glass = gr.material{kd = {0, 0, 0}, transparency = 1, ior = 1.5}
        local outer = gr.sphere('outer'); outer:scale(2, 2, 2)
        local shell = gr.difference(outer, gr.sphere('inner')); shell:set_material(glass)
        root = gr.node('root'); root:add_child(shell)
    )" + rbtest::renderLine());
    Ray ray{{-9, 0, 0}, {1, 0, 0}};
    rb::MediumStack media;
    const bool entering[4] = {true, false, true, false};
    const double eta_i[4] = {1.0, 1.5, 1.0, 1.5}, eta_t[4] = {1.5, 1.0, 1.5, 1.0};
    const double xs[4] = {-2, -1, 1, 2};
    for (int k = 0; k < 4; ++k) {
        rb::Hit hit;
        REQUIRE(world->scene.aggregate->intersect(ray, 1e9, hit));
        CHECK(hit.p.x == Approx(xs[k]));
        const rb::DielectricSplit s =
            rb::splitAtDielectric(ray.d, hit, 1.5, media, rb::FresnelFormula::Exact);
        CHECK(s.media.entering == entering[k]);
        CHECK(s.media.eta_i == eta_i[k]);
        CHECK(s.media.eta_t == eta_t[k]);
        media = s.media.beyond;
        ray = Ray{rb::offsetRayOrigin(hit.p, hit.ng, s.transmitted), s.transmitted};
    }
    rb::Hit none;
    CHECK_FALSE(world->scene.aggregate->intersect(ray, 1e9, none));
    CHECK(media.size == 0);
}

SCENARIO("shadows see the result as one solid", "[ch14][ex14.1][ex14.2][ex14.3][ex14.4]") {
    auto world = csgWorld(R"(
        local outer = gr.sphere('outer'); outer:scale(2, 2, 2)
        local shell = gr.difference(outer, gr.sphere('inner'))
        local block = gr.cube('block'); block:translate(-0.5, -0.5, -0.5); block:scale(2, 2, 2)
        local bitten = gr.difference(block, gr.nh_sphere('bite', {1, 0, 0}, 1.5))
        bitten:translate(10, 0, 0)
        root = gr.node('root'); root:add_child(shell); root:add_child(bitten)
    )" + rbtest::renderLine());
    const rb::Aggregate& scene = *world->scene.aggregate;
    THEN("a point in the hollow is shadowed from outside, by the shell alone") {
        CHECK(scene.occluded(Ray{{0, 0, 0}, {0, 1, 0}}, 10.0));
        // Between the hollow's centre and its own wall there is nothing.
        CHECK_FALSE(scene.occluded(Ray{{0, 0, 0}, {0, 1, 0}}, 0.9));
    }
    THEN("a ray through the bitten-out part passes, though it crosses the bite's sphere") {
        // Along y at x = 10.9, z = 0: inside the block's x range [9, 11], but the bite
        // (centre x = 11, radius 1.5) removed all of |y| ≤ 1 there: 0.1² + 1² < 1.5².
        CHECK_FALSE(scene.occluded(Ray{{10.9, -5, 0}, {0, 1, 0}}, 10.0));
        // At x = 9.2 the bite is 1.8 away: the block is whole.
        CHECK(scene.occluded(Ray{{9.2, -5, 0}, {0, 1, 0}}, 10.0));
    }
}

SCENARIO("a ray that starts inside an operand finds the result's surface",
         "[ch14][stability][ex14.1][ex14.2][ex14.3][ex14.4]") {
    auto world = csgWorld(R"(
        local outer = gr.sphere('outer'); outer:scale(2, 2, 2)
        local shell = gr.difference(outer, gr.sphere('inner'))
        root = gr.node('root'); root:add_child(shell)
    )" + rbtest::renderLine());
    rb::Hit hit;
    WHEN("it starts in the hollow (inside both spheres, outside the result)") {
        REQUIRE(world->scene.aggregate->intersect(Ray{{0.2, 0, 0}, {1, 0, 0}}, 1e9, hit));
        THEN("it meets the inner wall at x = 1, facing it") {
            CHECK(hit.p.x == Approx(1.0));
            CHECK(hit.ng.x == Approx(-1.0));
        }
    }
    WHEN("it starts in the glass of the shell (inside the outer sphere only)") {
        REQUIRE(world->scene.aggregate->intersect(Ray{{1.5, 0, 0}, {1, 0, 0}}, 1e9, hit));
        THEN("it leaves at x = 2, through a normal pointing away from the solid") {
            CHECK(hit.p.x == Approx(2.0));
            CHECK(hit.ng.x == Approx(1.0));
        }
        AND_WHEN("it goes the other way") {
            REQUIRE(world->scene.aggregate->intersect(Ray{{1.5, 0, 0}, {-1, 0, 0}}, 1e9, hit));
            THEN("it leaves into the hollow at x = 1") {
                CHECK(hit.p.x == Approx(1.0));
                CHECK(hit.ng.x == Approx(-1.0));
            }
        }
    }
}

// [ch14-coplanar-test]
SCENARIO("coplanar faces make no surface inside the result, under any rotation",
         "[ch14][stability][ex14.1][ex14.3][ex14.4]") {
    rbtest::Rng rng(rbtest::seedFromEnv("RB_CH14_SEED") + 1);
    int spurious = 0, lines = 0, flush = 0;
    for (int trial = 0; trial < 200; ++trial) {
        // One random placement for both operands, so their shared faces stay shared in exact
        // arithmetic while rounding differs.
        const Mat4 m = randomPlacement(rng);
        const auto at = [&](const Mat4& local) { return m * local; };
        static const rb::Box box;
        // Union of [0,1]³ and [1,2]×[0,1]²: touching at x = 1.
        std::vector<rb::Instance> leaves;
        leaves.reserve(4);
        leaves.push_back(rbtest::makeInstance(box, at(Mat4(1.0))));
        leaves.push_back(rbtest::makeInstance(box, at(glm::translate(Mat4(1.0), Vec3(1, 0, 0)))));
        // [0,1]³ minus [0,1]×[0.5,1.5]×[0,1]: B flush with A's faces x = 0, x = 1 and z = 0, 1.
        leaves.push_back(rbtest::makeInstance(box, at(Mat4(1.0))));
        leaves.push_back(rbtest::makeInstance(box, at(glm::translate(Mat4(1.0), Vec3(0, 0.5, 0)))));
        const rb::CsgShape joined(CsgOp::Union, rb::CsgLeaf::from(leaves[0]),
                                  rb::CsgLeaf::from(leaves[1]));
        const rb::CsgShape cut(CsgOp::Difference, rb::CsgLeaf::from(leaves[2]),
                               rb::CsgLeaf::from(leaves[3]));
        // A line along the local x axis through the shared face, and one through B's flush part.
        const double y = rng.uniform(0.05, 0.45), z = rng.uniform(0.05, 0.95);
        const Ray along{rb::transformPoint(m, Vec3(-1, y, z)),
                        rb::transformVector(m, Vec3(1, 0, 0))};
        const Ray flushLine{rb::transformPoint(m, Vec3(-1, y + 0.5, z)),
                            rb::transformVector(m, Vec3(1, 0, 0))};
        CrossingList c;
        joined.crossings(along, c);
        ++lines;
        // Source: [0,1] ∪ [1,2] = [0,2] along the line: entry at t = 1, exit at t = 3.
        if (c.size() != 2)
            ++spurious;
        else {
            CHECK(c[0].hit.t == Approx(1.0));
            CHECK(c[1].hit.t == Approx(3.0));
        }
        cut.crossings(flushLine, c);
        // Source: at height y + 0.5 ∈ (0.5, 1) the line is inside B wherever it is inside A.
        if (!c.empty()) ++spurious;
        ++flush;
    }
    INFO(spurious << " spurious surfaces on " << lines + flush << " lines");
    CHECK(spurious == 0);
}
// [ch14-coplanar-test]

namespace {

/// Check one crossing of a result: where, which way, and whose surface (material, normal, uv).
void checkSurface(const Crossing& c, double t, bool entering, const rb::Material* material,
                  const Vec3& n, const rb::Vec2& uv) {
    INFO("the crossing expected at t = " << t << (entering ? ", entering" : ", leaving"));
    CHECK(c.hit.t == Approx(t));
    CHECK(c.entering == entering);
    CHECK(c.hit.material == material);
    CHECK(glm::length(c.hit.n - n) < 1e-12);
    CHECK(glm::length(c.hit.uv - uv) < 1e-12);
}

}  // namespace

// [ch14-tie-test]
SCENARIO(
    "where A's and B's faces coincide the result reports A's, and B's only where B alone bounds it",
    "[ch14][ex14.1][ex14.3][ex14.4]") {
    static const rb::Box box;
    // A is the unit cube [0,1]³. Each B is a cube stretched to 2 in y and z, so that on the
    // faces x = 0 and x = 1 its texture coordinates (y/2, z/2) differ from A's (y, z).
    const rb::Instance a = rbtest::makeInstance(box, Mat4(1.0), &kMatA);
    const auto cubeB = [](double x0) {
        return rbtest::makeInstance(
            box, glm::scale(glm::translate(Mat4(1.0), Vec3(x0, 0, 0)), Vec3(1, 2, 2)), &kMatB);
    };
    const auto crossings = [](CsgOp op, const rb::Instance& first, const rb::Instance& second,
                              const Ray& ray) {
        CrossingList list;
        rb::CsgShape(op, rb::CsgLeaf::from(first), rb::CsgLeaf::from(second)).crossings(ray, list);
        return list;
    };
    // Lines along +x and −x through y = 0.25, z = 0.5, at x = −2 and x = 3 when t = 0.
    const Ray forward{Vec3(-2, 0.25, 0.5), Vec3(1, 0, 0)};
    const Ray backward{Vec3(3, 0.25, 0.5), Vec3(-1, 0, 0)};
    // Source: the box's face x = c has uv = (y, z) in its object space; B's object y, z are
    // half the world's.
    const rb::Vec2 uvA(0.25, 0.5), uvB(0.125, 0.25);
    const Vec3 minusX(-1, 0, 0), plusX(1, 0, 0);
    GIVEN("B = [0,1] × [0,2]², sharing A's faces x = 0 and x = 1") {
        const rb::Instance b = cubeB(0.0);
        WHEN("they are intersected: entering needs both operands there, leaving either one") {
            const CrossingList c = crossings(CsgOp::Intersection, a, b, forward);
            THEN("both surfaces of A ∩ B = [0, 1] are A's: its material, normal and uv") {
                REQUIRE(c.size() == 2);
                checkSurface(c[0], 2, true, &kMatA, minusX, uvA);
                checkSurface(c[1], 3, false, &kMatA, plusX, uvA);
            }
        }
        WHEN("they are united: entering needs either operand there, leaving both") {
            const CrossingList c = crossings(CsgOp::Union, a, b, forward);
            THEN("both surfaces of A ∪ B = [0, 1] are A's") {
                REQUIRE(c.size() == 2);
                checkSurface(c[0], 2, true, &kMatA, minusX, uvA);
                checkSurface(c[1], 3, false, &kMatA, plusX, uvA);
            }
        }
        WHEN("the operands are swapped, B ∩ A and B ∪ A") {
            THEN("both surfaces are B's: the first operand wins a tie, whatever it is") {
                for (const CsgOp op : {CsgOp::Intersection, CsgOp::Union}) {
                    const CrossingList c = crossings(op, b, a, forward);
                    REQUIRE(c.size() == 2);
                    checkSurface(c[0], 2, true, &kMatB, minusX, uvB);
                    checkSurface(c[1], 3, false, &kMatB, plusX, uvB);
                }
            }
        }
    }
    GIVEN("B = [−1,0] × [0,2]², touching A's face x = 0 from outside") {
        const rb::Instance b = cubeB(-1.0);
        WHEN("B is subtracted, and the line along +x leaves B where it enters A") {
            const CrossingList c = crossings(CsgOp::Difference, a, b, forward);
            THEN("A − B is A along it: both surfaces A's, facing out of A") {
                // Source: B's back face turned round, −x, is A's own normal there; B removes
                // nothing, so the result looks as A alone does.
                REQUIRE(c.size() == 2);
                checkSurface(c[0], 2, true, &kMatA, minusX, uvA);
                checkSurface(c[1], 3, false, &kMatA, plusX, uvA);
            }
        }
        WHEN("the line runs along −x, leaving A where it enters B") {
            const CrossingList c = crossings(CsgOp::Difference, a, b, backward);
            THEN("again both surfaces are A's") {
                REQUIRE(c.size() == 2);
                checkSurface(c[0], 2, true, &kMatA, plusX, uvA);
                checkSurface(c[1], 3, false, &kMatA, minusX, uvA);
            }
        }
    }
    GIVEN("B = [0.5,1.5] × [0,2]², biting off A's far half") {
        const rb::Instance b = cubeB(0.5);
        WHEN("B is subtracted, along +x") {
            const CrossingList c = crossings(CsgOp::Difference, a, b, forward);
            THEN(
                "A − B = [0, 0.5] leaves through B's face, B's material, uv and normal turned "
                "round") {
                // Source: at x = 0.5 only B's change (entering it) ends the result; at x = 1,
                // inside B, A's face bounds nothing. B's face x = 0.5 has the outward normal −x.
                REQUIRE(c.size() == 2);
                checkSurface(c[0], 2, true, &kMatA, minusX, uvA);
                checkSurface(c[1], 2.5, false, &kMatB, plusX, uvB);
            }
        }
    }
}
// [ch14-tie-test]

SCENARIO("CSG renders without NaN, negative or infinite pixels, even through glass",
         "[ch14][ex14.4][stability]") {
    auto world = csgWorld(R"(
        local glass = gr.material{kd = {0.1, 0.1, 0.1}, ks = {0.5, 0.5, 0.5}, shininess = 50,
                                  transparency = 0.9, ior = 1.5}
        local outer = gr.sphere('outer'); outer:scale(2, 2, 2)
        local shell = gr.difference(outer, gr.sphere('inner')); shell:set_material(glass)
        local a = gr.cube('a'); local b = gr.cube('b'); b:translate(0, 0, 0)
        local same = gr.difference(a, b)   -- a solid minus itself: every face coplanar
        local back = gr.nh_box('back', {-5, -5, -6}, 10)
        root = gr.node('root'); root:add_child(shell); root:add_child(same); root:add_child(back)
    )" + rbtest::renderLine());
    const rb::Image image = rbtest::renderSmall(*world, 48, 48);
    for (const float v : image.data()) {
        REQUIRE(std::isfinite(v));
        REQUIRE(v >= 0.0f);
    }
}

SCENARIO("with --features=all,-csg a CSG node is a plain group of its operands", "[ch14]") {
    const std::string lua = R"(
        local d = gr.difference(gr.sphere('a'), gr.nh_sphere('b', {1, 0, 0}, 0.5))
        root = gr.node('root'); root:add_child(d)
    )" + rbtest::renderLine();
    CHECK(rbtest::loadSceneText(lua, rbtest::chapters(14, "all,-csg")).at(0).instances.size() == 2);
    CHECK(rbtest::loadSceneText(lua, rbtest::chapters(14)).at(0).instances.size() == 1);
}

SCENARIO("CSG calls refuse bad arguments with a clear message", "[ch14]") {
    const auto error = [](const std::string& lua) {
        return rbtest::loadError(lua + "\n" + rbtest::renderLine("gr.node('r')"),
                                 rbtest::chapters(14));
    };
    CHECK_THAT(error("gr.union(gr.sphere('a'))"),
               Contains("gr.union") && Contains("(a, b [, name])"));
    CHECK_THAT(error("gr.difference(gr.sphere('a'), 3)"),
               Contains("gr.difference") && Contains("b"));
    CHECK_THAT(error("local a = gr.sphere('a'); a:csg(gr.sphere('b'), 'x')"),
               Contains("'u' (union), 'n' (intersection) or 'd' (difference)"));
    CHECK_THAT(
        error("local a = gr.node('a'); local b = gr.node('b'); b:add_child(a); a:csg(b, 'u')"),
        Contains("cycle"));
    CHECK_THAT(error("local a = gr.sphere('a'); a:csg(a, 'u')"), Contains("cycle"));
    CHECK_THAT(rbtest::loadError("gr.union(gr.sphere('a'), gr.sphere('b'))\n" +
                                     rbtest::renderLine("gr.node('r')"),
                                 rbtest::chapters(8)),
               Contains("chapter 14"));
}
