/// \file
/// Chapter 9's test geometry, shared by the tests and the chart program: icospheres, smooth
/// meshes built as gr.smooth_mesh builds them, and the normal error against the true sphere.
#pragma once

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <random>
#include <vector>

#include "phong/phong.h"
#include "smooth_mesh/smooth_mesh.h"

namespace rbtest {

using rb::Vec3;

/// A uniform random stream for the sphere measurements (one per call, seeded).
class SphereRng {
  public:
    explicit SphereRng(std::uint64_t seed) : engine_(seed) {}
    /// Uniform in [lo, hi).
    double uniform(double lo, double hi) {
        return lo + (hi - lo) * static_cast<double>(engine_() >> 11) * 0x1.0p-53;
    }
    /// A uniform direction. Source: Archimedes' hat-box theorem.
    Vec3 unitVector() {
        const double z = uniform(-1.0, 1.0), phi = uniform(0.0, 2.0 * M_PI);
        const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
        return Vec3(r * std::cos(phi), r * std::sin(phi), z);
    }

  private:
    std::mt19937_64 engine_;
};

/// OBJ data of a unit icosphere: the icosahedron with each triangle split into 4^level,
/// vertices pushed onto the sphere. With `exactNormals` every corner carries its vertex's exact
/// sphere normal as `vn`.
inline rb::ObjData icosphere(int level, bool exactNormals) {
    const double t = (1.0 + std::sqrt(5.0)) / 2.0;
    std::vector<Vec3> p = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
                           {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                           {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
    for (Vec3& v : p) v = glm::normalize(v);
    std::vector<std::array<int, 3>> f = {
        {0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
        {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
        {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
    for (int l = 0; l < level; ++l) {
        std::map<std::pair<int, int>, int> middle;
        auto mid = [&](int a, int b) {
            const auto key = std::minmax(a, b);
            auto it = middle.find(key);
            if (it != middle.end()) return it->second;
            p.push_back(glm::normalize(p[a] + p[b]));
            return middle[key] = static_cast<int>(p.size()) - 1;
        };
        std::vector<std::array<int, 3>> next;
        for (const auto& [a, b, c] : f) {
            const int ab = mid(a, b), bc = mid(b, c), ca = mid(c, a);
            next.insert(next.end(), {{a, ab, ca}, {b, bc, ab}, {c, ca, bc}, {ab, bc, ca}});
        }
        f = std::move(next);
    }
    rb::ObjData data;
    data.positions = p;
    if (exactNormals) data.normals = p;
    for (const auto& [a, b, c] : f)
        data.triangles.push_back({rb::ObjCorner{a, -1, exactNormals ? a : -1},
                                  rb::ObjCorner{b, -1, exactNormals ? b : -1},
                                  rb::ObjCorner{c, -1, exactNormals ? c : -1}});
    return data;
}

/// A smooth mesh built from OBJ data, as gr.smooth_mesh builds it.
inline std::shared_ptr<rb::SmoothMesh> smoothMesh(const rb::ObjData& data,
                                                  const rb::SmoothMeshOptions& options = {}) {
    return std::make_shared<rb::SmoothMesh>(std::make_shared<rb::Mesh>(data, "test.obj"), data,
                                            options);
}

/// The hit of `ray` on an instance, with chapter 9's shading normal applied when `smooth`.
inline bool shade(
    const rb::Instance& instance, const rb::Ray& ray, rb::Hit& hit, bool smooth = true,
    rb::SmoothNormals::Terminator terminator = rb::SmoothNormals::Terminator::PerMesh) {
    rb::ObjectHit oh;
    if (!instance.intersect(ray, std::numeric_limits<double>::infinity(), oh)) return false;
    hit = instance.toWorld(ray, oh);
    if (smooth) rb::SmoothNormals(terminator).apply(ray, hit);
    return true;
}

/// The angle in radians between two unit vectors, accurate for small angles.
inline double angleBetween(const Vec3& a, const Vec3& b) {
    return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

/// The root-mean-square angle between the shading normal of a unit icosphere of `level` and
/// the normal of the true unit sphere where the same ray meets it, over `rays` random rays
/// aimed inside 0.9 of the radius (away from the silhouette).
inline double sphereNormalError(int level, bool exactNormals, bool smooth, int rays,
                                std::uint64_t seed) {
    const auto mesh = smoothMesh(icosphere(level, exactNormals));
    rb::Instance instance;
    instance.shape = mesh.get();
    instance.setTransform(rb::Mat4(1.0));
    SphereRng rng(seed);
    double sum = 0.0;
    int count = 0;
    while (count < rays) {
        // A ray from a random direction at distance 4, aimed at a random point of the disk of
        // radius 0.9 facing it.
        const Vec3 w = rng.unitVector();
        const Vec3 u =
            glm::normalize(glm::cross(w, std::abs(w.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0)));
        const Vec3 v = glm::cross(w, u);
        const double r = 0.9 * std::sqrt(rng.uniform(0.0, 1.0)), phi = rng.uniform(0.0, 2.0 * M_PI);
        const Vec3 origin = 4.0 * w;
        const Vec3 d = glm::normalize(r * std::cos(phi) * u + r * std::sin(phi) * v - origin);
        rb::Hit hit;
        if (!shade(instance, rb::Ray{origin, d}, hit, smooth)) continue;
        // The true sphere's hit along the same ray: |o + t d| = 1, nearer root.
        // Source: the ray-sphere quadratic with a = 1, b = 2 o·d, c = |o|² − 1.
        const double b = glm::dot(origin, d), c = glm::dot(origin, origin) - 1.0;
        const Vec3 truth = glm::normalize(origin + (-b - std::sqrt(b * b - c)) * d);
        const Vec3 ns = smooth ? hit.ns : rb::faceForward(hit.ng, -d);
        sum += angleBetween(ns, truth) * angleBetween(ns, truth);
        ++count;
    }
    return std::sqrt(sum / count);
}

}  // namespace rbtest
