/// \file
/// Doubles rounded to float in a chosen direction, for bounds that must stay bounds, and the
/// next double up.
#pragma once

#include <cstdint>
#include <cstring>

namespace rb {

/// The smallest float not below x (x rounded up to float). NaN stays NaN. Branch-free: it runs
/// several times per ray.
[[gnu::always_inline]] inline float roundUpToFloat(double x) {
    const float f = static_cast<float>(x);
    // One float step towards +∞: the bit pattern moves one up for f > 0, one down for f < 0;
    // from ±0 the step is the smallest positive subnormal (bit pattern 1).
    std::uint32_t bits;
    std::memcpy(&bits, &f, sizeof bits);
    const std::uint32_t magnitude = bits & 0x7FFFFFFFu;
    const std::uint32_t stepped = magnitude == 0 ? 1u : (bits >> 31) ? bits - 1 : bits + 1;
    const std::uint32_t result = static_cast<double>(f) < x ? stepped : bits;
    float out;
    std::memcpy(&out, &result, sizeof out);
    return out;
}
/// The next double above t, for t > 0 and finite (a hit distance): one step of the bit pattern.
/// A distance limit of nextUp(t) lets a test accept a hit at exactly t.
[[gnu::always_inline]] inline double nextUp(double t) {
    std::uint64_t bits;
    std::memcpy(&bits, &t, sizeof bits);
    ++bits;
    std::memcpy(&t, &bits, sizeof t);
    return t;
}

/// The largest float not above x (x rounded down to float).
[[gnu::always_inline]] inline float roundDownToFloat(double x) {
    return -roundUpToFloat(-x);
}

}  // namespace rb
