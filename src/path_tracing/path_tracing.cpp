#include "path_tracing/path_tracing.h"

#include <cmath>

#include "core/error.h"
#include "core/render_context.h"
#include "lab/warp.h"

namespace rb {

bool pathTracingChosen(const RenderContext& context) {
    const std::string method = context.cliOption("integrator");
    if (method.empty()) return context.sceneOption("integrator_path", 0.0) != 0.0;
    if (method != "path" && method != "whitted")
        throw InputError("--integrator: expected 'path' or 'whitted', got '" + method + "'");
    return method == "path";
}

namespace {

/// A whole number from `lo` to `hi` given to option `name`, else `fallback`.
int wholeOption(const RenderContext& context, const char* name, int lo, int hi, int fallback) {
    const std::string text = context.cliOption(name);
    if (text.empty()) return fallback;
    const double n = parseNumberOption(std::string("--") + name, text);
    if (!(n >= lo && n <= hi && n == std::floor(n)))
        throw InputError(std::string("--") + name + ": expected a whole number from " +
                         std::to_string(lo) + " to " + std::to_string(hi) + ", got " + text);
    return static_cast<int>(n);
}

/// A4's view of an emitting surface (chapter 18 on, Whitted's integrator): it glows with its
/// emission, lighting nothing (Whitted's lights are the point lights).
class EmissionTerm final : public ShadingTerm {
  public:
    Colour apply(const ShadeContext&, const Ray&, const Hit& hit,
                 const Colour& colour) const override {
        return hit.material ? colour + hit.material->emission : colour;
    }
};

// [install-path-tracing]
void installPathTracing(Pipeline& pipeline, Scene&, const RenderContext& context) {
    // The options are checked whichever integrator runs: a typo is an error, not a no-op.
    const PathSettings settings = pathSettings(context);
    if (!pathTracingChosen(context)) {
        // Whitted: emitting surfaces glow, and a scene without them pays nothing.
        for (const Instance& i : context.instances)
            if (i.material && i.material->emission != Colour(0.0)) {
                pipeline.terms.push_back(std::make_shared<EmissionTerm>());
                break;
            }
        return;
    }
    auto tracer = std::make_shared<PathTracer>(settings);
    pipeline.radiance = tracer;
    // The emitters are gathered once the instances are final, before the first camera ray.
    pipeline.prePasses.push_back(tracer);
}
// [install-path-tracing]

}  // namespace

PathSettings pathSettings(const RenderContext& context) {
    PathSettings s;
    s.maxDepth = static_cast<int>(context.sceneOption("path_depth", s.maxDepth));
    s.rouletteDepth = static_cast<int>(context.sceneOption("path_roulette", s.rouletteDepth));
    s.maxDepth = wholeOption(context, "path-depth", 1, 1000000, s.maxDepth);
    s.rouletteDepth = wholeOption(context, "path-roulette", 0, 1000000, s.rouletteDepth);
    const std::string strategy = context.cliOption("path-strategy", "mis");
    if (strategy == "mis")
        s.strategy = PathStrategy::Mis;
    else if (strategy == "light")
        s.strategy = PathStrategy::Light;
    else if (strategy == "bsdf")
        s.strategy = PathStrategy::Bsdf;
    else
        throw InputError("--path-strategy: expected 'mis', 'light' or 'bsdf', got '" + strategy +
                         "'");
    return s;
}

/// The chapter's samplers for ./rt --warptest (path_warps.cpp).
std::vector<Warp> pathTracingWarps();

Feature pathTracingFeature() {
    return {"path_tracing",
            18,
            "path tracing: the rendering equation without bias (NEE, MIS, Russian roulette)",
            true,
            bindPathTracing,
            installPathTracing,
            {{"integrator", "path|whitted", "path tracing, or A4's recursive ray tracing",
              "the scene's gr.integrator, else whitted"},
             {"path-depth", "N", "bounces a path may take at most", "the scene's, else 64"},
             {"path-roulette", "N", "the bounce from which Russian roulette plays",
              "the scene's, else 3"},
             {"path-strategy", "mis|light|bsdf",
              "emitting surfaces by both samplers weighed by MIS, or by one alone", "mis"}},
            {},
            pathTracingWarps};
}

}  // namespace rb
