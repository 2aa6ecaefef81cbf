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

/// Perlin's quintic fade 6t^5 − 15t^4 + 10t^3, the blend weight across a cell: 0 and 1 at
/// the ends with zero first and second derivatives, so the noise is smooth across cell borders.
/// It rises monotonically on [0, 1].
double perlinFade(double t);

/// The gradient gradientNoise gives lattice point (i, j, k): one of the 12 cube-edge
/// directions, such as (1, −1, 0). Chapter 17 bounds the noise over a box with it.
Vec3 latticeGradient(std::int64_t i, std::int64_t j, std::int64_t k, std::uint32_t seed);

/// Fractal sum of `octaves` noise layers, each at twice the frequency and half the amplitude
/// of the one before (fBm), normalised so its amplitude stays about 1.
double fractalNoise(const Vec3& x, int octaves, std::uint32_t seed);

}  // namespace rb
