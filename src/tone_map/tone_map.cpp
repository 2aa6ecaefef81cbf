#include "tone_map/tone_map.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

#include "core/error.h"
#include "core/integrator.h"
#include "core/render_context.h"
#include "tone_map/hdr_output.h"
#include "tone_map/reinhard.h"
#include "tone_map/srgb.h"

namespace rb {

namespace {

/// A channel as the tone map reads it: negative and non-finite values are 0.
double usable(float c) {
    return std::isfinite(c) && c > 0.0f ? static_cast<double>(c) : 0.0;
}

}  // namespace

// [tone-settings]
ToneMapSettings toneMapSettings(const RenderContext& context) {
    ToneMapSettings s;
    // The operator: --tone-map, else the scene's tone_map, else none.
    const std::string op = context.cliOption("tone-map");
    bool opChosen = false;
    if (!op.empty()) {
        int k = -1;
        for (int i = 0; i < 3; ++i)
            if (op == kToneOperatorNames[i]) k = i;
        if (k < 0) throw InputError("--tone-map: expected none, global or local, got '" + op + "'");
        s.op = static_cast<ToneOperator>(k);
        opChosen = true;
    } else if (context.job.options.count("tone_map")) {
        s.op = static_cast<ToneOperator>(static_cast<int>(context.sceneOption("tone_map", 0)));
        opChosen = true;
    }
    // The key a: --tone-key, else the scene's, else 0.18 (Reinhard's "normal key").
    const std::string key = context.cliOption("tone-key");
    s.key =
        key.empty() ? context.sceneOption("tone_key", 0.18) : parseNumberOption("--tone-key", key);
    if (!(s.key > 0.0 && s.key <= 100.0))
        throw InputError("--tone-key: expected a key above 0 and at most 100, got " +
                         formatNumber(s.key));
    // L_white: a number, "max" (0: the image's largest scaled luminance) or "none" (< 0).
    const std::string white = context.cliOption("tone-white");
    if (white == "max")
        s.white = 0.0;
    else if (white == "none")
        s.white = -1.0;
    else if (!white.empty()) {
        s.white = parseNumberOption("--tone-white", white);
        if (s.white <= 0.0)
            throw InputError("--tone-white: expected a positive number, max or none, got '" +
                             white + "'");
    } else
        s.white = context.sceneOption("tone_white", 0.0);
    // Exposure in stops.
    const std::string exposure = context.cliOption("exposure");
    s.exposure = exposure.empty() ? context.sceneOption("exposure", 0.0)
                                  : parseNumberOption("--exposure", exposure);
    if (std::abs(s.exposure) > 30.0)
        throw InputError("--exposure: expected -30 to 30 stops, got " + formatNumber(s.exposure));
    // sRGB: --srgb, else the scene's, else on exactly when an operator was chosen.
    const std::string srgb = context.cliOption("srgb");
    if (srgb == "on")
        s.srgb = true;
    else if (srgb == "off")
        s.srgb = false;
    else if (!srgb.empty())
        throw InputError("--srgb: expected on or off, got '" + srgb + "'");
    else if (context.job.options.count("srgb"))
        s.srgb = context.sceneOption("srgb", 0.0) != 0.0;
    else
        s.srgb = opChosen && s.op != ToneOperator::None;
    s.sharpness = context.sceneOption("tone_sharpness", 8.0);
    s.threshold = context.sceneOption("tone_threshold", 0.05);
    return s;
}
// [tone-settings]

// [tone-map]
void toneMap(Image& film, const ToneMapSettings& settings) {
    const std::span<float> rgb = film.data();
    const std::size_t n = rgb.size() / 3;
    const double gain = std::exp2(settings.exposure);
    // Without an operator every pixel is scaled by the exposure alone.
    std::vector<double> ratio;  // display value / film value, per pixel
    if (settings.op != ToneOperator::None) {
        std::vector<double> Lw(n);
        // Step 1: the world luminance of each pixel, and the image's key.
        for (std::size_t p = 0; p < n; ++p)
            Lw[p] = luminance({usable(rgb[3 * p]), usable(rgb[3 * p + 1]), usable(rgb[3 * p + 2])});
        const double average = logAverageLuminance(Lw);
        // Step 2: scale so the log average lands on the key a (times the exposure).
        const double a = settings.key * gain;
        std::vector<double> L(n);
        for (std::size_t p = 0; p < n; ++p) L[p] = a / average * Lw[p];
        // Step 3: compress the scaled luminance.
        std::vector<double> Ld;
        if (settings.op == ToneOperator::Global) {
            double Lwhite = settings.white;
            if (Lwhite == 0.0) Lwhite = *std::max_element(L.begin(), L.end());
            // A black image has no largest luminance to burn: plain L / (1 + L).
            if (!(Lwhite > 0.0)) Lwhite = std::numeric_limits<double>::infinity();
            Ld.resize(n);
            for (std::size_t p = 0; p < n; ++p) Ld[p] = reinhardGlobal(L[p], Lwhite);
        } else {
            LocalOperatorSettings local;
            local.key = a;
            local.sharpness = settings.sharpness;
            local.threshold = settings.threshold;
            Ld = reinhardLocal(L, film.width(), film.height(), local);
        }
        // Step 4: colours keep their ratios: each channel is scaled by L_d / L_w.
        ratio.resize(n);
        for (std::size_t p = 0; p < n; ++p) ratio[p] = Lw[p] > 0.0 ? Ld[p] / Lw[p] : 0.0;
    }
    // Step 5: clamp to what a display shows, then encode.
    for (std::size_t p = 0; p < n; ++p)
        for (int c = 0; c < 3; ++c) {
            const double scale = ratio.empty() ? gain : ratio[p];
            double v = std::clamp(usable(rgb[3 * p + c]) * scale, 0.0, 1.0);
            if (settings.srgb) v = srgbEncode(v);
            rgb[3 * p + c] = static_cast<float>(v);
        }
}
// [tone-map]

std::uint64_t toneMapBytesPerPixel(const ToneMapSettings& settings) {
    switch (settings.op) {
        case ToneOperator::None:
            return 0;
        case ToneOperator::Global:
            return 4 * sizeof(double);
        case ToneOperator::Local:
            break;
    }
    return 9 * sizeof(double) + 1;
}

// [install-tone-map]
void installToneMap(Pipeline& pipeline, Scene&, const RenderContext& context) {
    // Read (and check) the settings for every scene, so a bad value always fails the same way.
    const ToneMapSettings settings = toneMapSettings(context);
    // Nothing asked for: no post-process, and the film is written as the course writes it.
    if (!settings.active()) return;
    pipeline.postProcess = std::make_shared<ToneMapper>(settings);
}
// [install-tone-map]

Feature toneMapFeature() {
    return {"tone_map",
            12,
            "tone mapping: exposure, Reinhard global and local, sRGB, Radiance .hdr output",
            true,
            bindToneMap,
            installToneMap,
            {{"tone-map", "none|global|local", "how radiance becomes display values",
              "the scene's gr.tone_map or tone_map, else none (clip)"},
             {"tone-key", "A", "the key: where the log-average luminance lands",
              "the scene's tone_key, else 0.18"},
             {"tone-white", "L|max|none", "global: the scaled luminance that becomes white",
              "the scene's tone_white, else max (the image's largest)"},
             {"exposure", "EV", "multiply the image by 2^EV before the tone map",
              "the scene's exposure, else 0"},
             {"srgb", "on|off", "encode the output with the sRGB transfer function",
              "the scene's srgb, else on with global or local"}},
            {{".hdr", "a Radiance HDR image", writeHdr}}};
}

}  // namespace rb
