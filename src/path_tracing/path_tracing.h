/// \file
/// Chapter 18, path tracing: the rendering equation solved without bias, the reference every
/// Monte Carlo chapter is measured against. A scene asks for it with gr.integrator('path') (or
/// the command line with --integrator=path); A4 scenes stay Whitted.
#pragma once

#include "core/feature.h"
#include "path_tracing/path_tracer.h"

namespace rb {

struct RenderContext;

/// True when the render is path traced: --integrator=path|whitted, else the scene's
/// gr.integrator, else Whitted. Throws InputError for another --integrator value.
bool pathTracingChosen(const RenderContext& context);

/// The path tracer's settings for one render: --path-depth, --path-roulette and
/// --path-strategy over the scene's gr.integrator fields. Throws InputError naming the option.
PathSettings pathSettings(const RenderContext& context);

/// Chapter 18's Lua calls: gr.integrator, and the material field `emission`.
void bindPathTracing(LuaBindings& lua);

/// Chapter 18's registration.
Feature pathTracingFeature();

}  // namespace rb
