// Chapter 14's chart data: nanoseconds per ray (closest hit) against a CSG solid of N
// operands, N = 1 ... 256, for three ways of building it, and the same N spheres without CSG
// in chapter 3's BVH for scale. Writes OUT_DIR/cost.dat and OUT_DIR/finding.txt.
//
// usage: ch14_csg_charts OUT_DIR
//
// The operands are spheres of radius 0.25 at fixed random places in [−1, 1]³; the rays start on
// a sphere of radius 5 and aim at random points of [−1, 1]³ (one thread, the fastest of 3 runs
// of 30000 rays each, the same rays for every series).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "bvh/bvh_aggregate.h"
#include "core/sphere.h"
#include "csg/csg.h"

using namespace rb;

namespace {

/// N small spheres at fixed random places; `big` adds one of radius 1.2 at the origin first.
std::vector<Instance> spheres(int n, const Shape& sphere, bool big = false) {
    std::mt19937_64 rng(14);
    auto u = [&] { return static_cast<double>(rng() >> 11) * 0x1.0p-53 * 2.0 - 1.0; };
    std::vector<Instance> out;
    if (big) {
        Instance b;
        b.shape = &sphere;
        b.setTransform(glm::scale(Mat4(1.0), Vec3(1.2)));
        out.push_back(b);
    }
    for (int i = 0; i < n; ++i) {
        Instance s;
        s.shape = &sphere;
        s.setTransform(glm::scale(glm::translate(Mat4(1.0), Vec3(u(), u(), u())), Vec3(0.25)));
        out.push_back(s);
    }
    return out;
}

/// The rays of every measurement.
std::vector<Ray> rays(int count) {
    std::mt19937_64 rng(7);
    auto u = [&] { return static_cast<double>(rng() >> 11) * 0x1.0p-53 * 2.0 - 1.0; };
    std::vector<Ray> out;
    for (int i = 0; i < count; ++i) {
        Vec3 o(u(), u(), u());
        o = 5.0 * glm::normalize(o + Vec3(1e-9));
        out.push_back(Ray{o, Vec3(u(), u(), u()) - o});
    }
    return out;
}

/// Fastest of 3 runs: nanoseconds per ray of `trace`, and the hits it found.
template <class Trace>
double nsPerRay(const std::vector<Ray>& rs, Trace trace, int& hits) {
    double best = 1e300;
    for (int run = 0; run < 3; ++run) {
        hits = 0;
        const auto t0 = std::chrono::steady_clock::now();
        for (const Ray& r : rs) hits += trace(r);
        const double s =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        best = std::min(best, s);
    }
    return best * 1e9 / static_cast<double>(rs.size());
}

/// A left-leaning chain ((s₁ ∪ s₂) ∪ s₃) ∪ …, as a script of nested gr.union calls makes it.
std::shared_ptr<const CsgShape> chain(const std::vector<Instance>& s,
                                      std::vector<std::shared_ptr<const CsgShape>>& keep) {
    CsgLeaf acc = CsgLeaf::from(s[0]);
    std::shared_ptr<const CsgShape> last;
    for (size_t i = 1; i < s.size(); ++i) {
        last = std::make_shared<const CsgShape>(CsgOp::Union, acc, CsgLeaf::from(s[i]));
        keep.push_back(last);
        Instance in;
        in.shape = last.get();
        in.setTransform(Mat4(1.0));
        acc = CsgLeaf::from(in);
    }
    return last;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: ch14_csg_charts OUT_DIR\n");
        return 2;
    }
    const std::string out = argv[1];
    const Sphere sphere;
    const std::vector<Ray> rs = rays(30000);
    std::ofstream dat(out + "/cost.dat");
    dat << "# N  balanced_union_ns  chain_union_ns  difference_ns  bvh_no_csg_ns  (per ray, 1 "
           "thread)\n";
    double first[4] = {0, 0, 0, 0}, mid[4] = {0, 0, 0, 0}, last[4] = {0, 0, 0, 0};
    int lastN = 0;
    for (int n = 2; n <= 256; n *= 2) {
        const std::vector<Instance> s = spheres(n, sphere);
        int hits = 0;
        ObjectHit h;
        // Balanced: gr.union(groupA, groupB), each group half the spheres.
        const std::vector<Instance> half1(s.begin(), s.begin() + n / 2),
            half2(s.begin() + n / 2, s.end());
        const auto balanced = CsgCompound(CsgOp::Union).build({half1, half2});
        const double tBalanced = nsPerRay(
            rs, [&](const Ray& r) { return balanced->intersect(r, 1e30, h); }, hits);
        // Chain: nested gr.union calls, one level per operand.
        std::vector<std::shared_ptr<const CsgShape>> keep;
        const auto chained = chain(s, keep);
        const double tChain = nsPerRay(
            rs, [&](const Ray& r) { return chained->intersect(r, 1e30, h); }, hits);
        // Difference: a big ball minus a group of n small ones (Swiss cheese).
        const std::vector<Instance> big = spheres(0, sphere, true);
        const auto cheese = CsgCompound(CsgOp::Difference).build({big, s});
        const double tCheese = nsPerRay(
            rs, [&](const Ray& r) { return cheese->intersect(r, 1e30, h); }, hits);
        // No CSG: the same spheres as instances in the BVH, closest hit.
        const auto bvh = buildBVHAggregate(s);
        Hit hit;
        const double tBvh = nsPerRay(
            rs, [&](const Ray& r) { return bvh->intersect(r, 1e30, hit); }, hits);
        dat << n << ' ' << tBalanced << ' ' << tChain << ' ' << tCheese << ' ' << tBvh << '\n';
        std::printf(
            "N %4d: balanced union %8.1f ns, chain %8.1f ns, difference %8.1f ns, BVH %6.1f ns\n",
            n, tBalanced, tChain, tCheese, tBvh);
        const double t[4] = {tBalanced, tChain, tCheese, tBvh};
        for (int k = 0; k < 4; ++k) {
            if (n == 2) first[k] = t[k];
            if (n == 16) mid[k] = t[k];
            last[k] = t[k];
        }
        lastN = n;
    }
    std::ofstream finding(out + "/finding.txt");
    char text[600];
    // The growth exponent from N = 16 to the largest N: cost ∝ N^slope.
    auto slope = [&](int k) { return std::log(last[k] / mid[k]) / std::log(lastN / 16.0); };
    std::snprintf(text, sizeof text,
                  "From 2 to %d operands a CSG hit costs %.0f to %.0f ns for a balanced union "
                  "(cost ~ N^%.2f from N = 16), up to %.0f ns for a chain of nested unions "
                  "(N^%.2f: each level copies the lists below it) and %.0f ns for a ball minus a "
                  "group of balls (N^%.2f): every operand whose bounds the ray meets lists all its "
                  "crossings, where the BVH's closest hit over the same spheres stays at %.0f-%.0f "
                  "ns.\n",
                  lastN, first[0], last[0], slope(0), last[1], slope(1), last[2], slope(2),
                  first[3], last[3]);
    finding << text;
    std::printf("%s", text);
    return 0;
}
