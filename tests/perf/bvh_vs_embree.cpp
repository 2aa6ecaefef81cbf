// bvh_vs_embree: raybook's mesh BVH against Embree 3 on the same OBJ and the same rays, in one
// process. Single-ray APIs on both sides (rb::Mesh::intersect / occluded against rtcIntersect1 /
// rtcOccluded1), medians of alternating runs, and a per-ray check that both find the same hits.
// A benchmark for `make bench`, not a test.
//
// usage: bvh_vs_embree file.obj [--threads N] [--runs N] [--bvh LAYOUT[,LAYOUT...]]
//        (defaults: 1 thread, 5 runs, wide: the widest layout this CPU runs). With several
//        layouts (e.g. --bvh wide4,wide8), each run traces every layout, then Embree, in turn, so
//        each layout is compared with the same Embree under the same load; the "target" lines
//        are the first layout's.
//
// The ray sets (tests/perf/ray_sets.h): (a) coherent camera rays, 1024x1024, 45° fov, from 1.6
// bounding radii, looking at the box centre along -z; (b) incoherent rays from a sphere of 2
// bounding radii towards uniform points in the box, fixed seed, closest hit with no far end;
// (c) the same rays as any-hit shadow rays ending at their target point. Every ray is rounded to
// single precision first, so both libraries trace exactly the same rays (Embree takes floats).
#include <embree3/rtcore.h>
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "bvh/mesh.h"
#include "bvh/obj.h"
#include "core/error.h"
#include "ray_sets.h"

namespace {

using Clock = std::chrono::steady_clock;
constexpr float kMiss = std::numeric_limits<float>::infinity();

/// Seconds since t0.
double seconds(Clock::time_point t0) {
    return std::chrono::duration<double>(Clock::now() - t0).count();
}

/// Median, minimum and maximum of a set of measurements.
struct Spread {
    double median, min, max;
};

/// The spread of v (non-empty).
Spread spread(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    return {n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]), v.front(), v.back()};
}

/// "12.34 (12.01-12.80)" with every value scaled by `scale`.
std::string show(const Spread& s, double scale, const char* format = "%.2f") {
    char a[32], b[32], c[32], out[128];
    std::snprintf(a, sizeof a, format, s.median * scale);
    std::snprintf(b, sizeof b, format, s.min * scale);
    std::snprintf(c, sizeof c, format, s.max * scale);
    std::snprintf(out, sizeof out, "%s (%s-%s)", a, b, c);
    return out;
}

/// Round a ray set to single precision, so raybook (double) and Embree (float) see the same rays.
std::vector<rbperf::BenchRay> toFloatPrecision(std::vector<rbperf::BenchRay> rays) {
    auto f = [](double x) { return static_cast<double>(static_cast<float>(x)); };
    for (auto& r : rays) {
        r.o = rb::Vec3(f(r.o.x), f(r.o.y), f(r.o.z));
        r.d = rb::Vec3(f(r.d.x), f(r.d.y), f(r.d.z));
        r.tMax = r.tMax >= 1e30 ? std::numeric_limits<double>::infinity() : f(r.tMax);
    }
    return rays;
}

/// An Embree device with a scene holding one triangle mesh (medium build quality).
struct EmbreeScene {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    /// Build from OBJ data with `threads` build threads.
    EmbreeScene(const rb::ObjData& data, int threads) {
        const std::string config = "threads=" + std::to_string(threads);
        device = rtcNewDevice(config.c_str());
        if (!device) throw std::runtime_error("rtcNewDevice failed");
        scene = rtcNewScene(device);
        rtcSetSceneBuildQuality(scene, RTC_BUILD_QUALITY_MEDIUM);
        RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
        rtcSetGeometryBuildQuality(geom, RTC_BUILD_QUALITY_MEDIUM);
        auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0,
                                                              RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                                              data.positions.size()));
        for (size_t i = 0; i < data.positions.size(); ++i)
            for (int k = 0; k < 3; ++k) v[3 * i + k] = static_cast<float>(data.positions[i][k]);
        auto* idx = static_cast<unsigned*>(
            rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                    3 * sizeof(unsigned), data.triangles.size()));
        for (size_t t = 0; t < data.triangles.size(); ++t)
            for (int k = 0; k < 3; ++k)
                idx[3 * t + k] = static_cast<unsigned>(data.triangles[t][k].v);
        rtcCommitGeometry(geom);
        rtcAttachGeometry(scene, geom);
        rtcReleaseGeometry(geom);
        rtcCommitScene(scene);
    }
    EmbreeScene(const EmbreeScene&) = delete;
    EmbreeScene& operator=(const EmbreeScene&) = delete;
    ~EmbreeScene() {
        rtcReleaseScene(scene);
        rtcReleaseDevice(device);
    }
};

/// An Embree ray from a benchmark ray.
RTCRay embreeRay(const rbperf::BenchRay& r) {
    RTCRay ray{};
    ray.org_x = static_cast<float>(r.o.x);
    ray.org_y = static_cast<float>(r.o.y);
    ray.org_z = static_cast<float>(r.o.z);
    ray.dir_x = static_cast<float>(r.d.x);
    ray.dir_y = static_cast<float>(r.d.y);
    ray.dir_z = static_cast<float>(r.d.z);
    ray.tnear = 0.0f;
    ray.tfar = static_cast<float>(r.tMax);
    ray.mask = 0xFFFFFFFF;
    return ray;
}

/// Trace every ray with trace(i) on `threads` OpenMP threads; returns rays per second.
template <class Trace>
double traceAll(size_t count, int threads, Trace&& trace) {
    const auto t0 = Clock::now();
#pragma omp parallel for schedule(dynamic, 1024) num_threads(threads)
    for (size_t i = 0; i < count; ++i) trace(i);
    return count / seconds(t0);
}

/// One query (closest or any hit) for one library; writes each ray's hit distance (closest;
/// kMiss when none) or 1/0 (any hit) into out.
using Query = double (*)(const void* target, const std::vector<rbperf::BenchRay>&, int threads,
                         std::vector<float>& out);

/// raybook closest hit.
double raybookClosest(const void* target, const std::vector<rbperf::BenchRay>& rays, int threads,
                      std::vector<float>& out) {
    const auto& mesh = *static_cast<const rb::Mesh*>(target);
    return traceAll(rays.size(), threads, [&](size_t i) {
        rb::ObjectHit h;
        out[i] = mesh.intersect(rb::Ray{rays[i].o, rays[i].d}, rays[i].tMax, h)
                     ? static_cast<float>(h.t)
                     : kMiss;
    });
}

/// raybook any hit (shadow rays).
double raybookAny(const void* target, const std::vector<rbperf::BenchRay>& rays, int threads,
                  std::vector<float>& out) {
    const auto& mesh = *static_cast<const rb::Mesh*>(target);
    return traceAll(rays.size(), threads, [&](size_t i) {
        out[i] = mesh.occluded(rb::Ray{rays[i].o, rays[i].d}, rays[i].tMax) ? 1.0f : 0.0f;
    });
}

/// Embree closest hit (rtcIntersect1).
double embreeClosest(const void* target, const std::vector<rbperf::BenchRay>& rays, int threads,
                     std::vector<float>& out) {
    const RTCScene scene = static_cast<const EmbreeScene*>(target)->scene;
    return traceAll(rays.size(), threads, [&](size_t i) {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        RTCRayHit rh;
        rh.ray = embreeRay(rays[i]);
        rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(scene, &context, &rh);
        out[i] = rh.hit.geomID != RTC_INVALID_GEOMETRY_ID ? rh.ray.tfar : kMiss;
    });
}

/// Embree any hit (rtcOccluded1).
double embreeAny(const void* target, const std::vector<rbperf::BenchRay>& rays, int threads,
                 std::vector<float>& out) {
    const RTCScene scene = static_cast<const EmbreeScene*>(target)->scene;
    return traceAll(rays.size(), threads, [&](size_t i) {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        RTCRay ray = embreeRay(rays[i]);
        rtcOccluded1(scene, &context, &ray);
        out[i] = ray.tfar < 0.0f ? 1.0f : 0.0f;  // Embree sets tfar to -inf on a hit
    });
}

/// How the two libraries' answers differ, ray by ray.
struct Agreement {
    size_t hitsA = 0, hitsB = 0;
    size_t hitMissMismatches = 0;   ///< One library hits, the other misses.
    size_t distanceMismatches = 0;  ///< Both hit, distances differ by more than 1e-4 relative.
};

/// Compare per-ray results a (raybook) and b (Embree); any-hit results are 1/0.
Agreement compare(const std::vector<float>& a, const std::vector<float>& b, bool anyHit) {
    Agreement g;
    for (size_t i = 0; i < a.size(); ++i) {
        const bool ha = anyHit ? a[i] != 0.0f : a[i] != kMiss;
        const bool hb = anyHit ? b[i] != 0.0f : b[i] != kMiss;
        g.hitsA += ha;
        g.hitsB += hb;
        if (ha != hb)
            ++g.hitMissMismatches;
        else if (ha && !anyHit && std::abs(a[i] - b[i]) > 1e-4f * std::max(a[i], b[i]))
            ++g.distanceMismatches;
    }
    return g;
}

/// The --bvh name of a layout: binary, wide4 or wide8.
const char* layoutKey(rb::BVHLayout layout) {
    return layout == rb::BVHLayout::Binary  ? "binary"
           : layout == rb::BVHLayout::Wide4 ? "wide4"
                                            : "wide8";
}

/// Command-line settings.
struct Settings {
    std::string obj;
    int threads = 1;
    int runs = 5;
    std::vector<rb::BVHLayout> layouts;  ///< Empty: the default, rb::bestWideLayout().
};

/// Parse `file.obj [--threads N] [--runs N] [--bvh L1,L2...]` (a bare number is the run count).
Settings parse(int argc, char** argv) {
    Settings s;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--bvh" && i + 1 < argc) {
            const std::string list = argv[++i];
            for (size_t start = 0; start <= list.size();) {
                const size_t comma = std::min(list.find(',', start), list.size());
                s.layouts.push_back(rb::bvhLayoutNamed(list.substr(start, comma - start)));
                start = comma + 1;
            }
        } else if ((a == "--threads" || a == "--runs") && i + 1 < argc) {
            const int v = std::max(1, std::atoi(argv[++i]));
            (a == "--threads" ? s.threads : s.runs) = v;
        } else if (!a.empty() && std::isdigit(static_cast<unsigned char>(a[0])) && !s.obj.empty()) {
            s.runs = std::max(1, std::atoi(a.c_str()));
        } else if (s.obj.empty() && a[0] != '-') {
            s.obj = a;
        } else {
            throw rb::InputError("unknown argument '" + a + "'");
        }
    }
    if (s.obj.empty()) throw rb::InputError("no OBJ file given");
    if (s.layouts.empty()) s.layouts.push_back(rb::bestWideLayout());
    return s;
}

int run(const Settings& s) {
    const rb::ObjData data = rb::loadObj(s.obj);
    // raybook's build splits big ranges as OpenMP tasks: give it the same threads as Embree.
    omp_set_num_threads(s.threads);

    // Build times, alternating raybook and Embree.
    // The first layout's build is timed; the others are built once, after.
    std::vector<double> rbBuild, emBuild;
    std::vector<std::unique_ptr<rb::Mesh>> meshes(s.layouts.size());
    std::unique_ptr<rb::Mesh>& mesh = meshes[0];
    std::unique_ptr<EmbreeScene> embree;
    for (int i = 0; i < s.runs; ++i) {
        mesh.reset();
        auto t0 = Clock::now();
        mesh = std::make_unique<rb::Mesh>(data, s.obj, s.layouts[0]);
        rbBuild.push_back(seconds(t0));
        embree.reset();
        t0 = Clock::now();
        embree = std::make_unique<EmbreeScene>(data, s.threads);
        emBuild.push_back(seconds(t0));
    }
    const Spread rbB = spread(rbBuild), emB = spread(emBuild);
    for (size_t l = 1; l < s.layouts.size(); ++l)
        meshes[l] = std::make_unique<rb::Mesh>(data, s.obj, s.layouts[l]);

    const rb::AABB box = mesh->bounds();
    const auto camera = toFloatPrecision(rbperf::cameraRays(box, 1024));
    const auto shadow = toFloatPrecision(rbperf::incoherentRays(box, 1 << 20, 7));
    const auto incoherent = rbperf::unbounded(shadow);

    std::printf(
        "BVH against Embree %d.%d.%d on %s (%zu triangles), %d thread%s, %d alternating "
        "runs: median (min-max)\n",
        RTC_VERSION_MAJOR, RTC_VERSION_MINOR, RTC_VERSION_PATCH, s.obj.c_str(),
        data.triangles.size(), s.threads, s.threads == 1 ? "" : "s", s.runs);
    std::printf(
        "  build ms: raybook %s (rb::Mesh: binned SAH, %s, triangles "
        "packed), Embree %s (medium quality); %d thread%s; raybook/Embree %.2f\n",
        show(rbB, 1e3, "%.1f").c_str(), rb::bvhLayoutDescription(mesh->bvh().layout()),
        show(emB, 1e3, "%.1f").c_str(), s.threads, s.threads == 1 ? "" : "s",
        rbB.median / emB.median);
    const double n = static_cast<double>(mesh->triangleCount());
    const double meshBytes = static_cast<double>(mesh->triangleBytes()) / n;
    const double bvhBytes = static_cast<double>(mesh->bvh().nodeBytes()) / n;
    for (const auto& m : meshes)
        std::printf(
            "  memory, %s: %.1f bytes/triangle (triangle packs and vertices %.1f, BVH nodes "
            "%.1f)\n",
            rb::bvhLayoutDescription(m->bvh().layout()),
            static_cast<double>(m->triangleBytes() + m->bvh().nodeBytes()) / n,
            static_cast<double>(m->triangleBytes()) / n,
            static_cast<double>(m->bvh().nodeBytes()) / n);
    std::printf("  %-36s %-24s %-24s %-8s %s\n", "rays", "raybook Mrays/s", "Embree Mrays/s",
                "rb/Embree", "agreement (hits raybook/Embree, hit-miss mismatches)");
    struct Set {
        const char* name;
        const char* key;  ///< For the machine-readable "target" lines.
        const std::vector<rbperf::BenchRay>* rays;
        bool anyHit;
    } sets[] = {{"coherent camera 1024^2", "coherent", &camera, false},
                {"incoherent 2^20", "incoherent", &incoherent, false},
                {"shadow (any hit) 2^20", "shadow", &shadow, true}};
    std::vector<std::pair<std::string, double>> ratios;
    for (const Set& set : sets) {
        const Query rbQuery = set.anyHit ? raybookAny : raybookClosest;
        const Query emQuery = set.anyHit ? embreeAny : embreeClosest;
        const size_t layouts = meshes.size();
        std::vector<std::vector<float>> outA(layouts, std::vector<float>(set.rays->size()));
        std::vector<float> outB(set.rays->size());
        std::vector<std::vector<double>> a(layouts);
        std::vector<double> b;
        for (int i = 0; i < s.runs; ++i) {
            for (size_t l = 0; l < layouts; ++l)
                a[l].push_back(rbQuery(meshes[l].get(), *set.rays, s.threads, outA[l]));
            b.push_back(emQuery(embree.get(), *set.rays, s.threads, outB));
        }
        const Spread sb = spread(b);
        for (size_t l = 0; l < layouts; ++l) {
            const Spread sa = spread(a[l]);
            // The first layout's ratio under the set's own name; every layout's under
            // name_layout (coherent_wide4, ...).
            if (l == 0) ratios.emplace_back(set.key, sa.median / sb.median);
            ratios.emplace_back(std::string(set.key) + "_" + layoutKey(meshes[l]->bvh().layout()),
                                sa.median / sb.median);
            // Every layout must find exactly the same hits.
            if (outA[l] != outA[0])
                std::printf("  (%s and %s DISAGREE on some rays)\n",
                            rb::bvhLayoutDescription(meshes[l]->bvh().layout()),
                            rb::bvhLayoutDescription(meshes[0]->bvh().layout()));
            const Agreement g = compare(outA[l], outB, set.anyHit);
            char agreement[160];
            std::snprintf(agreement, sizeof agreement, "%zu/%zu, %zu mismatch%s (%.1f ppm)",
                          g.hitsA, g.hitsB, g.hitMissMismatches,
                          g.hitMissMismatches == 1 ? "" : "es",
                          1e6 * g.hitMissMismatches / set.rays->size());
            const std::string name =
                std::string(set.name) + ", " + rb::bvhLayoutDescription(meshes[l]->bvh().layout());
            std::printf("  %-36s %-24s %-24s %-8.2f %s", name.c_str(), show(sa, 1e-6).c_str(),
                        show(sb, 1e-6).c_str(), sa.median / sb.median, agreement);
            if (!set.anyHit)
                std::printf(", %zu distance%s off by >1e-4", g.distanceMismatches,
                            g.distanceMismatches == 1 ? "" : "s");
            std::printf("\n");
        }
    }
    std::printf(
        "  targets (issue 12): raybook/Embree >= 1.0 coherent, >= 0.7 incoherent, >= 0.8 shadow; "
        "build <= 1.5x Embree's time (1 thread); <= 100 bytes/triangle\n");
    // Machine-readable lines for bench.sh's summary: "target <name> <value>".
    for (const auto& [key, ratio] : ratios) std::printf("target %s %.2f\n", key.c_str(), ratio);
    std::printf("target build %.2f\n", rbB.median / emB.median);
    std::printf("target bytes_per_triangle %.1f\n", meshBytes + bvhBytes);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        return run(parse(argc, argv));
    } catch (const std::exception& e) {
        std::fprintf(stderr,
                     "bvh_vs_embree: %s\nusage: bvh_vs_embree file.obj [--threads N] [--runs N] "
                     "[--bvh binary|wide|wide4|wide8[,...]]\n",
                     e.what());
        return 2;
    }
}
