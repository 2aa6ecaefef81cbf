/// \file
/// Reinhard et al. 2002, "Photographic tone reproduction for digital images": the key of an
/// image (its log-average luminance), the global operator with L_white, and the local
/// dodge-and-burn operator that picks a neighbourhood per pixel by a centre-surround test.
#pragma once

#include <vector>

#include "core/image.h"

namespace rb {

/// The luminance of a linear sRGB (Rec. 709) colour.
/// Source: ITU-R BT.709: Y = 0.2126 R + 0.7152 G + 0.0722 B.
double luminance(const Colour& c);

/// The δ of the log average, which keeps a black pixel from taking log(0) = −∞.
inline constexpr double kLogAverageDelta = 1e-4;

/// The log-average ("geometric mean") luminance of `values`:
/// exp((1/N) Σ log(δ + L_w)). Reinhard's paper takes it as the image's key.
double logAverageLuminance(const std::vector<double>& values, double delta = kLogAverageDelta);

/// The global operator: L_d = L (1 + L / L_white²) / (1 + L). L_white is the smallest scaled
/// luminance that becomes white; an infinite L_white gives L / (1 + L).
double reinhardGlobal(double L, double Lwhite);

/// The settings of the local operator (the paper's defaults, section 5).
struct LocalOperatorSettings {
    double key = 0.18;        ///< a: the key the luminances were scaled to.
    double sharpness = 8.0;   ///< φ: how sharp an edge the normaliser tolerates.
    double threshold = 0.05;  ///< ε: the centre-surround difference that ends the search.
    int scales = 8;           ///< How many scales s_i = 1.6^i (i = 0 … scales − 1) to try.
};

/// The scale s_i = 1.6^i of the local operator's i-th neighbourhood, in pixels.
double localScale(int i);

/// The blur of the local operator: `L` (width × height, row-major) convolved with the paper's
/// Gaussian profile R(x, y, s) = exp(−(x² + y²) / (α s)²) / (π (α s)²), with the weights
/// renormalised over the pixels inside the image (so a constant image stays constant).
std::vector<double> gaussianBlur(const std::vector<double>& L, int width, int height,
                                 double alphaS);

/// The local adaptation luminance V1(x, y, s_m) of each pixel of the scaled luminances `L`:
/// the blur at the largest scale s_m whose centre-surround difference |V(s_m)| stays below ε.
/// When `scaleIndex` is given it receives m for each pixel.
std::vector<double> localAdaptation(const std::vector<double>& L, int width, int height,
                                    const LocalOperatorSettings& settings,
                                    std::vector<int>* scaleIndex = nullptr);

/// The local operator: L_d = L / (1 + V1(x, y, s_m)).
std::vector<double> reinhardLocal(const std::vector<double>& L, int width, int height,
                                  const LocalOperatorSettings& settings);

}  // namespace rb
