/// \file
/// Helpers shared by the chapter tests and the stability suite: a portable random stream, the
/// feature sets of the chapter binaries, temporary folders, loading Lua scenes written inline,
/// worlds built from Lua (with rb::buildWorld, as `rt` builds them) or in code, small renders
/// and their comparison, a normal critical value, and the self-intersection probe used by the
/// "no shadow acne" tests.
#pragma once

#include <omp.h>
#include <stdlib.h>

#include <array>
#include <atomic>
#include <catch2/catch.hpp>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <filesystem>
#include <fstream>
#include <functional>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>
#include <map>
#include <memory>
#include <random>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "core/box.h"
#include "scene/chapter_features.h"
#include "phong/phong.h"
#include "bvh/bvh_aggregate.h"
#include "core/error.h"
#include "core/image.h"
#include "core/instance.h"
#include "core/integrator.h"
#include "scene/lua_scene.h"
#include "bvh/mesh.h"
#include "bvh/obj.h"
#include "core/render.h"
#include "core/render_context.h"
#include "core/sphere.h"
#include "core/world.h"
#include "adaptive_aa/adaptive_aa.h"
#include "dof/dof.h"
#include "smooth_mesh/smooth_mesh.h"
#include "bump/bump.h"
#include "csg/csg_feature.h"
#include "glossy/glossy.h"
#include "reflection/reflection.h"
#include "refraction/refraction.h"
#include "soft_shadows/soft_shadows.h"
#include "texture/texture.h"
#include "tone_map/tone_map.h"
#include "quadrics/quadrics.h"
#include "photon_map/photon_map.h"
#include "media/media.h"
#include "path_tracing/path_tracing.h"
#include "lab/chi_square.h"

namespace rbtest {

using rb::Vec3;

/// The project's root folder, where the tests read scenes and meshes (tests/source_dir.cpp).
const std::string& sourceDir();

/// Uniform random numbers from a fixed seed. The standard library's distributions are allowed
/// to differ between implementations, so the tests turn the raw std::mt19937_64 stream (whose
/// output the C++ standard fixes) into doubles themselves: the same seed gives the same rays on
/// every platform.
class Rng {
  public:
    explicit Rng(std::uint64_t seed) : engine_(seed) {}
    /// A uniform double in [0, 1): the top 53 bits of one 64-bit draw.
    double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
    /// A uniform double in [lo, hi).
    double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
    /// A uniform direction on the unit sphere.
    /// Source: Archimedes' hat-box theorem: z uniform in [-1, 1] and φ uniform in [0, 2π)
    /// give a uniform point on the sphere.
    Vec3 unitVector() {
        const double z = 1.0 - 2.0 * uniform();
        const double phi = 2.0 * glm::pi<double>() * uniform();
        const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
        return {r * std::cos(phi), r * std::sin(phi), z};
    }
    /// A uniform direction on the hemisphere around unit vector n (rejects the tangent plane).
    Vec3 hemisphere(const Vec3& n) {
        for (;;) {
            const Vec3 d = unitVector();
            const double c = glm::dot(d, n);
            if (c > 0.0) return d;
            if (c < 0.0) return -d;
        }
    }

  private:
    std::mt19937_64 engine_;
};

/// The chi-square machinery (upperGammaQ, chiSquareTail, chiSquareTest, sidak) is
/// src/lab/chi_square.h's: `./rt --warptest` runs the same code the tests run.
using rb::chiSquareTail;
using rb::chiSquareTest;
using rb::sidak;
using rb::upperGammaQ;

/// Chapters 1 to `last`, switched on by `spec` as --features does: what `rt_ch<last>` runs with.
inline rb::FeatureSet chapters(int last, const std::string& spec = "all") {
    const std::vector<rb::Feature> all = {rb::chapter01Feature(),  rb::phongFeature(),
                                          rb::bvhFeature(),  rb::reflectionFeature(),
                                          rb::refractionFeature(), rb::softShadowsFeature(),
                                          rb::glossyFeature(),     rb::adaptiveAaFeature(),
                                          rb::smoothMeshFeature(),  rb::textureFeature(),
                                          rb::bumpFeature(),        rb::toneMapFeature(),
                                          rb::dofFeature(),         rb::csgFeature(),
                                          rb::quadricsFeature(),    rb::photonMapFeature(),
                                          rb::mediaFeature(),       rb::pathTracingFeature()};
    std::vector<rb::Feature> upTo;
    for (const rb::Feature& f : all)
        if (f.chapter <= last) upTo.push_back(f);
    return rb::FeatureSet(upTo, spec);
}

/// The three core chapters, all switched on: what `rt_ch3 --features=all` runs with.
inline rb::FeatureSet coreFeatures() {
    return chapters(3);
}

/// 1, or the value of the environment variable `variable`: the seed of a file's random streams.
inline std::uint64_t seedFromEnv(const char* variable) {
    const char* s = std::getenv(variable);
    return s ? std::strtoull(s, nullptr, 10) : 1;
}

/// A fresh folder under the system's temporary directory, deleted with everything in it when
/// the object goes out of scope.
class TempDir {
  public:
    TempDir() {
        std::string pattern =
            (std::filesystem::temp_directory_path() / "raybook-test-XXXXXX").string();
        if (!::mkdtemp(pattern.data())) throw std::runtime_error("mkdtemp failed");
        path_ = pattern;
    }
    ~TempDir() {
        std::error_code ec;
        std::filesystem::remove_all(path_, ec);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
    /// The folder.
    const std::filesystem::path& path() const { return path_; }
    /// Write `text` to the file `name` inside the folder and return its full path.
    std::string write(const std::string& name, const std::string& text) const {
        const std::filesystem::path file = path_ / name;
        std::ofstream out(file, std::ios::binary);
        out << text;
        if (!out) throw std::runtime_error("cannot write " + file.string());
        return file.string();
    }

  private:
    std::filesystem::path path_;
};

// ---- Lua scenes written inline --------------------------------------------------------------

/// A gr.render call for `root` with a small image and one white light: most scene tests only
/// care about the graph, so they end with this line.
inline std::string renderLine(const std::string& root = "root") {
    return "gr.render(" + root +
           ", 'out.png', 8, 8, {0, 0, 10}, {0, 0, -1}, {0, 1, 0}, 50, {0.1, 0.1, 0.1},"
           " {gr.light({0, 0, 10}, {1, 1, 1}, {1, 0, 0})})\n";
}

/// A scene whose one object, the sphere 's', has the Lua material `material`; `extra` runs last.
inline std::string oneMaterialScene(const std::string& material, const std::string& extra = "") {
    return "local m = " + material +
           "\n"
           "root = gr.node('root')\n"
           "local s = gr.sphere('s')\n"
           "s:set_material(m)\n"
           "root:add_child(s)\n" +
           extra + renderLine();
}

/// The world bounds of the first instance named `name` in a loaded render.
inline rb::AABB boundsOf(const rb::LoadedRender& render, const std::string& name) {
    for (const rb::Instance& i : render.instances)
        if (i.name == name) return i.worldBounds;
    FAIL("no instance named " << name);
    return {};
}

/// Two points (or colours) equal to 1e-9.
inline bool near(const rb::Vec3& a, const rb::Vec3& b) {
    return glm::length(a - b) < 1e-9;
}

/// Write `lua` to `fileName` in a fresh temporary folder and run rb::loadScene on it.
inline std::vector<rb::LoadedRender> loadSceneText(const std::string& lua,
                                                   const rb::FeatureSet& features,
                                                   const std::string& fileName = "scene.lua",
                                                   bool legacy = false) {
    TempDir dir;
    rb::SceneLoadOptions options;
    options.era = legacy ? rb::EraChoice::Legacy : rb::EraChoice::Modern;
    return rb::loadScene(dir.write(fileName, lua), features, options);
}

/// loadSceneText with the core chapters.
inline std::vector<rb::LoadedRender> loadSceneText(const std::string& lua,
                                                   const std::string& fileName = "scene.lua",
                                                   bool legacy = false) {
    return loadSceneText(lua, coreFeatures(), fileName, legacy);
}

/// The message of the InputError that loading `lua` throws, or "" if it loads.
inline std::string loadError(const std::string& lua, const rb::FeatureSet& features,
                             const std::string& fileName = "scene.lua") {
    try {
        loadSceneText(lua, features, fileName);
    } catch (const rb::InputError& e) {
        return e.what();
    }
    return "";
}

/// loadError with the core chapters.
inline std::string loadError(const std::string& lua, const std::string& fileName = "scene.lua") {
    return loadError(lua, coreFeatures(), fileName);
}

/// The material of the only object of oneMaterialScene(material), loaded with `features`.
inline rb::Material materialOf(const std::string& material, const rb::FeatureSet& features) {
    const auto renders = loadSceneText(oneMaterialScene(material), features);
    REQUIRE(renders.size() == 1);
    REQUIRE(renders[0].instances.size() == 1);
    REQUIRE(renders[0].instances[0].material != nullptr);
    return *renders[0].instances[0].material;
}

// ---- Worlds ---------------------------------------------------------------------------------

/// The world of the first gr.render call in `lua`, built by rb::buildWorld as `rt` builds it.
inline std::unique_ptr<rb::World> worldFromLua(
    const std::string& lua, const rb::FeatureSet& features = coreFeatures(),
    const std::map<std::string, std::string>& featureOptions = {}) {
    return rb::buildWorld(std::move(loadSceneText(lua, features).at(0)), features, featureOptions);
}

/// The radiance the integrator returns along one ray, with sampler stream 0; counts rays.
inline rb::Colour traceOne(const rb::Scene& scene, const rb::Pipeline& pipeline, const rb::Ray& ray,
                           rb::RayCounters& counters) {
    const rb::Integrator integrator(scene, pipeline);
    rb::Sampler sampler(0, 0, 0);
    return integrator.trace(ray, sampler, counters, 0);
}

/// The radiance the integrator returns along one ray of a world.
inline rb::Colour traceOne(const rb::World& world, const rb::Ray& ray) {
    rb::RayCounters counters;
    return traceOne(world.scene, world.pipeline, ray, counters);
}

/// An instance of `shape` placed by `objectToWorld`, with an optional material.
inline rb::Instance makeInstance(const rb::Shape& shape, const rb::Mat4& objectToWorld,
                                 const rb::Material* material = nullptr,
                                 const std::string& name = "test") {
    rb::Instance instance;
    instance.shape = &shape;
    instance.material = material;
    instance.name = name;
    instance.setTransform(objectToWorld);
    return instance;
}

#if __has_include("bvh/mesh.h")  // an assignment of chapters 1-2 has no meshes
/// A mesh from positions and zero-based triangles, as if read from an OBJ file.
inline std::shared_ptr<rb::Mesh> makeMesh(const std::vector<Vec3>& positions,
                                          const std::vector<std::array<int, 3>>& triangles,
                                          const std::string& name = "test.obj") {
    rb::ObjData data;
    data.positions = positions;
    for (const auto& t : triangles)
        data.triangles.push_back({rb::ObjCorner{t[0]}, rb::ObjCorner{t[1]}, rb::ObjCorner{t[2]}});
    return std::make_shared<rb::Mesh>(data, name);
}
#endif

/// A world assembled in code and built as `rt` builds one; not movable (see scene.aggregate).
class TestWorld {
  public:
    TestWorld() = default;
    TestWorld(const TestWorld&) = delete;
    TestWorld& operator=(const TestWorld&) = delete;

    /// A copy of `m` that lives as long as the world.
    const rb::Material* material(const rb::Material& m) {
        materials_.push_back(m);
        return &materials_.back();
    }
    /// Place the unit cube [0,1]³ by objectToWorld.
    void addBox(const rb::Mat4& objectToWorld, const rb::Material* m,
                const std::string& name = "box") {
        add(box_, objectToWorld, m, name);
    }
    /// Place the unit sphere by objectToWorld.
    void addSphere(const rb::Mat4& objectToWorld, const rb::Material* m,
                   const std::string& name = "sphere") {
        add(sphere_, objectToWorld, m, name);
    }
    /// Place any shape (which must outlive the world).
    void add(const rb::Shape& shape, const rb::Mat4& objectToWorld, const rb::Material* m,
             const std::string& name = "test") {
        scene.instances.push_back(makeInstance(shape, objectToWorld, m, name));
    }
    /// Let the enabled features install themselves, then build the aggregate (`rt`'s order).
    void build(const rb::FeatureSet& features, int maxDepth = -1,
               const std::map<std::string, std::string>& featureOptions = {}) {
        if (maxDepth >= 0) scene.maxDepth = maxDepth;  // as --max-depth
        const rb::RenderJob job;
        const rb::RenderContext context{scene.instances, job, featureOptions};
        for (const rb::Feature& f : features.on())
            if (f.install) f.install(pipeline, scene, context);
        scene.aggregate = pipeline.buildAggregate(scene.instances);
    }
    /// The radiance the integrator returns along one ray; counts rays into `counters`.
    rb::Colour trace(const rb::Ray& ray, rb::RayCounters& counters) const {
        return traceOne(scene, pipeline, ray, counters);
    }
    /// The radiance the integrator returns along one ray.
    rb::Colour trace(const rb::Ray& ray) const {
        rb::RayCounters counters;
        return trace(ray, counters);
    }

    rb::Scene scene;        ///< Its aggregate refers to scene.instances.
    rb::Pipeline pipeline;  ///< What the features installed.

  private:
    std::deque<rb::Material> materials_;  // a deque never moves its elements
    rb::Box box_;
    rb::Sphere sphere_;
};

/// The unit cube stretched into the box [lo, hi].
inline rb::Mat4 boxFromTo(const Vec3& lo, const Vec3& hi) {
    return glm::scale(glm::translate(rb::Mat4(1.0), lo), hi - lo);
}

// ---- Renders and what they return -----------------------------------------------------------

/// Render a world through the camera of its gr.render call at width × height; counts rays.
inline rb::Image renderAt(const rb::World& world, int width, int height,
                          const rb::RenderSettings& settings, rb::RayCounters& counters) {
    const rb::PinholeCamera camera(world.source.job.camera, width, height);
    return rb::render(world.scene, world.pipeline, camera, width, height, settings, counters);
}

/// Render a world at the size its gr.render call asks for.
inline rb::Image renderWorld(const rb::World& world, const rb::RenderSettings& settings) {
    rb::RayCounters counters;
    return renderAt(world, world.source.job.width, world.source.job.height, settings, counters);
}

/// Render a world on one thread at width × height with `spp` samples per pixel; counts rays.
inline rb::Image renderSmall(const rb::World& world, int width, int height,
                             rb::RayCounters& counters, int spp = 1) {
    rb::RenderSettings settings;
    settings.threads = 1;
    settings.samplesPerPixel = spp;
    return renderAt(world, width, height, settings, counters);
}

/// renderSmall at 64 × 48 unless told, one ray through each pixel centre.
inline rb::Image renderSmall(const rb::World& world, int width = 64, int height = 48) {
    rb::RayCounters counters;
    return renderSmall(world, width, height, counters);
}

/// True when two images have the same size and hold exactly the same bits (NaN included).
/// A shouldStop hook that makes both threads of a 2-thread render take tiles. A test that two
/// threads give one thread's bits proves nothing when one thread takes every tile, which a
/// render of milliseconds on a busy machine allows (thread 0 finishes before thread 1 starts,
/// even 50 times in a row). So each thread, before its first tile, waits (at most 2 s) until
/// the other has asked for a tile too: then each renders at least that one. The hook only
/// waits; it stops nothing.
inline std::function<bool()> bothThreadsTakeTiles() {
    auto asked = std::make_shared<std::atomic<int>>(0);  // bit t: thread t has asked for a tile
    const auto start = std::chrono::steady_clock::now();
    return [asked, start] {
        *asked |= 1 << omp_get_thread_num();
        while (*asked != 3 && std::chrono::steady_clock::now() - start < std::chrono::seconds(2))
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
        return false;
    };
}

inline bool bitIdentical(const rb::Image& a, const rb::Image& b) {
    return a.width() == b.width() && a.height() == b.height() &&
           std::memcmp(a.data().data(), b.data().data(), a.data().size() * sizeof(float)) == 0;
}

/// True when every channel of every pixel is a finite, non-negative number.
inline bool allFiniteNonNegative(const rb::Image& image) {
    for (float c : image.data())
        if (!std::isfinite(c) || c < 0.0f) return false;
    return true;
}

/// True when every channel is a finite, non-negative number.
inline bool finiteNonNegative(const rb::Colour& c) {
    return rb::isFinite(c) && c.r >= 0.0 && c.g >= 0.0 && c.b >= 0.0;
}

// ---- Numbers --------------------------------------------------------------------------------

/// How many representable doubles lie between a and b (0 when equal). Both must be finite and
/// of the same sign.
inline std::uint64_t ulpDistance(double a, double b) {
    if (a == b) return 0;
    std::int64_t ia, ib;
    std::memcpy(&ia, &a, sizeof a);
    std::memcpy(&ib, &b, sizeof b);
    return ia > ib ? static_cast<std::uint64_t>(ia - ib) : static_cast<std::uint64_t>(ib - ia);
}

/// How many times fewer samples a test's heaviest Monte Carlo loops draw in the sanitizer tree
/// (make test-sanitize; CMake defines RB_SANITIZE_TESTS there). The sanitizers check the code
/// each sample runs, and a tenth of the samples runs the same code, at several times the cost of
/// a sample in the normal tree. A z-test on fewer samples is still a z-test: its error bar
/// widens with them. The normal tree runs every test at full strength.
#ifdef RB_SANITIZE_TESTS
constexpr int kSanitizerShare = 10;
#else
constexpr int kSanitizerShare = 1;
#endif

/// n samples, or a kSanitizerShare-th of them in the sanitizer tree.
constexpr int samples(int n) { return n / kSanitizerShare; }

/// The mean of n draws draw(0), ..., draw(n − 1), and the standard error of that mean (the
/// sample standard deviation over √n): what the z-tests of a Monte Carlo estimator compare.
template <class Draw>
std::pair<double, double> meanAndError(int n, Draw&& draw) {
    double sum = 0.0, sum2 = 0.0;
    for (int i = 0; i < n; ++i) {
        const double x = draw(i);
        sum += x;
        sum2 += x * x;
    }
    const double mean = sum / n;
    const double variance = std::max(0.0, (sum2 - n * mean * mean) / (n - 1));
    return {mean, std::sqrt(variance / n)};
}

/// The z with P(|Z| > z) = alpha for a standard normal Z: erfc(z/√2) = alpha, by bisection.
inline double zCritical(double alpha) {
    double lo = 0, hi = 40;
    for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (lo + hi);
        (std::erfc(mid / std::sqrt(2.0)) > alpha ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

// ---- The self-intersection probe ------------------------------------------------------------

/// A point found on a surface by a ray from outside, with the hit that found it.
struct SurfacePoint {
    rb::Hit hit;    ///< World-space hit (p, unit ng).
    rb::Ray probe;  ///< The ray that found it.
};

/// Shoot rays at an instance from random points on a sphere around its world bounds, aimed at
/// random points inside the bounds, and return the first `count` surface points they find.
inline std::vector<SurfacePoint> sampleSurface(const rb::Instance& instance, Rng& rng,
                                               size_t count) {
    const rb::AABB& b = instance.worldBounds;
    const Vec3 centre = b.centre();
    const double radius = glm::length(b.hi - b.lo);
    std::vector<SurfacePoint> points;
    for (size_t attempt = 0; points.size() < count && attempt < 100 * count; ++attempt) {
        const Vec3 origin = centre + 2.0 * radius * rng.unitVector();
        const Vec3 target(rng.uniform(b.lo.x, b.hi.x), rng.uniform(b.lo.y, b.hi.y),
                          rng.uniform(b.lo.z, b.hi.z));
        const rb::Ray ray{origin, target - origin};
        rb::ObjectHit oh;
        if (!instance.intersect(ray, std::numeric_limits<double>::infinity(), oh)) continue;
        points.push_back({instance.toWorld(ray, oh), ray});
    }
    return points;
}

/// The new ray a renderer would spawn from a surface point in direction `dir`: its origin is
/// moved off the surface by rb::offsetRayOrigin, to the side `dir` leaves towards.
inline rb::Ray spawnRay(const rb::Hit& hit, const Vec3& dir) {
    return rb::Ray{rb::offsetRayOrigin(hit.p, hit.ng, dir), dir};
}

/// The mirror direction of d about the unit normal n. Source: r = d − 2(d·n)n.
inline Vec3 mirror(const Vec3& d, const Vec3& n) {
    return d - 2.0 * glm::dot(d, n) * n;
}

/// The scene scales the design asks every spawned-ray test to survive (DESIGN §5 row 2).
inline const std::array<double, 5> kSceneScales = {1e-3, 1e-1, 1.0, 1e2, 1e4};

/// The object-to-world transform of a test object of size `scale`: stretched a little
/// differently along each axis (`stretch`), turned about a skew axis so no face is
/// axis-aligned, and moved a few sizes away from the origin so that world coordinates are
/// larger than the object (as they are in real scenes).
inline rb::Mat4 placeAtScale(double scale, const Vec3& stretch = Vec3(1.0)) {
    rb::Mat4 m(1.0);
    m = glm::translate(m, scale * Vec3(3.0, -2.0, 5.0));
    m = glm::rotate(m, 0.7, glm::normalize(Vec3(1.0, 2.0, -0.5)));
    m = glm::scale(m, scale * stretch);
    return m;
}

}  // namespace rbtest
