/// \file
/// sRGB encoding: linear light in [0, 1] to the values a display expects.
#pragma once

namespace rb {

/// The sRGB transfer function (the "gamma" of an sRGB display) of a linear value in [0, 1];
/// values outside are clamped first.
double srgbEncode(double linear);

}  // namespace rb
