/// \file
/// Chapter 13, depth of field: a thin lens in place of the pinhole, so that only the plane in
/// focus is sharp and everything nearer or farther blurs in proportion to the aperture.
#pragma once

#include "core/feature.h"
#include "dof/thin_lens.h"

namespace rb {

struct RenderContext;

/// The most lens samples per pixel (256 × 256), as for chapter 8's pixel samples.
inline constexpr int kMaxLensSamples = 65536;

/// Read the lens of one render. For each setting the first present wins: the command line
/// (--dof-aperture, --dof-focus, --dof-samples, --dof-shape), the scene (gr.lens or the
/// gr.options dof_aperture, dof_focus, dof_samples, dof_shape), seed 001's gr.render argument
/// {aperture, focalLength, dof} when its dof > 0 (a square aperture, dof² samples), the
/// default (aperture 0, a pinhole; focus at the view target, |view|, as seed 000; 16 samples; a
/// disk). Throws InputError for a bad value.
ThinLensSettings lensSettings(const RenderContext& context);

/// Plug chapter 13 into one render: install a ThinLens when the aperture is above 0; a pinhole
/// (aperture 0) leaves the core's camera, which then runs exactly as before.
void installDof(Pipeline& pipeline, Scene& scene, const RenderContext& context);

/// Chapter 13's Lua calls: gr.lens{...} and the options dof_aperture, dof_focus, dof_samples
/// and dof_shape.
void bindDof(LuaBindings& lua);

/// Chapter 13's feature record.
Feature dofFeature();

}  // namespace rb
