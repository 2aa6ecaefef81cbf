/// \file
/// Chapter 15, cylinders and cones: the unit cylinder and cone (or frustum) on the y axis,
/// capped or open, as a new shape kind (rb::Quadric). Capped shapes are solids whose caps are
/// real surfaces with outward normals, so glass cylinders refract through their caps.
#pragma once

#include "core/feature.h"

namespace rb {

class LuaBindings;

/// Chapter 15: gr.cylinder, gr.cyllinder (seed 001) and gr.cone.
Feature quadricsFeature();

/// Chapter 15's Lua calls.
void bindQuadrics(LuaBindings& lua);

}  // namespace rb
