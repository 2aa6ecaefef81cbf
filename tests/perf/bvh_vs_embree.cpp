// bvh_vs_embree: raybook's mesh BVH against Embree 3 on the same OBJ and the same rays, in one
// process. Single-ray APIs on both sides (Mesh::intersect / occluded against rtcIntersect1 /
// rtcOccluded1), one thread, medians of alternating runs. A benchmark, not a test.
//
// usage: bvh_vs_embree file.obj [runs]
#include <embree3/rtcore.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>
#include <string>

#include "core/mesh.h"
#include "core/obj.h"
#include "ray_sets.h"

namespace {

using Clock = std::chrono::steady_clock;
double seconds(Clock::time_point t0) {
    return std::chrono::duration<double>(Clock::now() - t0).count();
}
double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

/// An Embree scene holding one triangle mesh.
struct EmbreeScene {
    RTCDevice device = rtcNewDevice(nullptr);
    RTCScene scene = nullptr;
    explicit EmbreeScene(const rb::ObjData& data) {
        scene = rtcNewScene(device);
        rtcSetSceneBuildQuality(scene, RTC_BUILD_QUALITY_MEDIUM);
        RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(
            geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float),
            data.positions.size()));
        for (size_t i = 0; i < data.positions.size(); ++i)
            for (int k = 0; k < 3; ++k) v[3 * i + k] = static_cast<float>(data.positions[i][k]);
        auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
            geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned),
            data.triangles.size()));
        for (size_t t = 0; t < data.triangles.size(); ++t)
            for (int k = 0; k < 3; ++k) idx[3 * t + k] = static_cast<unsigned>(data.triangles[t][k].v);
        rtcCommitGeometry(geom);
        rtcAttachGeometry(scene, geom);
        rtcReleaseGeometry(geom);
        rtcCommitScene(scene);
    }
    ~EmbreeScene() {
        rtcReleaseScene(scene);
        rtcReleaseDevice(device);
    }
};

RTCRayHit embreeRay(const rbperf::BenchRay& r) {
    RTCRayHit rh{};
    rh.ray.org_x = static_cast<float>(r.o.x);
    rh.ray.org_y = static_cast<float>(r.o.y);
    rh.ray.org_z = static_cast<float>(r.o.z);
    rh.ray.dir_x = static_cast<float>(r.d.x);
    rh.ray.dir_y = static_cast<float>(r.d.y);
    rh.ray.dir_z = static_cast<float>(r.d.z);
    rh.ray.tnear = 0.0f;
    rh.ray.tfar = static_cast<float>(std::min(r.tMax, 1e30));
    rh.ray.mask = 0xFFFFFFFF;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    return rh;
}

/// Rays per second of raybook's closest-hit query; counts hits.
double raybookClosest(const rb::Mesh& mesh, const std::vector<rbperf::BenchRay>& rays, size_t& hits) {
    hits = 0;
    const auto t0 = Clock::now();
    for (const auto& r : rays) {
        rb::ObjectHit h;
        hits += mesh.intersect(rb::Ray{r.o, r.d}, r.tMax, h);
    }
    return rays.size() / seconds(t0);
}
double raybookAny(const rb::Mesh& mesh, const std::vector<rbperf::BenchRay>& rays, size_t& hits) {
    hits = 0;
    const auto t0 = Clock::now();
    for (const auto& r : rays) hits += mesh.occluded(rb::Ray{r.o, r.d}, r.tMax * (1 - 1e-9));
    return rays.size() / seconds(t0);
}
double embreeClosest(const EmbreeScene& e, const std::vector<rbperf::BenchRay>& rays, size_t& hits) {
    hits = 0;
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    const auto t0 = Clock::now();
    for (const auto& r : rays) {
        RTCRayHit rh = embreeRay(r);
        rtcIntersect1(e.scene, &context, &rh);
        hits += rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
    }
    return rays.size() / seconds(t0);
}
double embreeAny(const EmbreeScene& e, const std::vector<rbperf::BenchRay>& rays, size_t& hits) {
    hits = 0;
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    const auto t0 = Clock::now();
    for (const auto& r : rays) {
        RTCRayHit rh = embreeRay(r);
        rh.ray.tfar *= 1.0f - 1e-6f;
        rtcOccluded1(e.scene, &context, &rh.ray);
        hits += rh.ray.tfar < 0.0f;  // Embree sets tfar to -inf on a hit
    }
    return rays.size() / seconds(t0);
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: bvh_vs_embree file.obj [runs]\n");
        return 2;
    }
    const int runs = argc > 2 ? std::max(1, std::atoi(argv[2])) : 5;
    const rb::ObjData data = rb::loadObj(argv[1]);

    // Build times, alternating, medians.
    std::vector<double> rbBuild, emBuild;
    std::unique_ptr<rb::Mesh> mesh;
    std::unique_ptr<EmbreeScene> embree;
    for (int i = 0; i < runs; ++i) {
        auto t0 = Clock::now();
        mesh = std::make_unique<rb::Mesh>(data, argv[1]);
        rbBuild.push_back(seconds(t0));
        t0 = Clock::now();
        embree = std::make_unique<EmbreeScene>(data);
        emBuild.push_back(seconds(t0));
    }
    const rb::AABB box = mesh->bounds();
    const auto camera = rbperf::cameraRays(box, 1024);
    const auto incoherent = rbperf::incoherentRays(box, 1 << 20, 7);

    std::printf("BVH against Embree %d.%d.%d on %s (%zu triangles), 1 thread, median of %d runs\n",
                RTC_VERSION_MAJOR, RTC_VERSION_MINOR, RTC_VERSION_PATCH, argv[1],
                data.triangles.size(), runs);
    std::printf("  build: raybook %.1f ms (SAH, double), Embree %.1f ms (medium quality)\n",
                1e3 * median(rbBuild), 1e3 * median(emBuild));
    std::printf("  %-22s %-24s %-24s %6s %s\n", "rays", "raybook Mrays/s (min-max)",
                "Embree Mrays/s (min-max)", "ratio", "hit agreement");
    struct Set {
        const char* name;
        const std::vector<rbperf::BenchRay>* rays;
        bool shadow;
    } sets[] = {{"coherent 1024^2 camera", &camera, false},
                {"incoherent 2^20", &incoherent, false},
                {"any-hit (shadow) 2^20", &incoherent, true}};
    for (const Set& set : sets) {
        std::vector<double> a, b;
        size_t hitsA = 0, hitsB = 0;
        for (int i = 0; i < runs; ++i) {
            a.push_back(set.shadow ? raybookAny(*mesh, *set.rays, hitsA)
                                   : raybookClosest(*mesh, *set.rays, hitsA));
            b.push_back(set.shadow ? embreeAny(*embree, *set.rays, hitsB)
                                   : embreeClosest(*embree, *set.rays, hitsB));
        }
        const double ma = median(a) / 1e6, mb = median(b) / 1e6;
        char ra[64], rb2[64];
        std::snprintf(ra, sizeof ra, "%.2f (%.2f-%.2f)", ma, *std::min_element(a.begin(), a.end()) / 1e6,
                      *std::max_element(a.begin(), a.end()) / 1e6);
        std::snprintf(rb2, sizeof rb2, "%.2f (%.2f-%.2f)", mb, *std::min_element(b.begin(), b.end()) / 1e6,
                      *std::max_element(b.begin(), b.end()) / 1e6);
        std::printf("  %-22s %-24s %-24s %6.2f hits %zu vs %zu (%+.4f%%)\n", set.name, ra, rb2,
                    ma / mb, hitsA, hitsB,
                    100.0 * (double(hitsA) - double(hitsB)) / double(set.rays->size()));
    }
    std::printf("  target: ratio >= 0.5 on coherent and incoherent rays\n");
    return 0;
}
