/// \file
/// The smooth-mesh module (chapter 9): a triangle mesh shaded with normals interpolated from
/// its vertices, and what keeps those normals honest against the flat geometry: reflected rays
/// that stay above the surface, and shadow rays that start off the flat facet.
#pragma once

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "bvh/mesh.h"
#include "core/feature.h"
#include "core/integrator.h"
#include "smooth_mesh/vertex_normals.h"

namespace rb {

/// Barycentric coordinates (b0, b1, b2) of a point p in the plane of triangle (p0, p1, p2):
/// p = b0 p0 + b1 p1 + b2 p2 with b0 + b1 + b2 = 1. A degenerate triangle gives (1, 0, 0).
std::array<double, 3> barycentrics(const Vec3& p, const std::array<Vec3, 3>& v);

/// The shading normal at barycentrics b of a triangle with unit corner normals n and unit
/// geometric normal ng: n0, n1, n2 weighted by b0, b1, b2, normalised. Where the sum vanishes
/// (corner normals that cancel) it returns ng, never NaN.
Vec3 interpolateNormal(const std::array<double, 3>& b, const std::array<Vec3, 3>& n,
                       const Vec3& ng);

/// The smallest elevation, in radians, a mirror ray keeps above the geometric surface when the
/// shading normal is adapted (about 0.06°).
inline constexpr double kMinReflectionElevation = 1e-3;

/// The shading normal ns adapted so that the mirror image of wo about it leaves above the
/// geometric surface. wo (towards the viewer), ng and ns are unit vectors with wo · ng > 0 and
/// ns on ng's side. When wo mirrored about ns stays at least kMinReflectionElevation above the
/// tangent plane, ns is returned unchanged; otherwise the half vector of wo and the mirror ray
/// lifted to that elevation. Source: the shading-normal adaptation of A. Keller et al., "The
/// Iray Light Transport Simulation and Rendering System", SIGGRAPH 2017 Talks.
Vec3 adaptShadingNormal(const Vec3& wo, const Vec3& ng, const Vec3& ns);

/// Where shadow rays should start instead of p, as an offset from p: the point of the curved
/// surface that the corner normals describe (Boubekeur and Alexa's Phong tessellation), used
/// only where it lies above the flat triangle (J. Hanika, "Hacking the Shadow Terminator", Ray
/// Tracing Gems II, 2021). p has barycentrics b in triangle v; n are unit corner normals on
/// the side the shadow rays leave from.
Vec3 terminatorOffset(const Vec3& p, const std::array<double, 3>& b, const std::array<Vec3, 3>& v,
                      const std::array<Vec3, 3>& n);

/// How a smooth mesh was asked for: gr.smooth_mesh's options.
struct SmoothMeshOptions {
    NormalSource normals = NormalSource::File;
    double creaseDegrees = kDefaultCreaseDegrees;
    bool terminatorFix = true;  ///< Start shadow rays at terminatorOffset.
};

/// A triangle mesh with one normal per triangle corner. It intersects exactly like the
/// faceted Mesh it wraps (the same triangles, the same BVH); only shading differs, and only
/// when chapter 9 is switched on.
class SmoothMesh final : public Shape {
  public:
    /// Wrap `mesh` (built from `data`) with corner normals from `data` as `options` ask.
    SmoothMesh(std::shared_ptr<const Mesh> mesh, const ObjData& data,
               const SmoothMeshOptions& options);
    bool intersect(const Ray& ray, double tMax, ObjectHit& hit) const override {
        return mesh_->intersect(ray, tMax, hit);
    }
    bool occluded(const Ray& ray, double tMax) const override { return mesh_->occluded(ray, tMax); }
    AABB bounds() const override { return mesh_->bounds(); }
    const Mesh* triangleMesh() const override { return mesh_.get(); }

    /// The faceted mesh underneath.
    const Mesh& mesh() const { return *mesh_; }
    /// Object-space corners of triangle `primitive` (OBJ order).
    const std::array<Vec3, 3>& corners(std::uint32_t primitive) const {
        return corners_[primitive];
    }
    /// Unit corner normals of triangle `primitive`, on its winding normal's side.
    const std::array<Vec3, 3>& normals(std::uint32_t primitive) const {
        return normals_[primitive];
    }
    /// The options the mesh was built with.
    const SmoothMeshOptions& options() const { return options_; }

  private:
    std::shared_ptr<const Mesh> mesh_;
    std::vector<std::array<Vec3, 3>> corners_;  ///< Per OBJ triangle.
    std::vector<std::array<Vec3, 3>> normals_;  ///< Per OBJ triangle.
    SmoothMeshOptions options_;
};

/// The ShadingNormal chapter 9 installs: on a SmoothMesh hit, the interpolated normal, adapted
/// against the geometric surface, and the terminator's shadow offset.
class SmoothNormals final : public ShadingNormal {
  public:
    /// Which meshes get the terminator fix.
    enum class Terminator { PerMesh, Always, Never };
    explicit SmoothNormals(Terminator terminator = Terminator::PerMesh) : terminator_(terminator) {}
    void apply(const Ray& ray, Hit& hit) const override;

  private:
    Terminator terminator_;
};

/// The Feature record of chapter 9.
Feature smoothMeshFeature();

}  // namespace rb
