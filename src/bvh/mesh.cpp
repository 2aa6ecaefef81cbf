#include "bvh/mesh.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "bvh/triangle.h"
#include "core/error.h"

namespace rb {

Mesh::Mesh(const ObjData& data, const std::string& name, BVHLayout layout) {
    // The mesh keeps its vertices in float, as Embree and POV-Ray do: everything below (the
    // area test, the boxes, the packs) reads them rounded, so the boxes hold what is tested.
    const std::vector<glm::vec3> rounded(data.positions.begin(), data.positions.end());
    auto position = [&](int i) { return Vec3(rounded[static_cast<size_t>(i)]); };
    // Keep the triangles with non-zero area; a degenerate one can never be hit and has no
    // normal.
    std::vector<std::uint32_t> keptSource;
    std::vector<AABB> boxes;
    keptSource.reserve(data.triangles.size());
    boxes.reserve(data.triangles.size());
    for (size_t i = 0; i < data.triangles.size(); ++i) {
        const auto& c = data.triangles[i];
        const std::array<Vec3, 3> v{position(c[0].v), position(c[1].v), position(c[2].v)};
        if (!(glm::length(glm::cross(v[1] - v[0], v[2] - v[0])) > 0.0)) {
            ++dropped_;
            continue;
        }
        AABB box;
        for (const Vec3& p : v) box.extend(p);
        boxes.push_back(box);
        keptSource.push_back(static_cast<std::uint32_t>(i));
    }
    if (keptSource.empty())
        throw InputError(name + ": the mesh has no triangle with non-zero area");
    // Keep the texture coordinates of every triangle, by OBJ index, when the file has any.
    if (!data.texcoords.empty()) {
        texcoords_.reserve(data.triangles.size());
        for (const auto& c : data.triangles) {
            TriangleTexcoords t;
            if (c[0].vt < 0 || c[1].vt < 0 || c[2].vt < 0) {
                t.uv.fill(Vec2(std::numeric_limits<double>::quiet_NaN()));
            } else {
                for (int k = 0; k < 3; ++k) t.uv[k] = data.texcoords[c[k].vt];
                // Solve p1 − p0 = Δu1·dp/du + Δv1·dp/dv and p2 − p0 likewise (Cramer's rule).
                const Vec3 dp1 = position(c[1].v) - position(c[0].v);
                const Vec3 dp2 = position(c[2].v) - position(c[0].v);
                const Vec2 duv1 = t.uv[1] - t.uv[0], duv2 = t.uv[2] - t.uv[0];
                const double det = duv1.x * duv2.y - duv1.y * duv2.x;
                if (det != 0.0 && std::isfinite(1.0 / det)) {
                    t.dpdu = (duv2.y * dp1 - duv1.y * dp2) / det;
                    t.dpdv = (duv1.x * dp2 - duv2.x * dp1) / det;
                }
            }
            texcoords_.push_back(t);
        }
    }
    // Build the BVH (the boxes are freed inside), then copy each leaf's triangles into packs of
    // four and point the leaf at its first pack.
    // The SAH prices a leaf by its packs of four, and a leaf may hold two packs.
    BVHBuildOptions options;
    options.layout = layout;
    options.leafBlock = 4;
    options.maxLeafSize = 8;
    bvh_.build(std::move(boxes), options);
    bounds_ = bvh_.bounds();
    triangleCount_ = keptSource.size();
    const auto& order = bvh_.primitiveOrder();
    size_t packCount = 0;
    bvh_.forEachLeaf([&](std::uint32_t, std::uint32_t count) { packCount += (count + 3) / 4; });
    packs_.reserve(packCount);
    bvh_.forEachLeaf([&](std::uint32_t& first, std::uint32_t count) {
        const auto firstPack = static_cast<std::uint32_t>(packs_.size());
        for (std::uint32_t k = 0; k < count; k += 4) {
            Triangle4& pack = packs_.emplace_back();
            for (std::uint32_t lane = 0; lane < 4; ++lane) {
                // Spare lanes repeat the leaf's last triangle; the test never reports them.
                const std::uint32_t p = order[first + std::min(k + lane, count - 1)];
                const auto& corners = data.triangles[keptSource[p]];
                double extent = 0.0;
                for (int vertex = 0; vertex < 3; ++vertex) {
                    const Vec3 v = position(corners[vertex].v);
                    for (int axis = 0; axis < 3; ++axis) {
                        pack.p[vertex][axis][lane] = static_cast<float>(v[axis]);  // exact
                        extent = std::max(extent, std::abs(v[axis]));
                    }
                }
                pack.extent[lane] = static_cast<float>(extent);  // a float already
                pack.source[lane] = keptSource[p];
            }
        }
        first = firstPack;
    });
    bvh_.releasePrimitiveOrder();
    packs_.shrink_to_fit();
}

const TriangleTexcoords* Mesh::texcoords(std::uint32_t triangle) const {
    if (triangle >= texcoords_.size() || std::isnan(texcoords_[triangle].uv[0].x)) return nullptr;
    return &texcoords_[triangle];
}

size_t Mesh::triangleBytes() const {
    return packs_.size() * sizeof(Triangle4);
}

std::vector<Mesh::Triangle> Mesh::triangles() const {
    std::vector<Triangle> out;
    out.reserve(triangleCount_);
    bvh_.forEachLeaf([&](std::uint32_t first, std::uint32_t count) {
        for (std::uint32_t k = 0; k < count; ++k) {
            const Triangle4& pack = packs_[first + k / 4];
            const int lane = static_cast<int>(k % 4);
            out.push_back({vertices(pack, lane), pack.source[lane]});
        }
    });
    return out;
}

// [mesh-intersect]
template <class Counts>
bool Mesh::intersectCounting(const Ray& ray, double tMax, ObjectHit& hit, Counts& counts) const {
    if (isDegenerateDirection(ray.d)) return false;
    const WatertightRay wray(ray);
    const FilterRay fray(wray);
    const Triangle4* bestPack = nullptr;
    int bestLane = -1;
    TriangleHit best{};
    NearestTriangle nearest{tMax};
    const bool found = bvh_.closest(
        ray, tMax,
        [&](std::uint32_t first, std::uint32_t count, double& tClosest)
            __attribute__((always_inline)) {
                bool foundHere = false;
                // Four triangles at a time.
                for (std::uint32_t k = 0; k < count; k += 4) {
                    const Triangle4& pack = packs_[first + k / 4];
                    const int lane = intersectTriangle4(wray, fray, pack, std::min(count - k, 4u),
                                                        nearest, best, counts);
                    if (lane < 0) continue;
                    tClosest = best.t;
                    bestPack = &pack;
                    bestLane = lane;
                    foundHere = true;
                }
                return foundHere;
            },
        counts);
    if (!found) return false;
    const std::array<Vec3, 3> v = vertices(*bestPack, bestLane);
    hit.t = best.t;
    hit.n = glm::cross(v[1] - v[0], v[2] - v[0]);  // geometric normal, by the winding
    hit.uv = Vec2(best.b1, best.b2);  // barycentrics; chapter 10 turns them into `vt` (u, v)
    hit.primitive = bestPack->source[bestLane];
    return true;
}
// [mesh-intersect]

template <class Counts>
bool Mesh::occludedCounting(const Ray& ray, double tMax, Counts& counts) const {
    if (isDegenerateDirection(ray.d)) return false;
    const WatertightRay wray(ray);
    const FilterRay fray(wray);
    const FloatLimit limit(tMax);
    return bvh_.any(
        ray, tMax,
        [&](std::uint32_t first, std::uint32_t count, double t) __attribute__((always_inline)) {
            for (std::uint32_t k = 0; k < count; k += 4)
                if (occludedTriangle4(wray, fray, packs_[first + k / 4], std::min(count - k, 4u), t,
                                      limit, counts))
                    return true;
            return false;
        },
        counts);
}

bool Mesh::intersect(const Ray& ray, double tMax, ObjectHit& hit) const {
    NoCounts none;
    return intersectCounting(ray, tMax, hit, none);
}

bool Mesh::intersect(const Ray& ray, double tMax, ObjectHit& hit, TraversalCounts& counts) const {
    return intersectCounting(ray, tMax, hit, counts);
}

bool Mesh::occluded(const Ray& ray, double tMax) const {
    NoCounts none;
    return occludedCounting(ray, tMax, none);
}

bool Mesh::occluded(const Ray& ray, double tMax, TraversalCounts& counts) const {
    return occludedCounting(ray, tMax, counts);
}

}  // namespace rb
