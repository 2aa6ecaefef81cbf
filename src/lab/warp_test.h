/// \file
/// The sampling lab: draw a sampler's points, bin them on its domain, integrate the expected
/// count of every bin from the pdf the code states, test the two with chi-square, and draw
/// both and their difference (rt's `--warptest` option, in the spirit of Nori's warptest).
#pragma once

#include <cstdint>
#include <map>
#include <ostream>
#include <string>
#include <vector>

#include "core/feature.h"
#include "lab/chi_square.h"
#include "lab/warp.h"

namespace rb {

/// How a sampler is run through the lab.
struct WarpRunSettings {
    std::uint64_t samples = 200000;  ///< Points drawn (a grid sampler may draw a few more).
    int xBins = 0, yBins = 0;        ///< Bins per axis (0: the lab's default, 24 × 24).
    std::uint64_t seed = 1;          ///< The random streams' seed.
};

/// What one run of the lab found.
struct WarpRun {
    std::string name, title, caption;
    int chapter = 0;
    std::string exercise;
    WarpDomain domain;
    int xBins = 0, yBins = 0;
    std::uint64_t samples = 0;     ///< Points drawn.
    std::vector<double> observed;  ///< Per bin, row y major: bin (i, j) is [j·xBins + i].
    std::vector<double> expected;  ///< Samples × ∫ pdf over the bin.
    double outsideObserved = 0.0;  ///< Points off the domain (or NaN).
    double outsideExpected = 0.0;  ///< Samples × (1 − ∫ pdf over the domain).
    ChiSquare test;                ///< Over the bins and the outside cell.
};

/// The samplers of the built chapters, in chapter order.
std::vector<Warp> builtWarps(const std::vector<Feature>& built);

/// Run `warp` with parameter values `values` (missing ones take their defaults); throws
/// InputError for an unknown parameter or a value out of range.
WarpRun runWarp(const Warp& warp, const std::map<std::string, double>& values,
                const WarpRunSettings& settings);

/// ∫∫ f over [x0, x1] × [y0, y1], by adaptive Simpson cubature (exact for cubics; refined near
/// edges of the support, where f jumps).
double integrate2D(const std::function<double(const Vec2&)>& f, double x0, double x1, double y0,
                   double y1);

/// Write the run's figure as SVG: observed and expected histograms on one colour scale, their
/// standardised difference, and the verdict at level alpha. Throws InputError if it cannot.
void writeWarpFigure(const WarpRun& run, double alpha, const std::string& path);

/// The lab's command line, rt's `--warptest` option (args: what follows it). Returns the
/// exit code: 0 when every sampler run passes, 1 when one fails or the input is bad.
int warpTestCommand(const std::vector<std::string>& args, const std::vector<Feature>& built,
                    std::ostream& out, std::ostream& err);

}  // namespace rb
