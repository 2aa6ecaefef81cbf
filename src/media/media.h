/// \file
/// Chapter 17, participating media: fog, light shafts and smoke. A medium absorbs and scatters
/// light along every ray through it; single scattering looks towards every light through
/// attenuated shadow rays, and multiple scattering follows the phase function.
#pragma once

#include "core/feature.h"

namespace rb {

/// Chapter 17's registration: gr.medium, gr.fog, node:set_medium and the media options.
Feature mediaFeature();

}  // namespace rb
