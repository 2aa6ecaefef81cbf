#include "dof/dof.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "core/error.h"
#include "core/integrator.h"
#include "core/render_context.h"
#include "lab/warp.h"

namespace rb {

namespace {

/// One setting: --cli if given, else the scene option, else seed 001's value (when it has
/// one: `fromSeed`), else `fallback`. `source` receives where it came from, for messages.
double pick(const RenderContext& context, const char* cli, const char* scene, bool fromSeed,
            double seedValue, double fallback, std::string& source) {
    const std::string text = context.cliOption(cli);
    if (!text.empty()) {
        source = std::string("--") + cli;
        return parseNumberOption(source, text);
    }
    const double absent = std::nan("");  // scene options are always finite
    const double v = context.sceneOption(scene, absent);
    if (!std::isnan(v)) {
        source = std::string("the scene's ") + scene;
        return v;
    }
    source = fromSeed ? "gr.render's {aperture, focalLength, dof}" : "the default";
    return fromSeed ? seedValue : fallback;
}

}  // namespace

// [lens-settings]
ThinLensSettings lensSettings(const RenderContext& context) {
    ThinLensSettings s;
    // Seed 001's {aperture, focalLength, dof}: dof > 0 switches its depth of field on, with
    // dof² rays through a square aperture.
    const double seedDof = context.sceneOption("dof", 0.0);
    if (seedDof < 0.0 || seedDof != std::floor(seedDof) || seedDof > 256.0)
        throw InputError(
            "gr.render: dof (in {aperture, focalLength, dof}) must be a whole number "
            "from 0 (off) to 256, got " +
            formatNumber(seedDof));
    const bool seed = seedDof > 0.0;
    std::string where;
    s.aperture = pick(context, "dof-aperture", "dof_aperture", seed,
                      context.sceneOption("aperture", 0.0), 0.0, where);
    if (!(s.aperture >= 0.0))
        throw InputError(where + ": the aperture must be 0 (a pinhole) or more, got " +
                         formatNumber(s.aperture));
    // The focus: seed 000's distance from the eye to the view target, |view| (A4's view is
    // eye-to-target when the scene is written with a target in mind).
    const double viewTarget = glm::length(context.job.camera.view);
    s.focusDistance = pick(context, "dof-focus", "dof_focus", seed,
                           context.sceneOption("focal_length", viewTarget), viewTarget, where);
    if (!(s.focusDistance > 0.0) || !std::isfinite(s.focusDistance))
        throw InputError(where + ": the focus distance must be above 0, got " +
                         formatNumber(s.focusDistance));
    const double samples =
        pick(context, "dof-samples", "dof_samples", seed, seedDof * seedDof, 16.0, where);
    if (samples < 1.0 || samples > kMaxLensSamples || samples != std::floor(samples))
        throw InputError(where + ": expected a whole number of lens samples from 1 to " +
                         std::to_string(kMaxLensSamples) + ", got " + formatNumber(samples));
    s.samples = static_cast<int>(samples);
    // The shape: a name on the command line, a number in the scene (0 disk, 1 square).
    const std::string shape = context.cliOption("dof-shape");
    if (shape == "disk" || shape == "square")
        s.shape = shape == "disk" ? ApertureShape::Disk : ApertureShape::Square;
    else if (!shape.empty())
        throw InputError("--dof-shape: expected disk or square, got '" + shape + "'");
    else
        s.shape = pick(context, "", "dof_shape", seed, 1.0, 0.0, where) == 1.0
                      ? ApertureShape::Square
                      : ApertureShape::Disk;
    return s;
}
// [lens-settings]

// [install-dof]
void installDof(Pipeline& pipeline, Scene&, const RenderContext& context) {
    // Read (and check) the settings for every scene, so a bad value always fails the same way.
    const ThinLensSettings settings = lensSettings(context);
    // A pinhole: the core's camera, untouched, so this chapter costs nothing.
    if (settings.aperture == 0.0) return;
    pipeline.cameraRays = std::make_shared<ThinLens>(settings);
}
// [install-dof]

/// The chapter's samplers for ./rt --warptest (dof_warps.cpp).
std::vector<Warp> dofWarps();

Feature dofFeature() {
    return {"dof",
            13,
            "depth of field: a thin lens with a disk or square aperture",
            true,
            bindDof,
            installDof,
            {{"dof-aperture", "A", "lens aperture: disk diameter or square side (0: pinhole)",
              "the scene's gr.lens or aperture, else 0"},
             {"dof-focus", "F", "distance from the eye to the plane in focus",
              "the scene's, else |view| (the view target)"},
             {"dof-samples", "N", "lens samples per pixel (paired with the pixel's rays)",
              "the scene's, else 16"},
             {"dof-shape", "disk|square", "aperture shape", "the scene's, else disk"}},
            {},
            dofWarps};
}

}  // namespace rb
