// bvh_scaling: how BVH build time and time per ray grow with the triangle count, against brute
// force on the small sizes. The meshes are the bunny and its Loop subdivisions (3.7k, 15k, 59k,
// 235k triangles), made here. A benchmark for `make charts`, not a test.
//
// usage: bvh_scaling bunny_L0.obj out.dat
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <map>
#include <set>

#include "core/mesh.h"
#include "core/obj.h"
#include "core/triangle.h"
#include "ray_sets.h"

namespace {

using Clock = std::chrono::steady_clock;
double seconds(Clock::time_point t0) {
    return std::chrono::duration<double>(Clock::now() - t0).count();
}

// [loop-subdivision]
/// One step of Loop subdivision: every triangle becomes four; new edge points are
/// 3/8·(a + b) + 1/8·(c + d) (the two ends and the two opposite corners), old vertices move to
/// (1 − nβ)·v + β·Σ neighbours with β = 3/16 for n = 3 and 3/(8n) otherwise. Boundary edges
/// take their midpoint and boundary vertices stay put. Source: C. Loop, "Smooth Subdivision
/// Surfaces Based on Triangles", M.S. thesis, University of Utah, 1987.
rb::ObjData loopSubdivide(const rb::ObjData& in) {
    using Edge = std::pair<int, int>;
    auto key = [](int a, int b) { return a < b ? Edge{a, b} : Edge{b, a}; };
    std::map<Edge, std::vector<int>> opposite;  // edge → corners opposite it
    for (const auto& t : in.triangles)
        for (int k = 0; k < 3; ++k)
            opposite[key(t[k].v, t[(k + 1) % 3].v)].push_back(t[(k + 2) % 3].v);

    rb::ObjData out;
    // Move the old vertices.
    std::vector<std::set<int>> neighbours(in.positions.size());
    std::vector<bool> boundary(in.positions.size(), false);
    for (const auto& [e, opp] : opposite) {
        neighbours[e.first].insert(e.second);
        neighbours[e.second].insert(e.first);
        if (opp.size() != 2) boundary[e.first] = boundary[e.second] = true;
    }
    for (size_t v = 0; v < in.positions.size(); ++v) {
        const size_t n = neighbours[v].size();
        if (boundary[v] || n < 3) {
            out.positions.push_back(in.positions[v]);
            continue;
        }
        const double beta = n == 3 ? 3.0 / 16.0 : 3.0 / (8.0 * n);
        rb::Vec3 sum(0.0);
        for (int u : neighbours[v]) sum += in.positions[u];
        out.positions.push_back((1.0 - n * beta) * in.positions[v] + beta * sum);
    }
    // One new point per edge.
    std::map<Edge, int> edgePoint;
    for (const auto& [e, opp] : opposite) {
        const rb::Vec3 a = in.positions[e.first], b = in.positions[e.second];
        rb::Vec3 p = 0.5 * (a + b);
        if (opp.size() == 2)
            p = 0.375 * (a + b) + 0.125 * (in.positions[opp[0]] + in.positions[opp[1]]);
        edgePoint[e] = static_cast<int>(out.positions.size());
        out.positions.push_back(p);
    }
    // Four triangles for each old one, keeping the winding.
    for (const auto& t : in.triangles) {
        const int a = t[0].v, b = t[1].v, c = t[2].v;
        const int ab = edgePoint[key(a, b)], bc = edgePoint[key(b, c)], ca = edgePoint[key(c, a)];
        for (const auto& tri : {std::array<int, 3>{a, ab, ca}, std::array<int, 3>{ab, b, bc},
                                std::array<int, 3>{ca, bc, c}, std::array<int, 3>{ab, bc, ca}})
            out.triangles.push_back({rb::ObjCorner{tri[0]}, rb::ObjCorner{tri[1]}, rb::ObjCorner{tri[2]}});
    }
    return out;
}
// [loop-subdivision]

/// Seconds per closest-hit ray through the BVH.
double bvhTimePerRay(const rb::Mesh& mesh, const std::vector<rbperf::BenchRay>& rays) {
    size_t hits = 0;
    const auto t0 = Clock::now();
    for (const auto& r : rays) {
        rb::ObjectHit h;
        hits += mesh.intersect(rb::Ray{r.o, r.d}, r.tMax, h);
    }
    const double s = seconds(t0);
    if (hits == 0) std::fprintf(stderr, "bvh_scaling: no ray hit the mesh\n");
    return s / rays.size();
}

/// Seconds per closest-hit ray testing every triangle.
double bruteTimePerRay(const rb::Mesh& mesh, const std::vector<rbperf::BenchRay>& rays) {
    size_t hits = 0;
    const auto t0 = Clock::now();
    for (const auto& r : rays) {
        const rb::WatertightRay w(rb::Ray{r.o, r.d});
        double tMax = r.tMax;
        bool hit = false;
        for (size_t i = 0; i < mesh.triangleCount(); ++i) {
            const auto& v = mesh.triangle(i);
            rb::TriangleHit th;
            if (rb::intersectTriangle(w, v[0], v[1], v[2], tMax, th)) {
                tMax = th.t;
                hit = true;
            }
        }
        hits += hit;
    }
    const double s = seconds(t0);
    if (hits == 0) std::fprintf(stderr, "bvh_scaling: no ray hit the mesh\n");
    return s / rays.size();
}

double peakMiB() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return u.ru_maxrss / 1024.0;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 3) {
        std::fprintf(stderr, "usage: bvh_scaling bunny_L0.obj out.dat\n");
        return 2;
    }
    rb::ObjData data = rb::loadObj(argv[1]);
    std::FILE* out = std::fopen(argv[2], "w");
    if (!out) return 2;
    std::fprintf(out, "# triangles  build_ms  bvh_us_per_ray  brute_us_per_ray  mesh_B/tri  bvh_B/tri\n");
    std::printf("%10s %10s %14s %16s %12s %12s %10s\n", "triangles", "build ms", "BVH us/ray",
                "brute us/ray", "mesh B/tri", "BVH B/tri", "peak MiB");
    for (int level = 0; level <= 3; ++level) {
        if (level > 0) data = loopSubdivide(data);
        const auto t0 = Clock::now();
        const rb::Mesh mesh(data, "bunny");
        const double buildMs = 1e3 * seconds(t0);
        const auto rays = rbperf::incoherentRays(mesh.bounds(), 1 << 18, 11);
        const double bvh = bvhTimePerRay(mesh, rays);
        double brute = -1.0;
        if (level <= 1) {
            const std::vector<rbperf::BenchRay> few(rays.begin(), rays.begin() + (1 << 11));
            brute = bruteTimePerRay(mesh, few);
        }
        const double n = static_cast<double>(mesh.triangleCount());
        const double meshB = mesh.triangleBytes() / n;
        const double bvhB = (mesh.bvh().nodeBytes() + mesh.bvh().wideNodeBytes()) / n;
        std::fprintf(out, "%zu %.3f %.5f %.5f %.1f %.1f\n", mesh.triangleCount(), buildMs, 1e6 * bvh,
                     1e6 * brute, meshB, bvhB);
        std::printf("%10zu %10.1f %14.3f %16s %12.1f %12.1f %10.1f\n", mesh.triangleCount(), buildMs,
                    1e6 * bvh, brute < 0 ? "-" : std::to_string(1e6 * brute).c_str(), meshB, bvhB,
                    peakMiB());
    }
    std::fclose(out);
    return 0;
}
