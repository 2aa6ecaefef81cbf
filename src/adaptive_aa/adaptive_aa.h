/// \file
/// Chapter 8, antialiasing: more than one camera ray per pixel. Uniform and jittered n × n
/// supersampling, seed 000's N random samples, and adaptive recursive supersampling that spends
/// rays only where the picture changes.
#pragma once

#include <string>

#include "adaptive_aa/supersampling.h"
#include "core/feature.h"
#include "core/pixel_sampler.h"

namespace rb {

struct RenderContext;

/// How the samples of a pixel are placed.
enum class AaMode {
    None,      ///< The core: one ray through the pixel centre (or --spp random positions).
    Random,    ///< Seed 000's N× supersampling: N independent uniform positions.
    Uniform,   ///< n × n sub-pixel centres.
    Jittered,  ///< One random position in each of n × n cells.
    Adaptive   ///< Corners and centre, split where they differ.
};

/// The value of gr.option('aa_sampler', k) for each mode (k = 0 … 4), and of gr.antialias's
/// `sampler` field, --aa and messages (names[k]).
inline constexpr const char* kAaModeNames[] = {"none", "random", "uniform", "jittered", "adaptive"};

/// The settings chapter 8 reads for one render.
struct AaSettings {
    AaMode mode = AaMode::None;
    int samples = 1;  ///< Rays per pixel for random, uniform and jittered (n² for a grid).
    AdaptiveSettings adaptive;  ///< Threshold and depth for adaptive.
};

/// Read the settings. For each, the first that is present wins: the command line (--aa,
/// --spp, --aa-threshold, --aa-depth), the scene (gr.antialias, or gr.option('aa_sampler' …)),
/// seed 001's gr.render argument `aa` (1: a 2 × 2 uniform supersample), the default (none;
/// 4 samples; threshold 0.1; depth 3). Throws InputError for a bad or contradictory value.
AaSettings aaSettings(const RenderContext& context);

/// The pixel sampler chapter 8 installs: one of the estimators of supersampling.h per pixel.
class SupersamplingSampler final : public PixelSampler {
  public:
    /// A sampler with the given (checked) settings; mode must not be None.
    explicit SupersamplingSampler(const AaSettings& settings) : settings_(settings) {}
    /// Render a tile. The adaptive mode shares its lattice samples within the tile; a lattice
    /// point on a tile border is traced by both tiles and gets the same colour in each.
    void renderTile(const ImageTile& tile, const Integrator& integrator,
                    const PinholeCamera& camera, int width, int height, std::uint64_t seed,
                    Image& image, RayCounters& rays, PixelStop& stop) const override;
    /// The settings in use.
    const AaSettings& settings() const { return settings_; }

  private:
    AaSettings settings_;
};

/// Plug chapter 8 into one render: install a SupersamplingSampler when the settings ask for
/// antialiasing; otherwise leave the core's pixel loop, which then runs exactly as before.
void installAdaptiveAa(Pipeline& pipeline, Scene& scene, const RenderContext& context);

/// Chapter 8's Lua calls: gr.antialias{...} and the options aa_sampler, aa_samples,
/// aa_threshold and aa_depth.
void bindAdaptiveAa(LuaBindings& lua);

/// Chapter 8's feature record.
Feature adaptiveAaFeature();

}  // namespace rb
