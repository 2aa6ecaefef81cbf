/// \file
/// Gradient noise: a smooth, repeatable random function of 3D position (Perlin's noise with
/// hashed gradients instead of a permutation table).
#pragma once

#include <cstdint>

#include "core/vec.h"

namespace rb {

/// Perlin gradient noise at x: 0 at every integer lattice point, smooth (C2) between them, in
/// about [-1, 1]. `seed` picks one of 2^32 independent noise functions. 0 where a coordinate
/// is beyond ±2^62 or NaN (no lattice index fits there).
/// Source: K. Perlin, "Improving noise", SIGGRAPH 2002 (quintic fade, the 12 cube-edge
/// gradients); the gradients are chosen by hashing the lattice point, so no table is needed.
double gradientNoise(const Vec3& x, std::uint32_t seed);

/// Fractal sum of `octaves` noise layers, each at twice the frequency and half the amplitude
/// of the one before (fBm), normalised so its amplitude stays about 1.
double fractalNoise(const Vec3& x, int octaves, std::uint32_t seed);

}  // namespace rb
