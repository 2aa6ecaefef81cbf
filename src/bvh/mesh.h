/// \file
/// Triangle meshes: the shape chapter 3 adds, with its own BVH over its triangles.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "bvh/bvh.h"
#include "bvh/obj.h"
#include "core/shape.h"

namespace rb {

/// A triangle's `vt` coordinates, corner by corner, and the object-space derivatives of the
/// position along them (dp/du, dp/dv: zero when the coordinates are degenerate).
struct TriangleTexcoords {
    std::array<Vec2, 3> uv;
    Vec3 dpdu{0.0}, dpdv{0.0};
};

/// A triangle mesh in object space. Triangles are stored in BVH order with their vertices
/// copied out, so a leaf test reads one contiguous block.
class Mesh final : public Shape {
  public:
    /// Build from OBJ data. Degenerate (zero-area) triangles are dropped; throws InputError
    /// (naming `name`) when no triangle is left.
    Mesh(const ObjData& data, const std::string& name);
    bool intersect(const Ray& ray, double tMax, ObjectHit& hit) const override;
    bool occluded(const Ray& ray, double tMax) const override;
    AABB bounds() const override { return bounds_; }
    const Mesh* triangleMesh() const override { return this; }

    /// Number of triangles kept.
    size_t triangleCount() const { return triangles_.size(); }
    /// Degenerate triangles dropped at load.
    size_t droppedCount() const { return dropped_; }
    /// The mesh's BVH.
    const BVH& bvh() const { return bvh_; }
    /// Bytes used by triangle data (excluding the BVH).
    size_t triangleBytes() const;
    /// The three vertices of triangle slot i (BVH order).
    const std::array<Vec3, 3>& triangle(size_t i) const { return triangles_[i]; }
    /// The OBJ triangle index of slot i.
    std::uint32_t sourceIndex(size_t i) const { return source_[i]; }
    /// The `vt` texture coordinates of OBJ triangle `triangle` (a Hit's primitive); null when
    /// the file gave that triangle none (or not at every corner).
    const TriangleTexcoords* texcoords(std::uint32_t triangle) const;

  private:
    std::vector<std::array<Vec3, 3>> triangles_;     ///< Vertices, BVH order.
    std::vector<std::uint32_t> source_;              ///< OBJ triangle index per slot.
    /// `vt` per OBJ triangle (NaN where a corner has none); empty when the file has no `vt`.
    std::vector<TriangleTexcoords> texcoords_;
    BVH bvh_;
    AABB bounds_;
    size_t dropped_ = 0;
};

}  // namespace rb
