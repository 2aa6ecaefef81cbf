/// \file
/// What the scene language's own files share, private to src/scene: the Lua metatable names of
/// the scene's userdata (chapters reach nodes and materials through checkNode, checkMaterial,
/// pushNode and pushMaterial), and the few functions the loader (lua_scene.cpp), the sandbox
/// (lua_sandbox.cpp), argument reading (lua_arguments.cpp) and unknown names and --lenient
/// (lua_lenient.cpp) call in one another.
#pragma once

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "scene/lua_scene.h"

namespace rb {

/// Metatable of scene nodes (gr.node, gr.sphere, ...): `node:name(...)` methods live in its
/// __index.
inline constexpr const char* kNodeType = "rb.node";
/// Metatable of materials (gr.material): `material:name(...)` methods live in its __index.
inline constexpr const char* kMaterialType = "rb.material";

/// Add one occurrence of `kind` to a list of kinds with counts, keeping the first message.
void recordKind(std::vector<std::pair<std::string, std::string>>& kinds,
                std::map<std::string, int>& counts, const std::string& kind,
                const std::string& message);

/// Push "file:line: message" for the Lua code that called the running C function, as
/// luaL_error would, so that lua_error can be raised once the C++ objects that built the
/// message are destroyed (lua_error longjmps over destructors: strings would leak).
void pushCallerError(lua_State* L, const std::string& message);

/// A fresh Lua state for `builder`'s scene (null when Lua cannot make one): its allocator
/// capped at the scripts' memory limit, the builder reachable through sceneBuilder(L), and
/// only the sandbox's libraries open (all of them with --unsafe-lua).
lua_State* newSandboxState(SceneBuilder& builder);
/// Count the script's instructions from now on: past the limit, or on Ctrl-C, the script
/// stops with its file and line (an endless loop).
void limitInstructions(lua_State* L);

/// __index of the gr table: a gr call nobody defined names the chapter a build lacks, or is a
/// stand-in under --lenient.
int unknownGrCall(lua_State* L);
/// __index of the node and material methods: the same for a method nobody defined.
int unknownMethod(lua_State* L);

}  // namespace rb
