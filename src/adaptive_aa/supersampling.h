/// \file
/// The pixel estimators of chapter 8: where in a pixel to look, and how to average what is seen.
/// Each works on any radiance function of image position, so the tests can feed them shapes
/// whose exact pixel coverage is known.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "core/camera_rays.h"
#include "core/sampler.h"
#include "core/vec.h"

namespace rb {

/// The radiance arriving through image position p (in pixels; (0,0) is the image's top-left
/// corner), for ray `slot` of the pixel's rays (a thin lens, chapter 13, pairs its own strata
/// with the pixel's through it), traced with the random stream `sampler` (for the soft shadows
/// and glossy lobes the ray meets).
using RadianceAt = std::function<Colour(const Vec2& p, const RaySlot& slot, Sampler& sampler)>;

/// The pixel whose top-left corner is (x, y), and the key of its random streams.
struct PixelRef {
    int x = 0, y = 0;
    std::uint64_t seed = 0;   ///< --seed.
    std::uint64_t index = 0;  ///< y · width + x: the pixel's key in rb::Sampler.
};

/// Seed 000's N× supersampling: `count` independent uniform positions in the pixel (the core's
/// `--spp N` path, sample s drawing its position from stream (seed, pixel, s)).
Colour randomPixel(const PixelRef& pixel, int count, const RadianceAt& radiance);

/// Uniform n × n supersampling: the centres of an n × n grid of sub-pixels, averaged. n = 2 is
/// seed 001's "render at double the resolution and average 4 pixels".
Colour uniformPixel(const PixelRef& pixel, int n, const RadianceAt& radiance);

/// Jittered (stratified) n × n supersampling: one uniform random position in each cell of an
/// n × n grid, averaged. Sub-sample s = j·n + i takes its position from stream (seed, pixel, s).
Colour jitteredPixel(const PixelRef& pixel, int n, const RadianceAt& radiance);

/// The settings of adaptive supersampling.
struct AdaptiveSettings {
    double threshold = 0.1;  ///< Subdivide when two samples differ by more than this.
    int maxDepth = 3;        ///< How often a square may be split into four (0: never).
};

/// The largest `AdaptiveSettings::maxDepth` allowed: 4^6 = 4096 sub-squares per pixel.
inline constexpr int kMaxAdaptiveDepth = 6;

/// The samples of adaptive supersampling over a rectangle of pixels, on a lattice of
/// L = 2^(maxDepth+1) points per pixel side. A lattice point's sample is a pure function of its
/// position: its ray goes through (i/L, j/L) and draws from stream (seed, i + j·(width·L + 1),
/// 0). So a corner shared by two pixels (or two sub-squares) is traced once here, and any other
/// LatticeSamples (another tile, another thread) that traces it gets the same colour.
class LatticeSamples {
  public:
    /// The lattice of pixels [x0, x1) × [y0, y1) of an image `width` pixels wide, for squares
    /// split at most maxDepth times.
    LatticeSamples(int x0, int y0, int x1, int y1, int width, int maxDepth, std::uint64_t seed,
                   const RadianceAt& radiance);
    /// The sample at lattice point (i, j) (image coordinates × L; inside the rectangle), traced
    /// on first use.
    Colour at(std::int64_t i, std::int64_t j);
    /// Lattice points per pixel side: 2^(maxDepth+1).
    std::int64_t perPixel() const { return perPixel_; }
    /// How many samples were traced (each lattice point once).
    std::uint64_t traced() const { return traced_; }

  private:
    std::int64_t perPixel_;
    std::int64_t rowLength_;  ///< Lattice points per row of the whole image: the key's stride.
    std::int64_t i0_, j0_;    ///< The rectangle's top-left lattice point.
    std::int64_t columns_;    ///< Lattice points per row of the rectangle.
    std::uint64_t seed_;
    const RadianceAt& radiance_;
    // One slot per lattice point of the rectangle, left uninitialised: only the pages of points
    // actually traced are ever touched, and `done_` (one bit a point) says which those are.
    std::unique_ptr<Colour[]> samples_;
    std::vector<std::uint64_t> done_;
    std::uint64_t traced_ = 0;
};

/// Adaptive recursive supersampling of pixel (x, y), in the manner of POV-Ray's method 2 and
/// Whitted (1980): sample the pixel's four corners and its centre; while the centre differs
/// from a corner by more than the threshold (in any channel, after clamping to [0, 1]) and the
/// depth allows, split the square into four and do the same in each; a square that is not
/// split contributes (8·centre + Σ corners)/12 over its area.
Colour adaptivePixel(int x, int y, const AdaptiveSettings& settings, LatticeSamples& lattice);

}  // namespace rb
