/// \file
/// Meshes written as Lua tables (the legacy form of gr.mesh), for the calls that build meshes.
#pragma once

#include <lua.hpp>

#include "bvh/obj.h"

namespace rb {

/// The mesh given as Lua tables at stack indices 2 (vertices: {x, y, z} triples) and 3 (faces:
/// lists of 0-based vertex indices, fan-triangulated), as OBJ data. Throws InputError naming
/// `call` for a malformed vertex or an index that is not a vertex.
ObjData objFromLuaTables(lua_State* L, const char* call);

}  // namespace rb
