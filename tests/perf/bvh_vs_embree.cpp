// bvh_vs_embree: raybook's mesh BVH against Embree 3 on the same OBJ and the same rays, in one
// process. Single-ray APIs on both sides (rb::Mesh::intersect / occluded against rtcIntersect1 /
// rtcOccluded1), medians of alternating runs, and a per-ray check that both find the same hits.
// A benchmark for `make bench`, not a test. Embree is traced twice: in its default mode (the
// target) and in its robust mode (RTC_SCENE_FLAG_ROBUST), which, like raybook, never lets a ray
// slip between two triangles: the like-for-like comparison.
//
// usage: bvh_vs_embree file.obj [--threads N] [--runs N] [--bvh LAYOUT[,LAYOUT...]]
//        (defaults: 1 thread, 5 runs, wide: the widest layout this CPU runs). With several
//        layouts (e.g. --bvh wide4,wide8), each run traces every layout, then Embree, then
//        Embree robust, in turn, so each layout is compared with the same Embree under the same
//        load; the "target" lines are the first layout's.
//        bvh_vs_embree file.obj --profile SIDE KIND [--rays N] [--passes P]
//        traces one ray set on one side only, for valgrind (tests/perf/bvh_callgrind.sh): SIDE
//        is raybook, embree or embree-robust, KIND coherent, incoherent or shadow; N rays
//        (default 65536; coherent: a √N × √N camera), P passes over them (default 2). Under
//        callgrind (--instr-atstart=no --collect-atstart=no) the setup is not instrumented, the
//        first passes warm the caches, and only the last is collected.
//        bvh_vs_embree file.obj --counts [--rays N]
//        prints raybook's work per ray on those ray sets: wide nodes visited, packs of four
//        triangles filtered, exact tests run.
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

#if __has_include(<valgrind/callgrind.h>)
#include <valgrind/callgrind.h>
#define RB_HAVE_CALLGRIND 1
#else
#define RB_HAVE_CALLGRIND 0
#endif

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
    /// Build from OBJ data with `threads` build threads; `robust` sets RTC_SCENE_FLAG_ROBUST
    /// (Embree's watertight mode: no ray slips between triangles or past a box it grazes).
    EmbreeScene(const rb::ObjData& data, int threads, bool robust) {
        const std::string config = "threads=" + std::to_string(threads);
        device = rtcNewDevice(config.c_str());
        if (!device) throw std::runtime_error("rtcNewDevice failed");
        scene = rtcNewScene(device);
        if (robust) rtcSetSceneFlags(scene, RTC_SCENE_FLAG_ROBUST);
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
    std::vector<rb::BVHLayout> layouts;    ///< Empty: the default, rb::bestWideLayout().
    std::string profileSide, profileKind;  ///< --profile SIDE KIND; empty: the benchmark.
    bool counts = false;                   ///< --counts.
    int rays = 1 << 16;                    ///< Rays per set for --profile and --counts.
    int passes = 2;                        ///< Passes over the rays for --profile.
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
        } else if ((a == "--threads" || a == "--runs" || a == "--rays" || a == "--passes") &&
                   i + 1 < argc) {
            const int v = std::max(1, std::atoi(argv[++i]));
            (a == "--threads" ? s.threads
             : a == "--runs"  ? s.runs
             : a == "--rays"  ? s.rays
                              : s.passes) = v;
        } else if (a == "--profile" && i + 2 < argc) {
            s.profileSide = argv[++i];
            s.profileKind = argv[++i];
            if (s.profileSide != "raybook" && s.profileSide != "embree" &&
                s.profileSide != "embree-robust")
                throw rb::InputError("--profile: no side '" + s.profileSide +
                                     "' (raybook, embree or embree-robust)");
        } else if (a == "--counts") {
            s.counts = true;
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

/// The ray set `kind` (coherent, incoherent or shadow) of --profile and --counts: the first
/// `count` rays of the benchmark's incoherent and shadow sets, or a ⌊√count⌋² camera of the
/// coherent set's field of view. `anyHit` says whether it is the shadow set.
std::vector<rbperf::BenchRay> raysOfKind(const std::string& kind, const rb::AABB& box, int count,
                                         bool& anyHit) {
    anyHit = kind == "shadow";
    if (kind == "coherent") {
        const int side = static_cast<int>(std::sqrt(static_cast<double>(count)));
        return toFloatPrecision(rbperf::cameraRays(box, side));
    }
    if (kind != "incoherent" && kind != "shadow")
        throw rb::InputError("no ray kind '" + kind + "' (coherent, incoherent or shadow)");
    auto rays = toFloatPrecision(rbperf::incoherentRays(box, count, 7));
    return anyHit ? rays : rbperf::unbounded(std::move(rays));
}

/// --profile: trace one ray set on one side, `passes` times, collecting only the last pass
/// under callgrind (started with --instr-atstart=no --collect-atstart=no).
int profile(const Settings& s, const rb::ObjData& data) {
#if RB_HAVE_CALLGRIND
    omp_set_num_threads(1);
    const rb::AABB box = rb::Mesh(data, s.obj, s.layouts[0]).bounds();  // the benchmark's box
    bool anyHit = false;
    const auto rays = raysOfKind(s.profileKind, box, s.rays, anyHit);
    std::unique_ptr<rb::Mesh> mesh;
    std::unique_ptr<EmbreeScene> embree;
    if (s.profileSide == "raybook")
        mesh = std::make_unique<rb::Mesh>(data, s.obj, s.layouts[0]);
    else
        embree = std::make_unique<EmbreeScene>(data, 1, s.profileSide == "embree-robust");
    const void* target = mesh ? static_cast<const void*>(mesh.get()) : embree.get();
    const Query query =
        mesh ? (anyHit ? raybookAny : raybookClosest) : (anyHit ? embreeAny : embreeClosest);
    std::vector<float> out(rays.size());
    CALLGRIND_START_INSTRUMENTATION;
    for (int pass = 0; pass < s.passes; ++pass) {
        if (pass == s.passes - 1) CALLGRIND_TOGGLE_COLLECT;
        query(target, rays, 1, out);
        if (pass == s.passes - 1) CALLGRIND_TOGGLE_COLLECT;
    }
    CALLGRIND_STOP_INSTRUMENTATION;
    const size_t hits = static_cast<size_t>(std::count_if(
        out.begin(), out.end(), [&](float v) { return anyHit ? v != 0.0f : v != kMiss; }));
    std::printf("profile %s%s%s %s rays %zu passes %d hits %zu\n", s.profileSide.c_str(),
                mesh ? " " : "", mesh ? rb::bvhLayoutDescription(mesh->bvh().layout()) : "",
                s.profileKind.c_str(), rays.size(), s.passes, hits);
    return 0;
#else
    (void)s;
    (void)data;
    throw rb::InputError("--profile needs valgrind/callgrind.h (apt-get install valgrind)");
#endif
}

/// --counts: raybook's work per ray on the ray sets of --profile.
int counts(const Settings& s, const rb::ObjData& data) {
    const rb::Mesh mesh(data, s.obj, s.layouts[0]);
    std::printf(
        "# raybook %s on %s, %d rays per set: per ray, wide nodes visited, packs of four "
        "triangles through the float test, exact double tests\n",
        rb::bvhLayoutDescription(mesh.bvh().layout()), s.obj.c_str(), s.rays);
    for (const char* kind : {"coherent", "incoherent", "shadow"}) {
        bool anyHit = false;
        const auto rays = raysOfKind(kind, mesh.bounds(), s.rays, anyHit);
        rb::TraversalCounts c;
        for (const auto& r : rays) {
            rb::ObjectHit h;
            if (anyHit)
                mesh.occluded(rb::Ray{r.o, r.d}, r.tMax, c);
            else
                mesh.intersect(rb::Ray{r.o, r.d}, r.tMax, h, c);
        }
        const double n = static_cast<double>(rays.size());
        std::printf("counts %s nodes %.2f packs %.2f exact %.2f\n", kind, c.nodes / n, c.packs / n,
                    c.exactTests / n);
    }
    return 0;
}

int run(const Settings& s) {
    const rb::ObjData data = rb::loadObj(s.obj);
    if (!s.profileSide.empty()) return profile(s, data);
    if (s.counts) return counts(s, data);
    // raybook's build splits big ranges as OpenMP tasks: give it the same threads as Embree.
    omp_set_num_threads(s.threads);

    // Build times, alternating raybook and Embree.
    // The first layout's build is timed; the others are built once, after.
    std::vector<double> rbBuild, emBuild;
    std::vector<std::unique_ptr<rb::Mesh>> meshes(s.layouts.size());
    std::unique_ptr<rb::Mesh>& mesh = meshes[0];
    std::unique_ptr<EmbreeScene> embree, robust;
    for (int i = 0; i < s.runs; ++i) {
        mesh.reset();
        auto t0 = Clock::now();
        mesh = std::make_unique<rb::Mesh>(data, s.obj, s.layouts[0]);
        rbBuild.push_back(seconds(t0));
        embree.reset();
        t0 = Clock::now();
        embree = std::make_unique<EmbreeScene>(data, s.threads, false);
        emBuild.push_back(seconds(t0));
    }
    robust = std::make_unique<EmbreeScene>(data, s.threads, true);
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
    std::printf("  %-36s %-24s %-24s %-24s %-8s %-9s %s\n", "rays", "raybook Mrays/s",
                "Embree Mrays/s", "Embree robust Mrays/s", "rb/Embree", "rb/robust",
                "agreement (hits raybook/Embree, hit-miss mismatches; the same against robust)");
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
        std::vector<float> outB(set.rays->size()), outC(set.rays->size());
        std::vector<std::vector<double>> a(layouts);
        std::vector<double> b, c;
        for (int i = 0; i < s.runs; ++i) {
            for (size_t l = 0; l < layouts; ++l)
                a[l].push_back(rbQuery(meshes[l].get(), *set.rays, s.threads, outA[l]));
            b.push_back(emQuery(embree.get(), *set.rays, s.threads, outB));
            c.push_back(emQuery(robust.get(), *set.rays, s.threads, outC));
        }
        const Spread sb = spread(b), sc = spread(c);
        for (size_t l = 0; l < layouts; ++l) {
            const Spread sa = spread(a[l]);
            // The first layout's ratio under the set's own name; every layout's under
            // name_layout (coherent_wide4, ...).
            // Against robust mode: name_robust (coherent_robust, ...) and name_layout_robust.
            const std::string layoutName =
                std::string(set.key) + "_" + layoutKey(meshes[l]->bvh().layout());
            if (l == 0) {
                ratios.emplace_back(set.key, sa.median / sb.median);
                ratios.emplace_back(std::string(set.key) + "_robust", sa.median / sc.median);
            }
            ratios.emplace_back(layoutName, sa.median / sb.median);
            ratios.emplace_back(layoutName + "_robust", sa.median / sc.median);
            // Every layout must find exactly the same hits.
            if (outA[l] != outA[0])
                std::printf("  (%s and %s DISAGREE on some rays)\n",
                            rb::bvhLayoutDescription(meshes[l]->bvh().layout()),
                            rb::bvhLayoutDescription(meshes[0]->bvh().layout()));
            const Agreement g = compare(outA[l], outB, set.anyHit);
            const Agreement gr = compare(outA[l], outC, set.anyHit);
            // "hits raybook/Embree, mismatches[, distances off]; the same against robust".
            const auto agree = [&](const Agreement& x) {
                char text[160];
                int n = std::snprintf(text, sizeof text, "%zu/%zu, %zu mismatch%s (%.1f ppm)",
                                      x.hitsA, x.hitsB, x.hitMissMismatches,
                                      x.hitMissMismatches == 1 ? "" : "es",
                                      1e6 * x.hitMissMismatches / set.rays->size());
                if (!set.anyHit)
                    std::snprintf(text + n, sizeof text - n, ", %zu distance%s off by >1e-4",
                                  x.distanceMismatches, x.distanceMismatches == 1 ? "" : "s");
                return std::string(text);
            };
            const std::string agreement = agree(g) + "; robust " + agree(gr);
            const std::string name =
                std::string(set.name) + ", " + rb::bvhLayoutDescription(meshes[l]->bvh().layout());
            std::printf("  %-36s %-24s %-24s %-24s %-8.2f %-9.2f %s", name.c_str(),
                        show(sa, 1e-6).c_str(), show(sb, 1e-6).c_str(), show(sc, 1e-6).c_str(),
                        sa.median / sb.median, sa.median / sc.median, agreement.c_str());
            std::printf("\n");
        }
    }
    std::printf(
        "  targets (issue 12): raybook/Embree >= 1.0 coherent, >= 0.7 incoherent, >= 0.8 shadow; "
        "build <= 1.5x Embree's time (1 thread); <= 100 bytes/triangle; (issue 41) "
        "raybook/Embree robust >= 1.0 on all three\n");
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
