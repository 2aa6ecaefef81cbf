/// \file
/// The Wavefront OBJ reader: vertex arrays and fan-triangulated faces, with errors that name the
/// file and the line.
///
/// The reader understands the polygonal subset of OBJ that meshes in the wild use:
/// - `v x y z [w]` positions (w is ignored; a 6-number `v x y z r g b` vertex colour is ignored
///   too), `vt u [v [w]]` texture coordinates and `vn x y z` normals;
/// - faces `f` with 3 or more corners, each written `v`, `v/vt`, `v//vn` or `v/vt/vn`; the forms
///   may be mixed within a face;
/// - negative (relative) indices, `#` comments, blank lines, tabs and CRLF line endings.
///
/// `o`, `g`, `s`, `usemtl`, `mtllib`, `l`, `p` and `vp` are skipped. Anything else is an error.
#pragma once

#include <array>
#include <istream>
#include <string>
#include <vector>

#include "core/memory_budget.h"
#include "core/vec.h"

namespace rb {

/// Indices of one triangle corner into ObjData's arrays; -1 where the face gave none.
struct ObjCorner {
    int v = -1, vt = -1, vn = -1;
};

/// The contents of an OBJ file: vertex arrays and triangles (polygons fan-triangulated).
struct ObjData {
    std::vector<Vec3> positions;                      ///< `v` lines, in file order.
    std::vector<Vec2> texcoords;                      ///< `vt` lines, in file order.
    std::vector<Vec3> normals;                        ///< `vn` lines, in file order.
    std::vector<std::array<ObjCorner, 3>> triangles;  ///< Faces, zero-based indices.
};

/// Peak bytes that loading a mesh of this size takes (the arrays, the Mesh and its BVH).
std::uint64_t meshLoadBytes(const ObjData& data);

/// Parse OBJ text; displayName is used in error messages ("name:line: ..."). The mesh must fit
/// in what `budget` leaves free when parsing starts: the parse stops with an InputError as soon
/// as the mesh read so far would not, before the arrays grow past it.
ObjData parseObj(std::istream& in, const std::string& displayName, const MemoryBudget& budget = {});

/// Load an OBJ file; throws InputError naming the file if it cannot be opened, or if the mesh
/// would not fit in `budget`.
ObjData loadObj(const std::string& path, const MemoryBudget& budget = {});

}  // namespace rb
