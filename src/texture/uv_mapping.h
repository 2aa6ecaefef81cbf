/// \file
/// UV mapping: where on a texture each surface point lands. The sphere's angles, the box's
/// faces, a planar projection, and a mesh's `vt` coordinates interpolated over each triangle.
#pragma once

#include "core/hit.h"

namespace rb {

class Mesh;

/// How a texture finds its (u, v) on a surface.
enum class UVMapping {
    Surface,      ///< The shape's own: sphere angles, box faces, mesh `vt` (planar without).
    Planar,       ///< The object-space ground plane: u = x, v = −z.
    Spherical,    ///< The sphere's angles of the direction from the object's origin.
    Cylindrical,  ///< The longitude about the object's y axis, and the height: u = φ/2π, v = y.
};

/// A texture coordinate and the derivatives of the surface position along it: dp/du and dp/dv
/// span the tangent plane (chapter 11 tilts normals along them). Zero where undefined.
struct SurfaceUV {
    Vec2 uv{0.0};
    Vec3 dpdu{0.0};
    Vec3 dpdv{0.0};
};

/// The unit sphere's (u, v) = (φ/2π, θ/π) at unit direction d: φ is the angle about +y,
/// measured from +x towards −z, in [0, 2π); θ is the angle from the south pole (−y), so v runs
/// from 0 at the bottom of the image to 1 at its top. Source: seed 000, section 4.2.
SurfaceUV sphereUV(const Vec3& d);

/// The unit cube's face coordinates at object-space point p on face `axis` (0 = x, 1 = y,
/// 2 = z; the +1 face when p[axis] > 1/2), oriented so that each face shows an image upright
/// and unmirrored from outside (the top seen with −z up, the bottom with +z up).
SurfaceUV boxFaceUV(const Vec3& p, int axis);

/// The planar projection onto the object-space ground plane: u = x, v = −z (seen from above
/// with −z up, the image is upright).
SurfaceUV planarUV(const Vec3& p);

/// The cylindrical projection about the object-space y axis: u = φ/2π with φ measured as on the
/// sphere (from +x towards −z), v = y. For lathed shapes such as a cup.
SurfaceUV cylindricalUV(const Vec3& p);

/// A mesh triangle's (u, v): its corners' `vt` blended with the barycentrics (b1, b2) of the
/// hit, (1 − b1 − b2)·t0 + b1·t1 + b2·t2. Falls back to planarUV(p) when it has no `vt`.
SurfaceUV meshUV(const Mesh& mesh, std::uint32_t triangle, const Vec2& barycentric, const Vec3& p);

/// The (u, v) of a world-space hit under `mapping`, with dp/du and dp/dv in world space. A hit's
/// own uv (the barycentrics on a mesh) is left as the intersection stored it. A later chapter's
/// shape maps itself (Shape::surfaceCoordinates: a cylinder's or cone's angle and height); a
/// shape with no parameterisation of its own (a CSG node) falls back to the planar projection.
SurfaceUV surfaceUV(const Hit& hit, UVMapping mapping = UVMapping::Surface);

}  // namespace rb
