/// \file
/// Chapter 10's Lua helpers that later chapters reuse (chapter 11's bump maps load their height
/// images the same way).
#pragma once

#include <lua.hpp>
#include <memory>
#include <string>

#include "core/texture.h"
#include "texture/texture_image.h"

namespace rb {

/// The image in `file`, found like a mesh (working directory, scene folder, --assets) and
/// loaded once per scene: every later call naming the same file shares its texels. Throws
/// InputError naming `call` when the file is missing or not a readable image.
std::shared_ptr<const TextureImage> sceneImage(lua_State* L, const std::string& file,
                                               const std::string& call);

/// The texture at stack index arg of a method (message: argument arg − 1, after self): a
/// gr.texture result, or an image file name (an image
/// texture with the defaults: repeat, bilinear, the shape's own (u, v)). Throws InputError
/// naming `call` otherwise.
std::shared_ptr<const Texture> checkTexture(lua_State* L, int arg, const char* call);

}  // namespace rb
