/// \file
/// Doubles rounded to float in a chosen direction, for bounds that must stay bounds.
#pragma once

#include <cstdint>
#include <cstring>

namespace rb {

/// The smallest float not below x (x rounded up to float). NaN stays NaN.
[[gnu::always_inline]] inline float roundUpToFloat(double x) {
    float f = static_cast<float>(x);
    if (static_cast<double>(f) < x) {
        // One float step towards +∞: the bit pattern moves one up for f > 0, one down for
        // f < 0; from ±0 the step is the smallest positive subnormal.
        std::uint32_t bits;
        std::memcpy(&bits, &f, sizeof bits);
        bits = f > 0.0f ? bits + 1 : f < 0.0f ? bits - 1 : 1u;
        std::memcpy(&f, &bits, sizeof f);
    }
    return f;
}
/// The largest float not above x (x rounded down to float).
[[gnu::always_inline]] inline float roundDownToFloat(double x) {
    return -roundUpToFloat(-x);
}

}  // namespace rb
