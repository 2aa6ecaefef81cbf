/// \file
/// World: one loaded render request turned into a scene and a pipeline, ready to render.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/feature.h"
#include "core/integrator.h"
#include "core/scene_graph.h"

namespace rb {

/// Everything one render needs, kept together so the shapes and materials outlive the scene.
struct World {
    LoadedRender source;  ///< The request; keeps the scene graph (shapes, materials) alive.
    Scene scene;          ///< Instances, their aggregate, lights and settings.
    Pipeline pipeline;    ///< The shading the enabled features installed.
    std::vector<std::string> warnings;  ///< What was left out (shapes of a feature that is off).
};

/// Build the world for a loaded render: take its instances and lights, apply max_depth (the
/// scene's gr.option, then `maxDepth` when ≥ 0, as --max-depth) and min_weight (gr.option;
/// adaptive depth control, 0 turns it off), drop the instances of shapes whose feature is off
/// (World::warnings says so), let every enabled feature
/// install itself, then build the aggregate. `featureOptions` are the chapters' --name=value.
std::unique_ptr<World> buildWorld(LoadedRender render, const FeatureSet& features,
                                  const std::map<std::string, std::string>& featureOptions = {},
                                  int maxDepth = -1);

}  // namespace rb
