// Chapter 15's measurements, for tests/perf/ch15/charts.sh:
//   shapes.dat   ns per ray for the sphere and every quadric (random rays at the bounds)
//   mesh.dat     ns per ray and silhouette error of a cylinder tessellated with N segments
//   leaks.txt    rim rays that pass between cap and side: seed 001's separate tests vs the slab
//   finding.txt  one sentence with the numbers
// usage: ch15_quadric_costs OUT_DIR   (one thread; the fastest of 7 runs)
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "bvh/mesh.h"
#include "core/sphere.h"
#include "quadrics/cone.h"
#include "quadrics/cylinder.h"

using namespace rb;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr int kRays = 1 << 17;

/// Uniform doubles from a fixed seed (the top 53 bits of std::mt19937_64).
struct Rng {
    std::mt19937_64 engine{15};
    double uniform() { return static_cast<double>(engine() >> 11) * 0x1.0p-53; }
    Vec3 unitVector() {
        const double z = 1.0 - 2.0 * uniform(), phi = 2.0 * M_PI * uniform();
        const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
        return {r * std::cos(phi), r * std::sin(phi), z};
    }
};

/// Rays from a sphere of radius 4 aimed at random points of the box [−1, 1]³.
std::vector<Ray> makeRays() {
    Rng rng;
    std::vector<Ray> rays;
    for (int i = 0; i < kRays; ++i) {
        const Vec3 o = 4.0 * rng.unitVector();
        const Vec3 t(2 * rng.uniform() - 1, 2 * rng.uniform() - 1, 2 * rng.uniform() - 1);
        rays.push_back({o, t - o});
    }
    return rays;
}

/// One timed query kind: closest hits (intersect) or any hit (occluded) against one shape.
struct Job {
    const Shape* shape;
    bool occluded;
    double bestNs = 1e300;  ///< The fastest run: the one least disturbed by other processes.
    double hitShare = 0.0;
};

/// Time every job 7 times, interleaved (round after round), so a burst of load from other
/// processes spreads over all of them instead of favouring one; keep each job's fastest run.
void timeJobs(std::vector<Job>& jobs, const std::vector<Ray>& rays) {
    for (int round = 0; round < 7; ++round)
        for (Job& job : jobs) {
            int hits = 0;
            const auto t0 = std::chrono::steady_clock::now();
            for (const Ray& r : rays) {
                ObjectHit hit;
                hits += job.occluded ? job.shape->occluded(r, kInf)
                                     : job.shape->intersect(r, kInf, hit);
            }
            const double s =
                std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
            job.bestNs = std::min(job.bestNs, s * 1e9 / rays.size());
            job.hitShare = static_cast<double>(hits) / rays.size();
        }
}

/// The capped cylinder as a mesh with n side segments: vertices on the circle (inscribed),
/// two triangles per side quad and a fan per cap: 4n triangles.
Mesh tessellatedCylinder(int n) {
    ObjData data;
    for (int k = 0; k < n; ++k) {
        const double phi = 2.0 * M_PI * k / n;
        data.positions.emplace_back(std::sin(phi), -1.0, std::cos(phi));
        data.positions.emplace_back(std::sin(phi), 1.0, std::cos(phi));
    }
    data.positions.emplace_back(0.0, -1.0, 0.0);
    data.positions.emplace_back(0.0, 1.0, 0.0);
    const int bottom = 2 * n, top = 2 * n + 1;
    auto tri = [&](int a, int b, int c) {
        data.triangles.push_back({ObjCorner{a}, ObjCorner{b}, ObjCorner{c}});
    };
    for (int k = 0; k < n; ++k) {
        const int a = 2 * k, b = 2 * ((k + 1) % n);
        tri(a, b, a + 1);
        tri(b, b + 1, a + 1);
        tri(bottom, b, a);
        tri(top, a + 1, b + 1);
    }
    return Mesh(data, "tessellated cylinder");
}

/// Seed 001's way: the side's roots kept where |y| ≤ 1, each cap's plane hit kept where
/// x² + z² ≤ 1, the smallest positive t of the three. True when it finds a hit.
bool threeSurfaceHit(const Ray& ray, double tMax) {
    double best = tMax;
    const double a = ray.d.x * ray.d.x + ray.d.z * ray.d.z;
    const double h = ray.o.x * ray.d.x + ray.o.z * ray.d.z;
    const double c = ray.o.x * ray.o.x + ray.o.z * ray.o.z - 1.0;
    const double disc = h * h - a * c;
    if (a > 0.0 && disc >= 0.0)
        for (const double t : {(-h - std::sqrt(disc)) / a, (-h + std::sqrt(disc)) / a}) {
            const double y = ray.o.y + t * ray.d.y;
            if (t > 0.0 && t < best && std::abs(y) <= 1.0) best = t;
        }
    if (ray.d.y != 0.0)
        for (const double capY : {-1.0, 1.0}) {
            const double t = (capY - ray.o.y) / ray.d.y;
            const double x = ray.o.x + t * ray.d.x, z = ray.o.z + t * ray.d.z;
            if (t > 0.0 && t < best && x * x + z * z <= 1.0) best = t;
        }
    return best < tMax;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: ch15_quadric_costs OUT_DIR\n");
        return 2;
    }
    const std::string out = argv[1];
    const std::vector<Ray> rays = makeRays();

    // Cost per ray of each analytic shape.
    const Sphere sphere;
    const Cylinder cylinder, tube(false);
    const Cone cone, openCone(0.0, false), frustum(0.5);
    struct Named {
        const char* name;
        const Shape* shape;
    };
    const Named shapes[] = {{"sphere", &sphere}, {"cylinder", &cylinder},  {"open-cylinder", &tube},
                            {"cone", &cone},     {"open-cone", &openCone}, {"frustum", &frustum}};
    const std::vector<int> segments = {8, 16, 32, 51, 64, 128, 256, 512, 1024, 4096};
    std::vector<Mesh> meshes;
    for (const int n : segments) meshes.push_back(tessellatedCylinder(n));
    std::vector<Job> jobs;
    for (const Named& s : shapes) {
        jobs.push_back({s.shape, false});
        jobs.push_back({s.shape, true});
    }
    for (const Mesh& m : meshes) jobs.push_back({&m, false});
    timeJobs(jobs, rays);

    std::ofstream shapesDat(out + "/shapes.dat");
    shapesDat << "# shape ns_per_ray hit_fraction ns_per_shadow_ray\n";
    double sphereNs = 0, cylinderNs = 0, coneNs = 0, sphereShadowNs = 0, cylinderShadowNs = 0;
    for (size_t k = 0; k < std::size(shapes); ++k) {
        const Job &closest = jobs[2 * k], &any = jobs[2 * k + 1];
        shapesDat << shapes[k].name << " " << closest.bestNs << " " << closest.hitShare << " "
                  << any.bestNs << "\n";
        if (shapes[k].shape == &sphere) {
            sphereNs = closest.bestNs;
            sphereShadowNs = any.bestNs;
        }
        if (shapes[k].shape == &cylinder) {
            cylinderNs = closest.bestNs;
            cylinderShadowNs = any.bestNs;
        }
        if (shapes[k].shape == &cone) coneNs = closest.bestNs;
    }

    // Tessellated cylinders: cost, and the silhouette's largest error in pixels when the
    // cylinder is 512 pixels wide. Source: a chord of the unit circle over an angle 2π/n
    // lies 1 − cos(π/n) inside it at its middle.
    std::ofstream meshDat(out + "/mesh.dat");
    meshDat << "# segments triangles ns_per_ray silhouette_error_px_at_512\n";
    int halfPixelN = 0;
    double halfPixelNs = 0;
    for (size_t k = 0; k < segments.size(); ++k) {
        const int n = segments[k];
        const double ns = jobs[2 * std::size(shapes) + k].bestNs;
        const double errorPx = 256.0 * (1.0 - std::cos(M_PI / n));
        meshDat << n << " " << meshes[k].triangleCount() << " " << ns << " " << errorPx << "\n";
        if (n == 51) {  // the fewest segments within half a pixel: π / acos(1 − 1/512) = 50.3
            halfPixelN = n;
            halfPixelNs = ns;
        }
    }

    // Rim rays: each passes exactly through a point of a rim, going into the solid, so it
    // must hit there (t = 1). Its origin lies outside, beyond both the side and the cap.
    Rng rng;
    int slabMissed = 0, threeMissed = 0;
    const int rimRays = 1000000;
    for (int i = 0; i < rimRays; ++i) {
        const double phi = 2.0 * M_PI * rng.uniform();
        const double y = rng.uniform() < 0.5 ? -1.0 : 1.0;
        const Vec3 radial(std::cos(phi), 0.0, std::sin(phi)), tangent(-radial.z, 0.0, radial.x);
        const Vec3 rim = radial + Vec3(0.0, y, 0.0);
        // Inward: against the radial direction and the cap's normal, plus some sideways.
        const Vec3 in = -(0.05 + rng.uniform()) * radial - (0.05 + rng.uniform()) * Vec3(0, y, 0) +
                        (2.0 * rng.uniform() - 1.0) * tangent;
        const Ray ray{rim - (3.0 + 17.0 * rng.uniform()) * in, in * (3.0 + 17.0 * rng.uniform())};
        const Ray aimed{ray.o, rim - ray.o};
        ObjectHit hit;
        slabMissed += !cylinder.intersect(aimed, 1.0 + 1e-9, hit);
        threeMissed += !threeSurfaceHit(aimed, 1.0 + 1e-9);
    }
    std::ofstream(out + "/leaks.txt")
        << "rim rays " << rimRays << ", missed by the slab clip " << slabMissed
        << ", by seed 001's three separate tests " << threeMissed << "\n";

    char finding[1024];
    std::snprintf(finding, sizeof finding,
                  "On random rays a capped cylinder costs %.0f ns and a capped cone %.0f ns per "
                  "closest hit against %.0f ns for the sphere (%.1fx and %.1fx; most of it is "
                  "the normal and the atan2 of u, since a shadow ray costs %.0f ns against "
                  "%.0f ns), while a tessellated "
                  "cylinder accurate to half a pixel at 512 px (%d segments, %d triangles) costs "
                  "%.0f ns, %.1fx the quadric; of %d rays entering through a rim the slab "
                  "clip misses %d and seed 001's three separate tests miss %d.\n",
                  cylinderNs, coneNs, sphereNs, cylinderNs / sphereNs, coneNs / sphereNs,
                  cylinderShadowNs, sphereShadowNs, halfPixelN, 4 * halfPixelN, halfPixelNs,
                  halfPixelNs / cylinderNs, rimRays, slabMissed, threeMissed);
    std::ofstream(out + "/finding.txt") << finding;
    std::fputs(finding, stdout);
    return 0;
}
