#include "path_tracing/emitters.h"

#include <algorithm>
#include <cmath>

#include "bvh/mesh.h"
#include "core/box.h"
#include "core/sphere.h"
#include "photon_map/emission.h"

namespace rb {

namespace {

/// True when the material emits.
bool emits(const Material* m) {
    return m && (m->emission.r > 0.0 || m->emission.g > 0.0 || m->emission.b > 0.0);
}

/// The radius of the unit sphere under `m` when m scales it uniformly, else 0.
double uniformRadius(const Mat4& m) {
    const double x = glm::length(Vec3(m[0])), y = glm::length(Vec3(m[1])),
                 z = glm::length(Vec3(m[2]));
    const double tol = 1e-9 * std::max({x, y, z});
    const bool orthogonal = std::abs(glm::dot(Vec3(m[0]), Vec3(m[1]))) <= tol * x &&
                            std::abs(glm::dot(Vec3(m[1]), Vec3(m[2]))) <= tol * y &&
                            std::abs(glm::dot(Vec3(m[0]), Vec3(m[2]))) <= tol * z;
    return orthogonal && std::abs(x - y) <= tol && std::abs(x - z) <= tol ? x : 0.0;
}

/// The twelve object-space triangles of the unit cube, each with its outward face normal.
void cubeTriangles(std::vector<std::array<Vec3, 4>>& out) {
    for (int axis = 0; axis < 3; ++axis)
        for (int side = 0; side < 2; ++side) {
            const int u = (axis + 1) % 3, v = (axis + 2) % 3;
            Vec3 corner[4];
            for (int k = 0; k < 4; ++k) {
                corner[k][axis] = side;
                corner[k][u] = (k == 1 || k == 2) ? 1.0 : 0.0;
                corner[k][v] = (k >= 2) ? 1.0 : 0.0;
            }
            Vec3 normal(0.0);
            normal[axis] = side ? 1.0 : -1.0;
            out.push_back({corner[0], corner[1], corner[2], normal});
            out.push_back({corner[0], corner[2], corner[3], normal});
        }
}

}  // namespace

Emitters::Emitters(const std::vector<Instance>& instances) {
    std::vector<double> power;
    for (const Instance& instance : instances) {
        if (!emits(instance.material)) continue;
        Emitter e{&instance, {}, {}, Vec3(0.0), 0.0, 0.0};
        // Step 1: the object-space triangles (or the sphere) of the shape.
        std::vector<std::array<Vec3, 4>> local;  // a, b, c and the object-space normal
        if (dynamic_cast<const Box*>(instance.shape)) {
            cubeTriangles(local);
        } else if (const Mesh* mesh = instance.shape->triangleMesh();
                   mesh && mesh == instance.shape) {
            for (const Mesh::Triangle& t : mesh->triangles())
                local.push_back(
                    {t.v[0], t.v[1], t.v[2], glm::cross(t.v[1] - t.v[0], t.v[2] - t.v[0])});
        } else if (dynamic_cast<const Sphere*>(instance.shape)) {
            e.radius = uniformRadius(instance.objectToWorld);
            if (e.radius > 0.0) {
                e.centre = transformPoint(instance.objectToWorld, Vec3(0.0));
                e.area = 4.0 * M_PI * e.radius * e.radius;
            }
        }
        // Step 2: to world space, where an affine map keeps each triangle flat and uniform.
        for (const auto& t : local) {
            Triangle w;
            w.a = transformPoint(instance.objectToWorld, t[0]);
            w.e1 = transformPoint(instance.objectToWorld, t[1]) - w.a;
            w.e2 = transformPoint(instance.objectToWorld, t[2]) - w.a;
            const double area = 0.5 * glm::length(glm::cross(w.e1, w.e2));
            if (!(area > 0.0)) continue;
            w.n = glm::normalize(instance.normalToWorld * t[3]);
            e.area += area;
            e.triangles.push_back(w);
            e.areaCdf.push_back(e.area);
        }
        if (!(e.area > 0.0) || !std::isfinite(e.area)) continue;  // found by bounces alone
        const Colour& Le = instance.material->emission;
        power.push_back(e.area * (Le.r + Le.g + Le.b) / 3.0);
        index_[&instance] = static_cast<int>(emitters_.size());
        emitters_.push_back(std::move(e));
    }
    double total = 0.0;
    for (double p : power) cdf_.push_back(total += p);
    for (double& c : cdf_) c /= total;
}

// [emitter-sample]
EmitterSample Emitters::sample(double u, const Vec2& uv) const {
    // Step 1: the emitter, by power; u is reused, rescaled, for the triangle.
    const size_t k = std::min<size_t>(std::upper_bound(cdf_.begin(), cdf_.end(), u) - cdf_.begin(),
                                      cdf_.size() - 1);
    const double lo = k == 0 ? 0.0 : cdf_[k - 1];
    const double chosen = cdf_[k] - lo;
    const Emitter& e = emitters_[k];
    EmitterSample s;
    s.Le = e.instance->material->emission;
    s.pdfArea = chosen / e.area;
    const double v = std::clamp((u - lo) / chosen, 0.0, 1.0);
    if (e.triangles.empty()) {
        // A sphere: uniform over its whole area (the far half fails the cosine test).
        const Vec3 d = sampleUniformSphere(uv.x, uv.y);
        s.p = e.centre + e.radius * d;
        s.n = d;
        return s;
    }
    // Step 2: a triangle by area, then a uniform point on it (the square root warp).
    const double target = v * e.area;
    const size_t t = std::min<size_t>(
        std::upper_bound(e.areaCdf.begin(), e.areaCdf.end(), target) - e.areaCdf.begin(),
        e.triangles.size() - 1);
    const Triangle& tri = e.triangles[t];
    const double su = std::sqrt(uv.x);
    s.p = tri.a + su * (1.0 - uv.y) * tri.e1 + su * uv.y * tri.e2;
    s.n = tri.n;
    return s;
}
// [emitter-sample]

double Emitters::pdfArea(const Instance* instance) const {
    const auto it = index_.find(instance);
    if (it == index_.end()) return 0.0;
    const int k = it->second;
    return (cdf_[k] - (k == 0 ? 0.0 : cdf_[k - 1])) / emitters_[k].area;
}

}  // namespace rb
