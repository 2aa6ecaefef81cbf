/// \file
/// Meshes written as Lua tables (the legacy form of gr.mesh), for the calls that build meshes.
#pragma once

#include <lua.hpp>

#include "bvh/bvh.h"
#include "bvh/obj.h"

namespace rb {

struct SceneLoadOptions;

/// The BVH layout that --bvh asks for (binary|wide4|wide8|wide; wide, the best this CPU runs,
/// when absent).
BVHLayout bvhLayout(const SceneLoadOptions& options);

/// The mesh given as Lua tables at stack indices 2 (vertices: {x, y, z} triples) and 3 (faces:
/// lists of 0-based vertex indices, fan-triangulated), as OBJ data. Throws InputError naming
/// `call` for a malformed vertex or an index that is not a vertex.
ObjData objFromLuaTables(lua_State* L, const char* call);

}  // namespace rb
