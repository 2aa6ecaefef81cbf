#include "glossy/glossy.h"

#include <charconv>
#include <cmath>
#include <cstdio>

#include "core/error.h"
#include "core/from_chars.h"
#include "core/material.h"
#include "core/render_context.h"
#include "glossy/lobe_samplers.h"
#include "lab/warp.h"

namespace rb {

void bindGlossy(LuaBindings& lua);

// [glossy-lobe]
int GlossyLobe::sampleCount(const Material& m) const {
    // Glossiness 0 (or unset) keeps chapter 4's sharp mirror and chapter 5's sharp refraction.
    return m.param("glossiness") > 0.0 ? samples_ : 0;
}

bool GlossyLobe::sample(const Material& m, const Vec3& axis, const Vec3& n, Sampler& sampler,
                        Vec3& direction) const {
    const double fuzz = fuzzFromGlossiness(m.param("glossiness"));
    if (kind_ == LobeKind::Fuzz) {
        const double u1 = sampler.next1D(), u2 = sampler.next1D(), u3 = sampler.next1D();
        direction = sampleFuzzSphere(axis, fuzz, u1, u2, u3);
    } else {
        const Vec2 u = sampler.next2D();
        direction = samplePhongLobe(axis, phongExponentFromFuzz(fuzz), u.x, u.y);
    }
    // A direction below the surface would start inside the object (or, for a transmitted
    // ray, back on the side it came from): reject it. traceSpecular still counts it in the
    // average, so it carries zero light.
    return glm::dot(direction, n) > 0.0;
}
// [glossy-lobe]

namespace {

/// A whole number from 0 to 65536, or InputError naming `what`.
int parseSampleCount(const std::string& what, const std::string& text) {
    int v = -1;
    const auto [end, ec] = rb::fromChars(text.data(), text.data() + text.size(), v);
    if (ec != std::errc() || end != text.data() + text.size() || v < 0 || v > 65536)
        throw InputError(what + ": expected a whole number from 0 to 65536, got '" + text + "'");
    return v;
}

/// A scene option that must be a whole number in [0, hi].
int wholeSceneOption(double value, int hi, const std::string& what) {
    if (!(value >= 0.0 && value <= hi && value == std::floor(value))) {
        char got[32];
        std::snprintf(got, sizeof got, "%g", value);
        throw InputError(what + ": expected a whole number from 0 to " + std::to_string(hi) +
                         ", got " + got);
    }
    return static_cast<int>(value);
}

}  // namespace

// [glossy-samples]
int glossySampleCount(const RenderContext& context) {
    // The command line overrides the scene; raybook's named option overrides seed 001's
    // positional `dist`, which asks for dist × dist rays (0: no distribution ray tracing).
    const std::string cli = context.cliOption("glossy-samples");
    if (!cli.empty()) return parseSampleCount("--glossy-samples", cli);
    // Scene options are always finite, so NaN marks one that is absent.
    const double absent = std::nan("");
    const double option = context.sceneOption("glossy_samples", absent);
    if (!std::isnan(option)) return wholeSceneOption(option, 65536, "gr.option('glossy_samples')");
    const double dist = context.sceneOption("dist", absent);
    if (!std::isnan(dist)) {
        const int perAxis = wholeSceneOption(dist, 256, "gr.render: argument 13 (dist)");
        return perAxis * perAxis;
    }
    return kDefaultGlossySamples;
}
// [glossy-samples]

LobeKind glossyLobeKind(const RenderContext& context) {
    const std::string cli = context.cliOption("glossy-sampler");
    if (cli == "fuzz") return LobeKind::Fuzz;
    if (cli == "lobe") return LobeKind::Phong;
    if (!cli.empty())
        throw InputError("--glossy-sampler: expected fuzz or lobe, got '" + cli + "'");
    const double option = context.sceneOption("glossy_sampler", 1.0);
    if (option == 0.0) return LobeKind::Fuzz;
    if (option == 1.0) return LobeKind::Phong;
    char got[32];
    std::snprintf(got, sizeof got, "%g", option);
    throw InputError(std::string("gr.option('glossy_sampler'): expected 0 (fuzz sphere) or 1 ") +
                     "(Phong lobe), got " + got);
}

namespace {

// [glossy-install]
void installGlossy(Pipeline& pipeline, Scene&, const RenderContext& context) {
    // Read the options even when nothing is glossy, so a bad value is always reported.
    const int samples = glossySampleCount(context);
    const LobeKind kind = glossyLobeKind(context);
    // A scene without a glossy material pays nothing: no lobe, so every specular ray is sharp.
    if (samples > 0 && context.anyMaterialUses("glossiness"))
        pipeline.lobe = std::make_shared<GlossyLobe>(kind, samples);
}
// [glossy-install]

}  // namespace

/// The chapter's samplers for ./rt --warptest (glossy_warps.cpp).
std::vector<Warp> glossyWarps();

Feature glossyFeature() {
    return {"glossy",
            7,
            "glossy reflection and translucency: fuzz sphere or Phong lobe",
            true,
            bindGlossy,
            installGlossy,
            {{"glossy-samples", "N", "directions averaged per glossy surface",
              "the scene's glossy_samples or dist, else 16"},
             {"glossy-sampler", "fuzz|lobe", "fuzz sphere (seed 000) or Phong lobe",
              "the scene's glossy_sampler, else lobe"}},
            {},
            glossyWarps};
}

}  // namespace rb
