#include "tone_map/srgb.h"

#include <algorithm>
#include <cmath>

namespace rb {

// [srgb-encode]
double srgbEncode(double linear) {
    // [exercise-srgb-encode]
    // Exercise 12.4, sRGB encoding: read ch12-srgb.
    // Blank: return linear;
    // Source: IEC 61966-2-1 (sRGB): a straight segment near black, where a pure power would
    // have an infinite slope, then a power of 1/2.4 offset to meet it.
    const double c = std::clamp(linear, 0.0, 1.0);
    if (c <= 0.0031308) return 12.92 * c;
    return 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
    // [exercise-srgb-encode]
}
// [srgb-encode]

}  // namespace rb
