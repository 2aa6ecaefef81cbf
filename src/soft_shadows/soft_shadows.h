/// \file
/// Chapter 6, soft shadows: lights with an area, sampled as n × n points, so shadows get a
/// penumbra and highlights take the light's shape.
#pragma once

#include "core/feature.h"
#include "core/integrator.h"
#include "core/render_context.h"
#include "soft_shadows/area_light.h"

namespace rb {

/// The settings chapter 6 reads for one render, after the command line, the scene's
/// gr.option calls and seed 001's gr.render argument `ss` have had their say.
struct SoftShadowSettings {
    bool sample = true;      ///< False when seed 001's ss = 0 asks for no soft shadows.
    int samplesPerAxis = 0;  ///< For every area light; 0: each light's own.
    LightSampling sampling = LightSampling::Stratified;  ///< --light-sampling.
};

/// Read the settings: --light-samples=N wins over gr.option('light_samples', N), which wins
/// over seed 001's gr.render(..., aa, ss, ...). Throws InputError for a bad value.
SoftShadowSettings softShadowSettings(const RenderContext& context);

/// Plug chapter 6 into one render: when some light has a shape, sample area lights (with the
/// chosen strategy and count). A scene with only point lights is left untouched.
void installSoftShadows(Pipeline& pipeline, Scene& scene, const RenderContext& context);

/// Chapter 6's Lua calls: gr.light's six-argument form, gr.area_light{...}, gr.ball_light and
/// the option light_samples.
void bindSoftShadows(LuaBindings& lua);

/// Chapter 6's feature record.
Feature softShadowsFeature();

}  // namespace rb
