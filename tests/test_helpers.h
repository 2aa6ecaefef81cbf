/// \file
/// Helpers shared by the chapter 1–3 tests and the stability suite: a portable random stream,
/// temporary folders, loading Lua scenes written inline, building a renderable world the way
/// `rt` does, and the self-intersection probe used by the "no shadow acne" tests.
#pragma once

#include <stdlib.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>
#include <map>
#include <memory>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "core/chapter_features.h"
#include "core/image.h"
#include "core/instance.h"
#include "core/integrator.h"
#include "core/lua_scene.h"
#include "core/mesh.h"
#include "core/obj.h"
#include "core/render_context.h"

namespace rbtest {

using rb::Vec3;

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

/// The three core chapters, all switched on: what `rt_ch3 --features=all` runs with.
inline rb::FeatureSet coreFeatures() {
    return rb::FeatureSet({rb::chapter01Feature(), rb::chapter02Feature(), rb::chapter03Feature()},
                          "all");
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

/// A gr.render call for `root` with a small image and one white light: most scene tests only
/// care about the graph, so they end with this line.
inline std::string renderLine(const std::string& root = "root") {
    return "gr.render(" + root +
           ", 'out.png', 8, 8, {0, 0, 10}, {0, 0, -1}, {0, 1, 0}, 50, {0.1, 0.1, 0.1},"
           " {gr.light({0, 0, 10}, {1, 1, 1}, {1, 0, 0})})\n";
}

/// Write `lua` to `fileName` in a fresh temporary folder and run it through rb::loadScene with
/// the core chapters. Throws what loadScene throws.
inline std::vector<rb::LoadedRender> loadSceneText(const std::string& lua,
                                                   const std::string& fileName = "scene.lua",
                                                   bool legacy = false) {
    TempDir dir;
    rb::SceneLoadOptions options;
    options.legacy = legacy;
    return rb::loadScene(dir.write(fileName, lua), coreFeatures(), options);
}

/// A renderable world put together the way `rt` does it (src/core/main.cpp): the pipeline of
/// the enabled features, the instances of one gr.render call, their aggregate and lights.
/// Not movable: the aggregate refers to `scene.instances`.
struct World {
    rb::LoadedRender loaded;  ///< Keeps the scene graph (and so the shapes) alive.
    rb::Pipeline pipeline;
    rb::Scene scene;
    World() = default;
    World(const World&) = delete;
    World& operator=(const World&) = delete;
    /// The camera of the gr.render call.
    rb::PinholeCamera camera() const {
        return rb::PinholeCamera(loaded.job.camera, loaded.job.width, loaded.job.height);
    }
};

/// Install the enabled core features into a pipeline for one render, as `rt` does, with no
/// command-line feature options.
inline void installCore(rb::Pipeline& pipeline, rb::Scene& scene, const rb::RenderJob& job) {
    static const std::map<std::string, std::string> kNoOptions;
    const rb::RenderContext context{scene.instances, job, kNoOptions};
    const rb::FeatureSet features = coreFeatures();  // outlives the loop over its list
    for (const rb::Feature& f : features.on())
        if (f.install) f.install(pipeline, scene, context);
}

/// Build the world of render request `index` from loaded scene requests, in the order of
/// src/core/main.cpp: instances, lights and ambient; the features plug in; the aggregate.
inline std::unique_ptr<World> buildWorld(std::vector<rb::LoadedRender> renders, size_t index = 0) {
    auto world = std::make_unique<World>();
    world->loaded = std::move(renders.at(index));
    world->scene.instances = std::move(world->loaded.instances);
    world->scene.lights = world->loaded.job.lights;
    world->scene.ambient = world->loaded.job.ambient;
    installCore(world->pipeline, world->scene, world->loaded.job);
    world->scene.aggregate = world->pipeline.buildAggregate(world->scene.instances);
    return world;
}

/// Load a scene written inline and build the world of its first gr.render call.
inline std::unique_ptr<World> worldFromLua(const std::string& lua) {
    return buildWorld(loadSceneText(lua));
}

/// The radiance the integrator returns along one ray of a world.
inline rb::Colour traceOne(const World& world, const rb::Ray& ray) {
    const rb::Integrator integrator(world.scene, world.pipeline);
    rb::Sampler sampler(0, 0, 0);
    rb::RayCounters counters;
    return integrator.trace(ray, sampler, counters, 0);
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

/// How many representable doubles lie between a and b (0 when equal). Both must be finite and
/// of the same sign.
inline std::uint64_t ulpDistance(double a, double b) {
    if (a == b) return 0;
    std::int64_t ia, ib;
    std::memcpy(&ia, &a, sizeof a);
    std::memcpy(&ib, &b, sizeof b);
    return ia > ib ? static_cast<std::uint64_t>(ia - ib) : static_cast<std::uint64_t>(ib - ia);
}

/// True when every channel of every pixel is a finite, non-negative number.
inline bool allFiniteNonNegative(const rb::Image& image) {
    for (float c : image.data())
        if (!std::isfinite(c) || c < 0.0f) return false;
    return true;
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
