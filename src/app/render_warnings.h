/// \file
/// Warnings for a render that would surprise a student: a picture that can only be empty,
/// scene arguments this build ignores, an output name that is not a PNG's.
#pragma once

#include <string>
#include <vector>

#include "core/camera.h"
#include "core/feature.h"
#include "core/instance.h"
#include "core/scene_graph.h"

namespace rb {

/// One line each (without "rt: warning: "), naming the gr.render call: the render is still
/// made, but it would not show what the student probably expects.
/// `output` is the file the image goes to (gr.render's, or --output's).
std::vector<std::string> renderWarnings(const RenderJob& job,
                                        const std::vector<Instance>& instances,
                                        const PinholeCamera& camera, const FeatureSet& features,
                                        const std::string& output);

/// For a path-traced render (chapter 18): one line per material that would reflect more light
/// than it receives (kd + ks + reflect over 1 in some channel), which the path tracer scales
/// down, naming the first node that uses it.
std::vector<std::string> energyWarnings(const RenderJob& job,
                                        const std::vector<Instance>& instances);

}  // namespace rb
