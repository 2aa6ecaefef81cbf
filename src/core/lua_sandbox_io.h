/// \file
/// The sandbox's read-only `io`: enough for the course's readobj.lua to read OBJ files.
#pragma once

#include <lua.hpp>

namespace rb {

/// Define the global `io` of a sandboxed scene: io.open(path, "r"), io.lines and the file
/// methods read, lines and close, for files under the scene's folder and the --assets folders.
void openReadOnlyIo(lua_State* L);

}  // namespace rb
