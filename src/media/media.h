/// \file
/// Chapter 17, participating media: fog, light shafts and smoke. A medium absorbs and scatters
/// light along every ray through it; single scattering looks towards every light through
/// attenuated shadow rays, and multiple scattering follows the phase function.
#pragma once

#include "core/feature.h"
#include "media/participating_media.h"

namespace rb {

struct RenderContext;

/// The media settings of one render from the command line (--media, --media-shadows,
/// --media-step, --media-majorant); step 0 means "from the scene's size". Throws InputError
/// for a value out of range, naming the option.
MediaSettings mediaSettings(const RenderContext& context);

/// Chapter 17's Lua calls: gr.medium, gr.fog and node:set_medium.
void bindMedia(LuaBindings& lua);

/// Chapter 17's registration: gr.medium, gr.fog, node:set_medium and the media options.
Feature mediaFeature();

}  // namespace rb
