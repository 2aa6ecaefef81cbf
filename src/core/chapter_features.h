/// \file
/// The Feature records of the core chapters 1–3 (each defined in its chapter's files).
#pragma once

#include "core/feature.h"

namespace rb {

/// Chapter 1: camera rays, spheres and boxes, headlight shading, brute-force intersection.
Feature chapter01Feature();
/// Chapter 2: Phong shading with point lights and hard shadows.
Feature chapter02Feature();
/// Chapter 3: triangle meshes and the two-level BVH.
Feature chapter03Feature();

}  // namespace rb
