#include "adaptive_aa/adaptive_aa.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>

#include "core/error.h"
#include "core/render_context.h"
#include "lab/warp.h"

namespace rb {

namespace {

/// The most rays per pixel the random and grid samplers may take (256 × 256).
constexpr int kMaxSamples = 65536;

/// True when n is a perfect square.
bool isSquare(int n) {
    const int r = static_cast<int>(std::lround(std::sqrt(static_cast<double>(n))));
    return r * r == n;
}

/// A mode from its name (--aa, gr.antialias), or InputError naming `what`.
AaMode modeNamed(const std::string& name, const std::string& what) {
    for (int k = 0; k < 5; ++k)
        if (name == kAaModeNames[k]) return static_cast<AaMode>(k);
    throw InputError(what + ": expected none, random, uniform, jittered or adaptive, got '" + name +
                     "'");
}

}  // namespace

// [aa-settings]
AaSettings aaSettings(const RenderContext& context) {
    AaSettings s;
    const double absent = std::nan("");  // scene options are always finite
    const double seedAa = context.sceneOption("aa", absent);
    // The sampler: --aa, else the scene's, else seed 001's aa = 1 (a 2 × 2 uniform supersample).
    std::string where = "the default";
    if (!context.cliOption("aa").empty()) {
        s.mode = modeNamed(context.cliOption("aa"), "--aa");
        where = "--aa";
    } else if (!std::isnan(context.sceneOption("aa_sampler", absent))) {
        s.mode = static_cast<AaMode>(static_cast<int>(context.sceneOption("aa_sampler", 0)));
        where = "the scene's aa_sampler";
    } else if (!std::isnan(seedAa)) {
        if (seedAa != 0.0 && seedAa != 1.0)
            throw InputError("gr.render: argument 11 (aa) must be 0 (off) or 1 (on), got " +
                             formatNumber(seedAa));
        if (seedAa == 1.0) s.mode = AaMode::Uniform;
        where = "gr.render's aa";
    }
    // Rays per pixel: --spp, else the scene's aa_samples, else 4 (seed 001's 2 × 2).
    const std::string spp = context.cliOption("spp");
    s.samples = 4;
    if (!spp.empty())
        s.samples = static_cast<int>(parseNumberOption("--spp", spp));
    else if (!std::isnan(context.sceneOption("aa_samples", absent)))
        s.samples = static_cast<int>(context.sceneOption("aa_samples", 4));
    const std::string sppSource = spp.empty() ? "aa_samples" : "--spp";
    if (s.samples < 1 || s.samples > kMaxSamples)
        throw InputError(sppSource + ": expected 1 to " + std::to_string(kMaxSamples) +
                         " rays per pixel, got " + std::to_string(s.samples));
    if ((s.mode == AaMode::Uniform || s.mode == AaMode::Jittered) && !isSquare(s.samples))
        throw InputError(
            sppSource + " " + std::to_string(s.samples) + ": the " +
            kAaModeNames[static_cast<int>(s.mode)] + " sampler (from " + where +
            ") takes n x n rays per pixel, so it needs a square number (4, 9, 16, ...)");
    if (s.mode == AaMode::Adaptive && !spp.empty())
        throw InputError(
            "--spp does not apply to the adaptive sampler (from " + where +
            "): its rays follow --aa-threshold and --aa-depth; add --aa=jittered (or uniform, "
            "random) to choose a sampler that takes --spp");
    // The adaptive sampler's threshold and depth.
    const std::string threshold = context.cliOption("aa-threshold");
    s.adaptive.threshold = threshold.empty() ? context.sceneOption("aa_threshold", 0.1)
                                             : parseNumberOption("--aa-threshold", threshold);
    if (s.adaptive.threshold < 0.0)
        throw InputError("--aa-threshold: expected a number >= 0, got " +
                         formatNumber(s.adaptive.threshold));
    const std::string depth = context.cliOption("aa-depth");
    const double d =
        depth.empty() ? context.sceneOption("aa_depth", 3) : parseNumberOption("--aa-depth", depth);
    if (d != std::floor(d) || d < 0 || d > kMaxAdaptiveDepth)
        throw InputError("--aa-depth: expected a whole number from 0 to " +
                         std::to_string(kMaxAdaptiveDepth) + ", got " + formatNumber(d));
    s.adaptive.maxDepth = static_cast<int>(d);
    return s;
}
// [aa-settings]

// [render-tile]
void SupersamplingSampler::renderTile(const ImageTile& tile, const Integrator& integrator,
                                      const PinholeCamera& camera, int width, int,
                                      std::uint64_t seed, Image& image, RayCounters& rays,
                                      PixelStop& stop) const {
    // What every estimator asks for: the radiance through an image position, as the core's
    // loop traces it (a camera ray, then the integrator with the sample's own random stream).
    // A camera-ray generator (chapter 13's lens) pairs each ray with one of its own samples.
    const CameraRayGenerator* lens = integrator.pipeline().cameraRays.get();
    const RadianceAt radiance = [&](const Vec2& p, const RaySlot& slot, Sampler& sampler) {
        const Ray ray =
            lens ? lens->generate(camera, p, slot, sampler) : camera.generateRay(p.x, p.y);
        rays.add(RayKind::Camera);
        return integrator.trace(ray, sampler, rays, 0);
    };
    if (settings_.mode == AaMode::Adaptive) {
        // The adaptive sampler's samples, shared by the pixels of this tile.
        LatticeSamples lattice(tile.x0, tile.y0, tile.x1, tile.y1, width,
                               settings_.adaptive.maxDepth, seed, radiance);
        for (int y = tile.y0; y < tile.y1; ++y)
            for (int x = tile.x0; x < tile.x1; ++x) {
                image.set(x, y, adaptivePixel(x, y, settings_.adaptive, lattice));
                stop.afterPixel(rays.total());
            }
        return;
    }
    // A lens that needs more rays per pixel raises the count (to the next square for a grid):
    // its samples are paired with the pixel's, not multiplied by them.
    const int samples =
        lens ? std::max(settings_.samples, lens->raysPerPixel()) : settings_.samples;
    const int n = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(samples)) - 1e-9));
    for (int y = tile.y0; y < tile.y1; ++y)
        for (int x = tile.x0; x < tile.x1; ++x) {
            const PixelRef pixel{x, y, seed, static_cast<std::uint64_t>(y) * width + x};
            Colour c(0.0);
            switch (settings_.mode) {
                case AaMode::Random:
                    c = randomPixel(pixel, samples, radiance);
                    break;
                case AaMode::Uniform:
                    c = uniformPixel(pixel, n, radiance);
                    break;
                case AaMode::Jittered:
                    c = jitteredPixel(pixel, n, radiance);
                    break;
                case AaMode::Adaptive:  // rendered above
                case AaMode::None:
                    break;  // never installed
            }
            image.set(x, y, c);
            stop.afterPixel(rays.total());
        }
}
// [render-tile]

// [install-aa]
void installAdaptiveAa(Pipeline& pipeline, Scene&, const RenderContext& context) {
    // Read (and check) the settings for every scene, so a bad value always fails the same way.
    const AaSettings settings = aaSettings(context);
    // No antialiasing asked for: the core's loop, untouched, so this chapter costs nothing.
    if (settings.mode == AaMode::None) return;
    pipeline.pixelSampler = std::make_shared<SupersamplingSampler>(settings);
}
// [install-aa]

/// The chapter's samplers for ./rt --warptest (adaptive_aa_warps.cpp).
std::vector<Warp> adaptiveAaWarps();

Feature adaptiveAaFeature() {
    return {"adaptive_aa",
            8,
            "antialiasing: uniform, jittered and adaptive supersampling",
            true,
            bindAdaptiveAa,
            installAdaptiveAa,
            {{"aa", "none|random|uniform|jittered|adaptive", "how a pixel's rays are placed",
              "the scene's gr.antialias or aa, else none"},
             {"aa-threshold", "T", "adaptive: split a square whose samples differ by more",
              "the scene's aa_threshold, else 0.1"},
             {"aa-depth", "D", "adaptive: how often a square may be split (0 to 6)",
              "the scene's aa_depth, else 3"}},
            {},
            adaptiveAaWarps};
}

}  // namespace rb
