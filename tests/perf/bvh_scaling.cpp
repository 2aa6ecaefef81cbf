// bvh_scaling: how BVH build time, time per ray and memory grow with the triangle count, against
// brute force on small meshes. Measures one OBJ per process, so the peak resident memory it
// reports belongs to that mesh alone. `make charts` runs it on the bunny and its Loop
// subdivisions (tests/perf/subdivide.cpp: 3.7k, 15k, 59k and 235k triangles) and draws
// docs/charts/ch03-bvh-scaling.svg. A benchmark, not a test.
//
// usage: bvh_scaling file.obj [--rays N] [--brute-rays N] [--runs N] [--bvh LAYOUT] [--header]
//   --rays N        incoherent rays through the BVH (default 2^18)
//   --brute-rays N  the first N of them also through a loop over every triangle (default 0: off)
//   --runs N        repeats of each timing; the median is reported (default 3)
//   --bvh LAYOUT    binary, wide4, wide8 or wide (default: wide, the widest this CPU runs)
//   --header        print the column names first
// Prints one line: triangles, Mesh construction ms, BVH::build ms, BVH µs/ray, brute-force
// µs/ray (-1 when off), mesh bytes/triangle, BVH bytes/triangle, peak RSS after loading the OBJ
// and building the mesh (MiB), peak RSS at the end (MiB, with the rays and the timed rebuilds),
// brute-force rays whose hit differs from the BVH's, peak RSS after loading the OBJ alone (MiB).
// One thread.
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <memory>
#include <string>

#include "bvh/mesh.h"
#include "bvh/obj.h"
#include "bvh/triangle.h"
#include "core/error.h"
#include "ray_sets.h"

namespace {

using Clock = std::chrono::steady_clock;

/// Seconds since t0.
double seconds(Clock::time_point t0) {
    return std::chrono::duration<double>(Clock::now() - t0).count();
}

/// The median of v (non-empty).
double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/// Peak resident set size of this process so far, MiB (getrusage; Linux reports KiB).
double peakMiB() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return u.ru_maxrss / 1024.0;
}

/// Closest-hit distance of every ray through the BVH (infinity on a miss); returns seconds.
double traceBvh(const rb::Mesh& mesh, const std::vector<rbperf::BenchRay>& rays,
                std::vector<double>& t) {
    const auto t0 = Clock::now();
    for (size_t i = 0; i < rays.size(); ++i) {
        rb::ObjectHit h;
        t[i] = mesh.intersect(rb::Ray{rays[i].o, rays[i].d}, rays[i].tMax, h)
                   ? h.t
                   : std::numeric_limits<double>::infinity();
    }
    return seconds(t0);
}

/// Closest-hit distance of every ray by testing every triangle (same watertight test); returns
/// seconds.
double traceBrute(const rb::Mesh& mesh, const std::vector<rbperf::BenchRay>& rays,
                  std::vector<double>& t) {
    const auto triangles = mesh.triangles();
    const auto t0 = Clock::now();
    for (size_t i = 0; i < rays.size(); ++i) {
        const rb::WatertightRay w(rb::Ray{rays[i].o, rays[i].d});
        double tMax = rays[i].tMax;
        bool hit = false;
        for (const rb::Mesh::Triangle& tri : triangles) {
            const auto& v = tri.v;
            rb::TriangleHit th;
            if (rb::intersectTriangle(w, v[0], v[1], v[2], tMax, th)) {
                tMax = th.t;
                hit = true;
            }
        }
        t[i] = hit ? tMax : std::numeric_limits<double>::infinity();
    }
    return seconds(t0);
}

/// Command-line settings.
struct Settings {
    std::string obj;
    int rays = 1 << 18;
    int bruteRays = 0;
    int runs = 3;
    rb::BVHLayout layout = rb::bestWideLayout();
    bool header = false;
};

/// Parse the command line (see the file comment).
Settings parse(int argc, char** argv) {
    Settings s;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto number = [&]() {
            if (i + 1 >= argc) throw rb::InputError(a + " needs a number");
            return std::max(0, std::atoi(argv[++i]));
        };
        if (a == "--rays")
            s.rays = std::max(1, number());
        else if (a == "--brute-rays")
            s.bruteRays = number();
        else if (a == "--runs")
            s.runs = std::max(1, number());
        else if (a == "--bvh" && i + 1 < argc)
            s.layout = rb::bvhLayoutNamed(argv[++i]);
        else if (a == "--header")
            s.header = true;
        else if (s.obj.empty() && !a.empty() && a[0] != '-')
            s.obj = a;
        else
            throw rb::InputError("unknown argument '" + a + "'");
    }
    if (s.obj.empty()) throw rb::InputError("no OBJ file given");
    return s;
}

int run(const Settings& s) {
    // Load and build once, as ./rt does, and take the memory peak there.
    const rb::ObjData data = rb::loadObj(s.obj);
    const double peakLoad = peakMiB();
    auto mesh = std::make_unique<rb::Mesh>(data, s.obj, s.layout);
    const double peakBuild = peakMiB();

    // Build times: the whole rb::Mesh (copying triangles into BVH order included), and
    // BVH::build alone over the triangles' boxes.
    std::vector<rb::AABB> boxes;
    boxes.reserve(data.triangles.size());
    for (const auto& t : data.triangles) {
        rb::AABB b;
        for (const auto& c : t) b.extend(data.positions[c.v]);
        boxes.push_back(b);
    }
    std::vector<double> meshMs, bvhMs;
    for (int i = 0; i < s.runs; ++i) {
        auto t0 = Clock::now();
        {
            const rb::Mesh m(data, s.obj, s.layout);
            meshMs.push_back(1e3 * seconds(t0));
        }
        t0 = Clock::now();
        rb::BVH bvh;
        rb::BVHBuildOptions options;
        options.layout = s.layout;
        bvh.build(boxes, options);
        bvhMs.push_back(1e3 * seconds(t0));
    }

    // Time per ray, incoherent rays (the same generator and seed for every mesh).
    const auto rays = rbperf::unbounded(rbperf::incoherentRays(mesh->bounds(), s.rays, 11));
    std::vector<double> tBvh(rays.size()), perRay;
    for (int i = 0; i < s.runs; ++i) perRay.push_back(traceBvh(*mesh, rays, tBvh) / rays.size());
    double brute = -1.0;
    size_t mismatches = 0;
    if (s.bruteRays > 0) {
        const std::vector<rbperf::BenchRay> few(
            rays.begin(), rays.begin() + std::min<size_t>(s.bruteRays, rays.size()));
        std::vector<double> tBrute(few.size()), bruteRay;
        for (int i = 0; i < s.runs; ++i)
            bruteRay.push_back(traceBrute(*mesh, few, tBrute) / few.size());
        brute = median(bruteRay);
        for (size_t i = 0; i < few.size(); ++i)
            if (std::isinf(tBrute[i]) != std::isinf(tBvh[i]) ||
                std::abs(tBrute[i] - tBvh[i]) > 1e-9 * std::max(1.0, std::abs(tBvh[i])))
                ++mismatches;
    }

    const double n = static_cast<double>(mesh->triangleCount());
    if (s.header)
        std::printf(
            "# triangles mesh_build_ms bvh_build_ms bvh_us_per_ray brute_us_per_ray "
            "mesh_B_per_tri bvh_B_per_tri peak_MiB_build peak_MiB_end brute_mismatches "
            "peak_MiB_load\n");
    std::printf("%zu %.3f %.3f %.5f %.3f %.1f %.1f %.1f %.1f %zu %.1f\n", mesh->triangleCount(),
                median(meshMs), median(bvhMs), 1e6 * median(perRay), brute < 0 ? -1.0 : 1e6 * brute,
                mesh->triangleBytes() / n, mesh->bvh().nodeBytes() / n, peakBuild, peakMiB(),
                mismatches, peakLoad);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        return run(parse(argc, argv));
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bvh_scaling: %s\n", e.what());
        return 2;
    }
}
