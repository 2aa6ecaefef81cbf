/// \file
/// The Feature record of chapter 1, the core every chapter builds on. Later chapters declare
/// theirs in their own folders (phong/phong.h, bvh/bvh_aggregate.h, ...). It lives in src/scene,
/// not src/core, because it joins chapter 1's Lua calls (bindA4) to core's shading: core
/// includes nothing of the scene language.
#pragma once

#include "core/feature.h"

namespace rb {

/// Chapter 1: camera rays, spheres and boxes, headlight shading, brute-force intersection.
Feature chapter01Feature();

}  // namespace rb
