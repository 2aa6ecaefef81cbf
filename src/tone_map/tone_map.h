/// \file
/// Chapter 12, tone mapping: the film holds radiance of any size, a display shows [0, 1].
/// Exposure, Reinhard's global and local operators and sRGB encoding turn one into the other,
/// as an image post-process after the render; Radiance .hdr output keeps the film as it is.
#pragma once

#include <cstdint>
#include <string>

#include "core/feature.h"
#include "core/post_process.h"

namespace rb {

struct RenderContext;

/// Which curve maps scaled luminance to display luminance.
enum class ToneOperator {
    None,    ///< Clip: each channel clamped to [0, 1], as the CS488 framework writes it.
    Global,  ///< Reinhard 2002, equation 4: L (1 + L / L_white²) / (1 + L).
    Local    ///< Reinhard 2002, equation 9: L / (1 + V1(x, y, s_m)), dodge and burn.
};

/// The value of gr.option('tone_map', k) for each operator (k = 0, 1, 2), and of
/// gr.tone_map's `operator` field and --tone-map (names[k]).
inline constexpr const char* kToneOperatorNames[] = {"none", "global", "local"};

/// The settings of chapter 12 for one render.
struct ToneMapSettings {
    ToneOperator op = ToneOperator::None;
    double key = 0.18;        ///< a: the scaled log-average luminance (middle grey).
    double white = 0.0;       ///< L_white (scaled); 0: the image's largest, < 0: infinite.
    double exposure = 0.0;    ///< Stops: the scaled luminance is multiplied by 2^exposure.
    bool srgb = false;        ///< Encode the result with the sRGB transfer function.
    double sharpness = 8.0;   ///< φ of the local operator.
    double threshold = 0.05;  ///< ε of the local operator.
    /// True when the settings change the image at all (otherwise nothing is installed).
    bool active() const { return op != ToneOperator::None || exposure != 0.0 || srgb; }
};

/// Read the settings. For each, the first that is present wins: the command line
/// (--tone-map, --tone-key, --tone-white, --exposure, --srgb), the scene (gr.tone_map, or
/// gr.option('tone_map' …)), the default (none; key 0.18; L_white the image's largest; 0
/// stops; sRGB on exactly when an operator is chosen). Throws InputError for a bad value.
ToneMapSettings toneMapSettings(const RenderContext& context);

/// Tone map the film in place: exposure, then the operator on luminance (colours keep their
/// ratios), then clamping to [0, 1] and, if asked, sRGB encoding. Negative and non-finite
/// channels count as 0.
void toneMap(Image& film, const ToneMapSettings& settings);

/// The bytes per pixel toneMap allocates besides the film: nothing without an operator; the
/// luminances, scaled luminances, display luminances and ratios (4 doubles) for the global
/// operator; and for the local one also its blurs (centre, surround, adaptation and the blur's
/// intermediate and result: 5 doubles) and a flag per pixel.
std::uint64_t toneMapBytesPerPixel(const ToneMapSettings& settings);

/// The post-process chapter 12 installs.
class ToneMapper final : public PostProcess {
  public:
    /// A tone mapper with the given (checked) settings.
    explicit ToneMapper(const ToneMapSettings& settings) : settings_(settings) {}
    /// Tone map the film in place.
    void apply(Image& film) const override { toneMap(film, settings_); }
    /// The buffers toneMap allocates per pixel for these settings.
    std::uint64_t bytesPerPixel() const override { return toneMapBytesPerPixel(settings_); }
    /// The settings in use.
    const ToneMapSettings& settings() const { return settings_; }

  private:
    ToneMapSettings settings_;
};

/// Plug chapter 12 into one render: install a ToneMapper when the settings change the image;
/// otherwise the core writes the film as before.
void installToneMap(Pipeline& pipeline, Scene& scene, const RenderContext& context);

/// Chapter 12's Lua calls: gr.tone_map{...} and the options tone_map, tone_key, tone_white,
/// exposure, srgb, tone_sharpness and tone_threshold.
void bindToneMap(LuaBindings& lua);

/// Chapter 12's feature record.
Feature toneMapFeature();

}  // namespace rb
