#include "media/noise_bound.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "bump/gradient_noise.h"

namespace rb {

namespace {

/// Boxes crossing more lattice walls than this on an axis get anyNoise() (cheap and loose).
constexpr int kMaxWallsPerAxis = 1;
/// Pieces no longer than this (in lattice cells) are bounded whole; longer ones are split,
/// because the bound of a piece loosens with its size.
constexpr double kPieceLength = 0.25;

/// The union of two intervals.
NoiseRange join(const NoiseRange& a, const NoiseRange& b) {
    return {std::min(a.lo, b.lo), std::max(a.hi, b.hi)};
}

/// The interval of an affine function g·(f − c) for f in the box [a, b]: each axis adds its
/// term's smaller and larger end.
NoiseRange dotRange(const Vec3& g, const Vec3& a, const Vec3& b, const Vec3& c) {
    NoiseRange r{0.0, 0.0};
    for (int axis = 0; axis < 3; ++axis) {
        const double u = g[axis] * (a[axis] - c[axis]), v = g[axis] * (b[axis] - c[axis]);
        r.lo += std::min(u, v);
        r.hi += std::max(u, v);
    }
    return r;
}

/// The interval of the noise over the piece [a, b] ⊂ [0, 1]³ of lattice cell (i, j, k).
/// The noise is Σ_c w_c(f)·d_c(f) over the 8 corners c, with weights w_c ≥ 0 that sum to 1
/// (products of faded coordinates) and d_c = g_c·(f − c). Two bounds hold, and so does the
/// tighter of the two: the convex one, [min d_c, max d_c], and the term by term one,
/// Σ_c [w_c]·[d_c] with the weights' own intervals (tight when the piece is small).
NoiseRange pieceRange(std::int64_t i, std::int64_t j, std::int64_t k, std::uint32_t seed,
                      const Vec3& a, const Vec3& b) {
    // The fade rises on [0, 1], so its interval over [a, b] is [fade(a), fade(b)].
    const Vec3 fadeA(perlinFade(a.x), perlinFade(a.y), perlinFade(a.z));
    const Vec3 fadeB(perlinFade(b.x), perlinFade(b.y), perlinFade(b.z));
    NoiseRange convex{INFINITY, -INFINITY}, terms{0.0, 0.0};
    for (int corner = 0; corner < 8; ++corner) {
        const Vec3 c(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1);
        const NoiseRange d =
            dotRange(latticeGradient(i + (corner & 1), j + ((corner >> 1) & 1),
                                     k + ((corner >> 2) & 1), seed),
                     a, b, c);
        convex = join(convex, d);
        // The weight: fade(f) on the axes where the corner is at 1, 1 − fade(f) where at 0.
        double wLo = 1.0, wHi = 1.0;
        for (int axis = 0; axis < 3; ++axis) {
            wLo *= c[axis] > 0.0 ? fadeA[axis] : 1.0 - fadeB[axis];
            wHi *= c[axis] > 0.0 ? fadeB[axis] : 1.0 - fadeA[axis];
        }
        // w ≥ 0: w·d is largest at wHi when d > 0 and at wLo when d < 0 (and so on).
        terms.lo += d.lo < 0.0 ? wHi * d.lo : wLo * d.lo;
        terms.hi += d.hi > 0.0 ? wHi * d.hi : wLo * d.hi;
    }
    return {std::max(convex.lo, terms.lo), std::min(convex.hi, terms.hi)};
}

/// An interval that holds every value of gradient noise, whatever the lattice's gradients:
/// [−R, R] with R the largest of Σ_c w_c(f)·max_g g·(f − c) over the cell, each corner's
/// gradient picked adversarially (for the cube-edge gradients, max_g g·d is the sum of d's two
/// largest |dᵢ|). R is bounded piece by piece as pieceRange does, once; it is about 1.
NoiseRange anyNoise() {
    static const double r = [] {
        constexpr int n = 24;  // pieces per axis
        double worst = 0.0;
        for (int z = 0; z < n; ++z)
            for (int y = 0; y < n; ++y)
                for (int x = 0; x < n; ++x) {
                    const Vec3 a = Vec3(x, y, z) / double(n), b = Vec3(x + 1, y + 1, z + 1) / double(n);
                    const Vec3 fadeA(perlinFade(a.x), perlinFade(a.y), perlinFade(a.z));
                    const Vec3 fadeB(perlinFade(b.x), perlinFade(b.y), perlinFade(b.z));
                    double sum = 0.0;
                    for (int corner = 0; corner < 8; ++corner) {
                        double w = 1.0, d[3];
                        for (int axis = 0; axis < 3; ++axis) {
                            const bool one = (corner >> axis) & 1;
                            w *= one ? fadeB[axis] : 1.0 - fadeA[axis];
                            // The largest |f − c| on this axis over the piece.
                            d[axis] = one ? 1.0 - a[axis] : b[axis];
                        }
                        std::sort(d, d + 3);
                        sum += w * (d[1] + d[2]);
                    }
                    worst = std::max(worst, sum);
                }
        return worst;
    }();
    return {-r, r};
}

/// The ends of the pieces [lo, hi] splits into along one axis: at every lattice wall, and
/// within a cell into pieces of at most kPieceLength.
std::vector<double> pieceEnds(double lo, double hi) {
    std::vector<double> ends{lo};
    double start = lo;
    while (start < hi) {
        const double wall = std::min(std::floor(start) + 1.0, hi);
        const int n = std::max(1, static_cast<int>(std::ceil((wall - start) / kPieceLength)));
        for (int m = 1; m < n; ++m) ends.push_back(start + (wall - start) * m / n);
        ends.push_back(wall);
        start = wall;
    }
    return ends;
}

}  // namespace

NoiseRange gradientNoiseRange(const Vec3& lo, const Vec3& hi, std::uint32_t seed) {
    // Far out (or NaN) gradientNoise returns 0, inside anyNoise().
    if (!isFinite(lo) || !isFinite(hi) || !(maxAbsComponent(lo) < 0x1p61) ||
        !(maxAbsComponent(hi) < 0x1p61))
        return anyNoise();
    for (int axis = 0; axis < 3; ++axis)
        if (std::floor(hi[axis]) - std::floor(lo[axis]) > kMaxWallsPerAxis) return anyNoise();
    const std::vector<double> xs = pieceEnds(lo.x, hi.x), ys = pieceEnds(lo.y, hi.y),
                              zs = pieceEnds(lo.z, hi.z);
    NoiseRange range{INFINITY, -INFINITY};
    for (size_t z = 0; z + 1 < zs.size() || z == 0; ++z)
        for (size_t y = 0; y + 1 < ys.size() || y == 0; ++y)
            for (size_t x = 0; x + 1 < xs.size() || x == 0; ++x) {
                // A flat box (lo = hi on an axis) is one piece of zero length there.
                const Vec3 a(xs[x], ys[y], zs[z]);
                const Vec3 b(xs[std::min(x + 1, xs.size() - 1)],
                             ys[std::min(y + 1, ys.size() - 1)],
                             zs[std::min(z + 1, zs.size() - 1)]);
                // The piece's cell: the floor of its middle (its ends may sit on walls).
                const Vec3 cell = glm::floor(0.5 * (a + b));
                range = join(range, pieceRange(static_cast<std::int64_t>(cell.x),
                                               static_cast<std::int64_t>(cell.y),
                                               static_cast<std::int64_t>(cell.z), seed,
                                               a - cell, b - cell));
            }
    // Every value also lies in anyNoise(), which may be tighter for pieces near a cell's middle.
    return {std::max(range.lo, anyNoise().lo), std::min(range.hi, anyNoise().hi)};
}

NoiseRange fractalNoiseRange(const Vec3& lo, const Vec3& hi, int octaves, std::uint32_t seed) {
    // The same sum as fractalNoise, over intervals: octave o at frequency 2^o, amplitude 2^−o.
    NoiseRange sum{0.0, 0.0};
    double amplitude = 1.0, total = 0.0, frequency = 1.0;
    for (int o = 0; o < octaves; ++o) {
        const NoiseRange r = gradientNoiseRange(frequency * lo, frequency * hi,
                                                seed + static_cast<std::uint32_t>(o));
        sum.lo += amplitude * r.lo;
        sum.hi += amplitude * r.hi;
        total += amplitude;
        amplitude *= 0.5;
        frequency *= 2.0;
    }
    if (!(total > 0.0)) return {0.0, 0.0};
    return {sum.lo / total, sum.hi / total};
}

}  // namespace rb
