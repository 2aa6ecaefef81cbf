/// \file
/// Chapter 14's feature record: constructive solid geometry.
#pragma once

#include "core/feature.h"

namespace rb {

/// Chapter 14: union, intersection and difference of solids (`gr.union`, `node:csg`).
Feature csgFeature();

}  // namespace rb
