/// \file
/// The texture module (chapter 10): material colours looked up from images and procedural
/// textures at each hit's (u, v). It plugs into the core's texture lookup.
#pragma once

#include "core/feature.h"
#include "core/hit.h"
#include "core/material.h"

namespace rb {

/// Chapter 10: textures.
Feature textureFeature();

/// The colours the surface shader sees at hit: the material's kd and ks, each replaced by the
/// texture in its slot ("kd", "ks") when there is one. A TextureLookup.
Material lookupTextures(const Hit& hit);

/// Chapter 10's Lua calls (lua_texture.cpp).
void bindTextures(LuaBindings& lua);

}  // namespace rb
