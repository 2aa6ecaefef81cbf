#include "tone_map/reinhard.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rb {

double luminance(const Colour& c) {
    // Source: ITU-R BT.709, the primaries of linear sRGB.
    return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
}

// [log-average]
double logAverageLuminance(const std::vector<double>& values, double delta) {
    // [exercise-log-average]
    // Exercise 12.1, the log-average luminance: read ch12-key.
    // Blank: return 1.0;
    if (values.empty()) return delta;
    // Average the logarithms (a sum in a fixed order, so any thread count gives the same key);
    // δ keeps a black pixel from contributing log(0) = −∞.
    double sumLog = 0.0;
    for (const double Lw : values) sumLog += std::log(delta + Lw);
    return std::exp(sumLog / static_cast<double>(values.size()));
    // [exercise-log-average]
}
// [log-average]

// [global-operator]
double reinhardGlobal(double L, double Lwhite) {
    // [exercise-global-operator]
    // Exercise 12.2, the global operator with L_white: read ch12-global.
    // Blank: return std::min(L, 1.0);
    // L / (1 + L) compresses every luminance into [0, 1); the factor (1 + L / L_white²) lifts
    // the top of the curve so that L_white itself lands on 1. An infinite L_white drops it.
    const double burn = std::isinf(Lwhite) ? 1.0 : 1.0 + L / (Lwhite * Lwhite);
    return L * burn / (1.0 + L);
    // [exercise-global-operator]
}
// [global-operator]

double localScale(int i) {
    // Source: Reinhard et al. 2002, section 5: "a scale ratio of 1.6 between successive
    // scales", starting at one pixel.
    return std::pow(1.6, i);
}

namespace {

// [blur-line]
/// One line of a separable blur: row `line` of the width-wide image `in` (alongRows), or its
/// column `line`, into `out`; the line has `length` pixels and `weight` holds the taps 0..radius.
/// A template, so each direction's index arithmetic compiles without a test per tap.
template <bool alongRows>
void blurLine(const std::vector<double>& in, std::vector<double>& out, int line, int width,
              int length, const std::vector<double>& weight) {
    const int radius = static_cast<int>(weight.size()) - 1;
    for (int i = 0; i < length; ++i) {
        double sum = 0.0, total = 0.0;
        for (int k = std::max(-radius, -i); k <= std::min(radius, length - 1 - i); ++k) {
            const int j = i + k;
            const std::size_t index = alongRows ? static_cast<std::size_t>(line) * width + j
                                                : static_cast<std::size_t>(j) * width + line;
            const double w = weight[std::abs(k)];
            sum += w * in[index];
            total += w;
        }
        const std::size_t index = alongRows ? static_cast<std::size_t>(line) * width + i
                                            : static_cast<std::size_t>(i) * width + line;
        out[index] = sum / total;
    }
}
// [blur-line]

}  // namespace

// [gaussian-blur]
std::vector<double> gaussianBlur(const std::vector<double>& L, int width, int height,
                                 double alphaS) {
    // The profile exp(−(x² + y²)/(αs)²) is a product of two 1D profiles, so blur the rows, then
    // the columns. It is a Gaussian with σ = αs/√2; three σ hold all but 0.3% of the weight.
    const int radius = std::max(1, static_cast<int>(std::ceil(3.0 * alphaS / std::sqrt(2.0))));
    std::vector<double> weight(radius + 1);
    for (int k = 0; k <= radius; ++k) weight[k] = std::exp(-(k * k) / (alphaS * alphaS));
    // Each output pixel sums the taps that fall inside the image and divides by their weight:
    // near a border the kernel shrinks instead of reading black. The lines are independent,
    // so threads share them out; each pixel's sum runs in the same order on any thread.
    const auto pass = [&](const std::vector<double>& in, bool alongRows) {
        std::vector<double> out(in.size());
        const int length = alongRows ? width : height;
        const int lines = alongRows ? height : width;
#pragma omp parallel for schedule(static)
        for (int line = 0; line < lines; ++line) {
            if (alongRows)
                blurLine<true>(in, out, line, width, length, weight);
            else
                blurLine<false>(in, out, line, width, length, weight);
        }
        return out;
    };
    return pass(pass(L, true), false);
}
// [gaussian-blur]

// [scale-selection]
std::vector<double> localAdaptation(const std::vector<double>& L, int width, int height,
                                    const LocalOperatorSettings& settings,
                                    std::vector<int>* scaleIndex) {
    // Source: Reinhard et al. 2002, section 5: α1 = 1/(2√2), α2 = 1.6 α1. Since α2 s_i equals
    // α1 s_{i+1}, the surround of scale i is the centre of scale i + 1: one blur per scale.
    const double alpha1 = 1.0 / (2.0 * std::sqrt(2.0));
    const std::size_t n = L.size();
    std::vector<double> centre = gaussianBlur(L, width, height, alpha1 * localScale(0));
    std::vector<double> adaptation = centre;  // V1 at the smallest scale, until a larger fits
    std::vector<char> settled(n, 0);
    if (scaleIndex) scaleIndex->assign(n, 0);
    for (int i = 0; i < settings.scales; ++i) {
        const double s = localScale(i);
        const std::vector<double> surround =
            gaussianBlur(L, width, height, alpha1 * localScale(i + 1));
        // [exercise-scale-selection]
        // Exercise 12.3, the local scale selection: read ch12-local.
        // Blank: break;
        // V = (V1 − V2) / (2^φ a / s² + V1): the centre-surround difference, normalised so that
        // it reads the same in bright and dark regions. Grow the neighbourhood while it stays
        // below ε; the first scale where it does not has reached an edge.
        const double normaliser = std::pow(2.0, settings.sharpness) * settings.key / (s * s);
        for (std::size_t p = 0; p < n; ++p) {
            if (settled[p]) continue;
            const double V = (centre[p] - surround[p]) / (normaliser + centre[p]);
            if (std::abs(V) < settings.threshold) {
                adaptation[p] = centre[p];
                if (scaleIndex) (*scaleIndex)[p] = i;
            } else
                settled[p] = 1;
        }
        // [exercise-scale-selection]
        centre = surround;
    }
    return adaptation;
}
// [scale-selection]

// [local-operator]
std::vector<double> reinhardLocal(const std::vector<double>& L, int width, int height,
                                  const LocalOperatorSettings& settings) {
    const std::vector<double> V1 = localAdaptation(L, width, height, settings);
    std::vector<double> Ld(L.size());
    // A pixel darker than its surround is divided by less than its own 1 + L (dodged, kept
    // bright); one brighter than its surround by more (burnt, kept from white).
    for (std::size_t p = 0; p < L.size(); ++p) Ld[p] = L[p] / (1.0 + V1[p]);
    return Ld;
}
// [local-operator]

}  // namespace rb
