#include "soft_shadows/soft_shadows.h"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "core/error.h"
#include "core/from_chars.h"
#include "lab/warp.h"

namespace rb {

namespace {

/// The most samples per axis any setting may ask for (256² = 65536 shadow rays per light).
constexpr int kMaxSamplesPerAxis = 256;

/// A samples-per-axis value from the scene: a whole number in [0, kMaxSamplesPerAxis].
int sceneSampleCount(double v, const std::string& where) {
    if (v != std::floor(v) || v < 0 || v > kMaxSamplesPerAxis)
        throw InputError(where + ": expected a whole number of samples per axis from 0 to " +
                         std::to_string(kMaxSamplesPerAxis) + ", got " + std::to_string(v));
    return static_cast<int>(v);
}

}  // namespace

// [soft-shadow-settings]
SoftShadowSettings softShadowSettings(const RenderContext& context) {
    SoftShadowSettings settings;
    // Samples per axis: the command line, else gr.option, else seed 001's ss (0: hard shadows).
    const std::string cli = context.cliOption("light-samples");
    if (!cli.empty()) {
        int n = -1;
        const auto [end, ec] = rb::fromChars(cli.data(), cli.data() + cli.size(), n);
        if (ec != std::errc() || end != cli.data() + cli.size() || n < 0 || n > kMaxSamplesPerAxis)
            throw InputError("--light-samples: expected a whole number from 0 to " +
                             std::to_string(kMaxSamplesPerAxis) + ", got '" + cli + "'");
        settings.samplesPerAxis = n;
    } else if (context.job.options.count("light_samples")) {
        settings.samplesPerAxis = sceneSampleCount(context.job.options.at("light_samples"),
                                                   context.job.where + ": light_samples");
    } else if (context.job.options.count("ss")) {
        const int ss = sceneSampleCount(context.job.options.at("ss"), context.job.where + ": ss");
        settings.sample = ss > 0;
        settings.samplesPerAxis = ss;
    }
    // The strategy: stratified unless the command line asks for independent samples.
    const std::string strategy = context.cliOption("light-sampling", "stratified");
    if (strategy == "independent")
        settings.sampling = LightSampling::Independent;
    else if (strategy != "stratified")
        throw InputError("--light-sampling: expected stratified or independent, got '" + strategy +
                         "'");
    return settings;
}
// [soft-shadow-settings]

// [install-soft-shadows]
void installSoftShadows(Pipeline&, Scene& scene, const RenderContext& context) {
    // Read (and check) the settings even when they will not be used, so a typo in a
    // command line fails the same way for every scene.
    const SoftShadowSettings settings = softShadowSettings(context);
    // Only point lights: nothing to do, and nothing to pay.
    const bool anyShape = std::any_of(scene.lights.begin(), scene.lights.end(),
                                      [](const PointLight& l) { return l.shape != nullptr; });
    if (!anyShape || !settings.sample) return;  // ss = 0 (seed 001): shaped lights stay points
    for (PointLight& light : scene.lights) {
        // Give each of our shapes the strategy this render asked for.
        const auto* shape = dynamic_cast<const AreaLightShape*>(light.shape.get());
        if (shape && shape->sampling() != settings.sampling)
            light.shape = shape->withSampling(settings.sampling);
    }
    scene.sampleAreaLights = true;
    scene.lightSamples = settings.samplesPerAxis;
}
// [install-soft-shadows]

/// The chapter's samplers for ./rt --warptest (soft_shadows_warps.cpp).
std::vector<Warp> softShadowsWarps();

Feature softShadowsFeature() {
    Feature f{"soft_shadows",
              6,
              "rectangular and ball area lights, soft shadows",
              true,
              bindSoftShadows,
              installSoftShadows};
    f.options = {
        {"light-samples", "N", "samples per axis for every area light (N x N shadow rays)",
         "the scene's light_samples or ss, else each light's own"},
        {"light-sampling", "stratified|independent", "how points on area lights are chosen",
         "stratified"},
    };
    f.warps = softShadowsWarps;
    return f;
}

}  // namespace rb
