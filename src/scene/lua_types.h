/// \file
/// The Lua metatable names of the scene's userdata, shared by the loader (lua_scene.cpp) and the
/// registry of calls (lua_bindings.cpp). Private to src/scene: chapters reach nodes and materials
/// through checkNode, checkMaterial, pushNode and pushMaterial.
#pragma once

namespace rb {

/// Metatable of scene nodes (gr.node, gr.sphere, ...): `node:name(...)` methods live in its
/// __index.
inline constexpr const char* kNodeType = "rb.node";
/// Metatable of materials (gr.material): `material:name(...)` methods live in its __index.
inline constexpr const char* kMaterialType = "rb.material";

}  // namespace rb
