/// \file
/// Triangle meshes: the shape chapter 3 adds, with its own BVH over its triangles.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "bvh/bvh.h"
#include "bvh/obj.h"
#include "bvh/triangle4.h"
#include "core/shape.h"

namespace rb {

/// A triangle's `vt` coordinates, corner by corner, and the object-space derivatives of the
/// position along them (dp/du, dp/dv: zero when the coordinates are degenerate).
struct TriangleTexcoords {
    std::array<Vec2, 3> uv;
    Vec3 dpdu{0.0}, dpdv{0.0};
};

/// A triangle mesh in object space, its vertices in float. Each BVH leaf's triangles are copied
/// out into packs of four (Triangle4), so a leaf test reads one contiguous block and filters four
/// triangles at once; the exact test reads the same pack, in double.
class Mesh final : public Shape {
  public:
    /// Build from OBJ data. Degenerate (zero-area) triangles are dropped; throws InputError
    /// (naming `name`) when no triangle is left. `layout` picks the BVH traversal.
    Mesh(const ObjData& data, const std::string& name, BVHLayout layout = bestWideLayout());
    bool intersect(const Ray& ray, double tMax, ObjectHit& hit) const override;
    bool occluded(const Ray& ray, double tMax) const override;
    /// intersect(), adding the work it did to `counts` (for the benchmarks).
    bool intersect(const Ray& ray, double tMax, ObjectHit& hit, TraversalCounts& counts) const;
    /// occluded(), adding the work it did to `counts` (for the benchmarks).
    bool occluded(const Ray& ray, double tMax, TraversalCounts& counts) const;
    AABB bounds() const override { return bounds_; }
    const Mesh* triangleMesh() const override { return this; }

    /// Number of triangles kept.
    size_t triangleCount() const { return triangleCount_; }
    /// Degenerate triangles dropped at load.
    size_t droppedCount() const { return dropped_; }
    /// The mesh's BVH.
    const BVH& bvh() const { return bvh_; }
    /// Bytes used by triangle data, the packs (excluding the BVH).
    size_t triangleBytes() const;
    /// A kept triangle: its vertices and its OBJ triangle index.
    struct Triangle {
        std::array<Vec3, 3> v;
        std::uint32_t source;
    };
    /// Every kept triangle, in storage order (for tests and benchmarks; it copies).
    std::vector<Triangle> triangles() const;
    /// The `vt` texture coordinates of OBJ triangle `triangle` (a Hit's primitive); null when
    /// the file gave that triangle none (or not at every corner).
    const TriangleTexcoords* texcoords(std::uint32_t triangle) const;

  private:
    /// intersect() and occluded(), counting their work in `counts` (NoCounts: none).
    template <class Counts>
    bool intersectCounting(const Ray& ray, double tMax, ObjectHit& hit, Counts& counts) const;
    template <class Counts>
    bool occludedCounting(const Ray& ray, double tMax, Counts& counts) const;

    /// Triangle packs: a BVH leaf of n triangles points at ⌈n/4⌉ consecutive packs.
    std::vector<Triangle4> packs_;
    size_t triangleCount_ = 0;
    /// `vt` per OBJ triangle (NaN where a corner has none); empty when the file has no `vt`.
    std::vector<TriangleTexcoords> texcoords_;
    BVH bvh_;
    AABB bounds_;
    size_t dropped_ = 0;
};

}  // namespace rb
