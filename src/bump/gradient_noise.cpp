#include "bump/gradient_noise.h"

#include <cmath>

namespace rb {

namespace {

/// A well-mixed 32-bit hash of a lattice point and a seed (multiply–xorshift rounds; every
/// input bit affects every output bit).
std::uint32_t hashLattice(std::int64_t i, std::int64_t j, std::int64_t k, std::uint32_t seed) {
    std::uint64_t h = seed * 0x9E3779B97F4A7C15ull;
    for (std::int64_t c : {i, j, k}) {
        h ^= static_cast<std::uint64_t>(c) + 0x632BE59BD9B4E019ull + (h << 6) + (h >> 2);
        h *= 0xBF58476D1CE4E5B9ull;
        h ^= h >> 31;
    }
    return static_cast<std::uint32_t>(h >> 32);
}

/// The 12 cube-edge gradients, picked by hash % 12.
constexpr double kGradients[12][3] = {{1, 1, 0}, {-1, 1, 0}, {1, -1, 0}, {-1, -1, 0},
                                      {1, 0, 1}, {-1, 0, 1}, {1, 0, -1}, {-1, 0, -1},
                                      {0, 1, 1}, {0, -1, 1}, {0, 1, -1}, {0, -1, -1}};

/// The dot product of the lattice point's gradient with the offset d from that point.
double gradientDot(std::uint32_t hash, const Vec3& d) {
    const double* g = kGradients[hash % 12];
    return g[0] * d.x + g[1] * d.y + g[2] * d.z;
}

double lerp(double t, double a, double b) {
    return a + t * (b - a);
}

}  // namespace

double perlinFade(double t) {
    return t * t * t * (t * (t * 6.0 - 15.0) + 10.0);
}

Vec3 latticeGradient(std::int64_t i, std::int64_t j, std::int64_t k, std::uint32_t seed) {
    const double* g = kGradients[hashLattice(i, j, k, seed) % 12];
    return {g[0], g[1], g[2]};
}

double gradientNoise(const Vec3& x, std::uint32_t seed) {
    // Find the lattice cell and the position inside it.
    const Vec3 cell = glm::floor(x);
    // Beyond 2^62 (or NaN) a lattice index does not fit an integer: no noise there.
    if (!isFinite(cell) || !(maxAbsComponent(cell) < 0x1p62)) return 0.0;
    const Vec3 f = x - cell;
    const auto i = static_cast<std::int64_t>(cell.x), j = static_cast<std::int64_t>(cell.y),
               k = static_cast<std::int64_t>(cell.z);
    // Each corner's gradient dotted with the offset from that corner.
    double corner[2][2][2];
    for (int a = 0; a < 2; ++a)
        for (int b = 0; b < 2; ++b)
            for (int c = 0; c < 2; ++c)
                corner[a][b][c] =
                    gradientDot(hashLattice(i + a, j + b, k + c, seed), f - Vec3(a, b, c));
    // Blend the eight with the faded weights.
    const Vec3 w(perlinFade(f.x), perlinFade(f.y), perlinFade(f.z));
    const double y0 = lerp(w.y, lerp(w.x, corner[0][0][0], corner[1][0][0]),
                           lerp(w.x, corner[0][1][0], corner[1][1][0]));
    const double y1 = lerp(w.y, lerp(w.x, corner[0][0][1], corner[1][0][1]),
                           lerp(w.x, corner[0][1][1], corner[1][1][1]));
    return lerp(w.z, y0, y1);
}

double fractalNoise(const Vec3& x, int octaves, std::uint32_t seed) {
    double sum = 0.0, amplitude = 1.0, total = 0.0, frequency = 1.0;
    for (int o = 0; o < octaves; ++o) {
        sum += amplitude * gradientNoise(frequency * x, seed + static_cast<std::uint32_t>(o));
        total += amplitude;
        amplitude *= 0.5;
        frequency *= 2.0;
    }
    return total > 0.0 ? sum / total : 0.0;
}

}  // namespace rb
