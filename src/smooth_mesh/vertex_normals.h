/// \file
/// Vertex normals for a triangle mesh: read from the OBJ file's `vn`, or computed by
/// averaging the faces around each vertex, weighted by their angles, within a crease angle.
#pragma once

#include <array>
#include <vector>

#include "bvh/obj.h"

namespace rb {

/// Where a smooth mesh's vertex normals come from.
enum class NormalSource {
    File,      ///< The file's `vn` where a corner names one, computed for the other corners.
    Computed,  ///< Always computed (the file's `vn` are ignored).
};

/// The default crease angle in degrees: faces meeting at a sharper angle than this keep their
/// own normals at the shared vertex. 60° keeps a cube (90°) faceted and smooths a sphere of 8
/// or more segments around (45° between neighbours).
inline constexpr double kDefaultCreaseDegrees = 60.0;

/// The unit normal of face (p0, p1, p2) by its winding, or zero for a degenerate face.
Vec3 faceNormal(const Vec3& p0, const Vec3& p1, const Vec3& p2);

/// The interior angle of triangle (p0, p1, p2) at p0, in radians (0 for a degenerate corner).
double cornerAngle(const Vec3& p0, const Vec3& p1, const Vec3& p2);

/// One face around a vertex: its unit normal and its interior angle at the vertex.
struct FaceAtVertex {
    Vec3 n;
    double angle;
};

/// The normal of one corner of a face with unit normal ng: the sum of the normals of the faces
/// around the vertex, each weighted by its angle there, over the faces whose normal lies within
/// the crease (cos of the angle to ng at least cosCrease), normalised. Each face's normal is
/// first turned to ng's side, because course meshes wind both ways. Returns ng when nothing
/// is left to average.
Vec3 angleWeightedNormal(const std::vector<FaceAtVertex>& faces, const Vec3& ng, double cosCrease);

/// One unit normal per triangle corner (triangles in file order), each on the side of its
/// face's winding normal. A corner takes the file's `vn` when `source` is File and the `vn`
/// has a finite, non-zero length; otherwise the angle-weighted average of the normals of the
/// faces around its vertex (vertices at the same position count as one) that meet its own face at
/// no more than `creaseDegrees`. A corner of a degenerate face gets zero (the mesh drops such
/// faces; they are never hit).
std::vector<std::array<Vec3, 3>> cornerNormals(const ObjData& data, NormalSource source,
                                               double creaseDegrees = kDefaultCreaseDegrees);

}  // namespace rb
