#include "adaptive_aa/supersampling.h"

#include <algorithm>

namespace rb {

Colour randomPixel(const PixelRef& pixel, int count, const RadianceAt& radiance) {
    Colour sum(0.0);
    for (int s = 0; s < count; ++s) {
        Sampler sampler(pixel.seed, pixel.index, s);
        const Vec2 u = sampler.next2D();
        sum += radiance(Vec2(pixel.x + u.x, pixel.y + u.y), {pixel.seed, pixel.index, s, count},
                        sampler);
    }
    return sum / static_cast<double>(count);
}

// [uniform-pixel]
Colour uniformPixel(const PixelRef& pixel, int n, const RadianceAt& radiance) {
    // Sample the centre of each of the n × n sub-pixels, in scanline order.
    Colour sum(0.0);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            Sampler sampler(pixel.seed, pixel.index, static_cast<std::uint64_t>(j) * n + i);
            const Vec2 p(pixel.x + (i + 0.5) / n, pixel.y + (j + 0.5) / n);
            sum += radiance(p, {pixel.seed, pixel.index, j * n + i, n * n}, sampler);
        }
    return sum / static_cast<double>(n * n);
}
// [uniform-pixel]

// [jittered-pixel]
Colour jitteredPixel(const PixelRef& pixel, int n, const RadianceAt& radiance) {
    // [exercise-jittered]
    // Exercise 8.1, jittered supersampling: read ch08-equations.
    // Blank: return Colour(0.0);
    // One uniform position in each cell: the cell is chosen, only the place inside it is random.
    Colour sum(0.0);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            Sampler sampler(pixel.seed, pixel.index, static_cast<std::uint64_t>(j) * n + i);
            const Vec2 u = sampler.next2D();
            const Vec2 p(pixel.x + (i + u.x) / n, pixel.y + (j + u.y) / n);
            sum += radiance(p, {pixel.seed, pixel.index, j * n + i, n * n}, sampler);
        }
    return sum / static_cast<double>(n * n);
    // [exercise-jittered]
}
// [jittered-pixel]

LatticeSamples::LatticeSamples(int x0, int y0, int x1, int y1, int width, int maxDepth,
                               std::uint64_t seed, const RadianceAt& radiance)
    : perPixel_(std::int64_t(2) << maxDepth),
      rowLength_(static_cast<std::int64_t>(width) * perPixel_ + 1),
      i0_(x0 * perPixel_),
      j0_(y0 * perPixel_),
      columns_((x1 - x0) * perPixel_ + 1),
      seed_(seed),
      radiance_(radiance) {
    const std::int64_t points = columns_ * ((y1 - y0) * perPixel_ + 1);
    samples_.reset(new Colour[points]);  // uninitialised on purpose (see done_)
    done_.assign((points + 63) / 64, 0);
}

// [lattice-sample]
Colour LatticeSamples::at(std::int64_t i, std::int64_t j) {
    // Already traced: share it.
    const std::int64_t slot = (j - j0_) * columns_ + (i - i0_);
    const std::uint64_t bit = std::uint64_t(1) << (slot % 64);
    if (done_[slot / 64] & bit) return samples_[slot];
    // First use: trace it. Its position and its random stream depend only on (i, j) and the
    // seed, so whoever traces this point gets this colour. L is a power of two, so i / L is
    // exact: the lattice point and a pixel centre (i = (x + ½)·L) are the very same position.
    const std::int64_t key = j * rowLength_ + i;
    Sampler sampler(seed_, static_cast<std::uint64_t>(key), 0);
    const double L = static_cast<double>(perPixel_);
    samples_[slot] =
        radiance_(Vec2(i / L, j / L), {seed_, static_cast<std::uint64_t>(key), 0, 1}, sampler);
    done_[slot / 64] |= bit;
    ++traced_;
    return samples_[slot];
}
// [lattice-sample]

namespace {

/// The largest channel difference of two colours as the image will show them (clamped to
/// [0, 1]): a difference above white cannot be seen, so it must not trigger refinement.
double visibleDifference(const Colour& a, const Colour& b) {
    const Colour d = glm::abs(glm::clamp(a, 0.0, 1.0) - glm::clamp(b, 0.0, 1.0));
    return std::max({d.x, d.y, d.z});
}

// [adaptive-square]
/// The mean radiance over the square with top-left lattice point (i, j) and side `size`
/// (lattice units), whose corner samples are c00 (top-left), c10, c01 and c11.
Colour adaptiveSquare(std::int64_t i, std::int64_t j, std::int64_t size, int depth,
                      const AdaptiveSettings& settings, LatticeSamples& lattice, const Colour& c00,
                      const Colour& c10, const Colour& c01, const Colour& c11) {
    // [exercise-adaptive-square]
    // Exercise 8.2, adaptive recursive supersampling: read ch08-equations.
    // Blank: return Colour(0.0);
    // Sample the centre, and compare it with the four corners.
    const std::int64_t h = size / 2;
    const Colour centre = lattice.at(i + h, j + h);
    const bool differs = visibleDifference(centre, c00) > settings.threshold ||
                         visibleDifference(centre, c10) > settings.threshold ||
                         visibleDifference(centre, c01) > settings.threshold ||
                         visibleDifference(centre, c11) > settings.threshold;
    if (!differs || depth == settings.maxDepth)
        // Centre 2/3, corners 1/12 each: the symmetric rule on these five points that is exact
        // for every polynomial of degree 3 (it integrates x² to 1/12 over the unit square).
        return (8.0 * centre + c00 + c10 + c01 + c11) / 12.0;
    // Split into four: the new corners are the edge midpoints and the centre.
    const Colour top = lattice.at(i + h, j), bottom = lattice.at(i + h, j + size);
    const Colour left = lattice.at(i, j + h), right = lattice.at(i + size, j + h);
    const int d = depth + 1;
    return 0.25 *
           (adaptiveSquare(i, j, h, d, settings, lattice, c00, top, left, centre) +
            adaptiveSquare(i + h, j, h, d, settings, lattice, top, c10, centre, right) +
            adaptiveSquare(i, j + h, h, d, settings, lattice, left, centre, c01, bottom) +
            adaptiveSquare(i + h, j + h, h, d, settings, lattice, centre, right, bottom, c11));
    // [exercise-adaptive-square]
}
// [adaptive-square]

}  // namespace

Colour adaptivePixel(int x, int y, const AdaptiveSettings& settings, LatticeSamples& lattice) {
    // The pixel is the square of side L whose top-left lattice point is (x·L, y·L); its corners
    // are shared with its neighbours through the lattice.
    const std::int64_t L = lattice.perPixel();
    const std::int64_t i = x * L, j = y * L;
    return adaptiveSquare(i, j, L, 0, settings, lattice, lattice.at(i, j), lattice.at(i + L, j),
                          lattice.at(i, j + L), lattice.at(i + L, j + L));
}

}  // namespace rb
