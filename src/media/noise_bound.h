/// \file
/// NoiseRange: bounds of chapter 11's gradient noise over a box, so a procedural smoke gets a
/// majorant grid and tracking skips its thin parts (chapter 17).
#pragma once

#include <cstdint>

#include "core/vec.h"

namespace rb {

/// An interval of values [lo, hi].
struct NoiseRange {
    double lo, hi;
};

/// An interval that holds gradientNoise(x, seed) for every x in the box [lo, hi] of noise
/// space. Interval arithmetic on the noise's own formula, so it is never too narrow; it is
/// tight for boxes small beside a lattice cell and [−2, 2] for boxes that span many.
NoiseRange gradientNoiseRange(const Vec3& lo, const Vec3& hi, std::uint32_t seed);

/// An interval that holds fractalNoise(x, octaves, seed) for every x in the box [lo, hi]: the
/// octaves' intervals, weighted as fractalNoise weights the octaves.
NoiseRange fractalNoiseRange(const Vec3& lo, const Vec3& hi, int octaves, std::uint32_t seed);

}  // namespace rb
