/// \file
/// Pearson's chi-square goodness-of-fit test, the one copy that the chapter tests and the
/// sampling lab (rt's `--warptest` option) share: pooling of cells expecting fewer than 5 samples,
/// the statistic, its p-value through the regularised upper incomplete gamma function, and
/// Šidák's correction for several tests at once.
///
/// It lives in src/lab/ rather than in tests/ because `rt` itself runs it (the lab is part of
/// every chapter binary), and rather than in src/core/ because the renderer never needs it:
/// src/lab/ is the one place for what a reader runs to *check* a chapter, not to render it.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace rb {

/// Q(a, x) = Γ(a, x) / Γ(a), the regularised upper incomplete gamma function.
/// Source: Numerical Recipes, 3rd ed., §6.2: the series for x < a + 1, Lentz's continued
/// fraction otherwise.
inline double upperGammaQ(double a, double x) {
    if (x <= 0.0) return 1.0;
    const double prefix = std::exp(a * std::log(x) - x - std::lgamma(a));
    if (x < a + 1.0) {
        double term = 1.0 / a, sum = term;
        for (int k = 1; k < 100000 && std::abs(term) > 1e-17 * std::abs(sum); ++k) {
            term *= x / (a + k);
            sum += term;
        }
        return std::max(0.0, 1.0 - prefix * sum);
    }
    const double tiny = 1e-300;
    double b = x + 1.0 - a, c = 1.0 / tiny, d = 1.0 / b, h = d;
    for (int i = 1; i < 100000; ++i) {
        const double an = -i * (i - a);
        b += 2.0;
        d = an * d + b;
        if (std::abs(d) < tiny) d = tiny;
        c = b + an / c;
        if (std::abs(c) < tiny) c = tiny;
        d = 1.0 / d;
        const double delta = d * c;
        h *= delta;
        if (std::abs(delta - 1.0) < 1e-16) break;
    }
    return prefix * h;
}

/// P(χ²_dof > x): the p-value of a chi-square statistic with dof degrees of freedom.
inline double chiSquareTail(double x, int dof) {
    return upperGammaQ(0.5 * dof, 0.5 * x);
}

/// Šidák's per-test level for k independent tests at family-wise level alpha.
/// Source: Šidák, "Rectangular confidence regions for the means of multivariate normal
/// distributions", JASA 62 (1967).
inline double sidak(double alpha, int k) {
    return 1.0 - std::pow(1.0 - alpha, 1.0 / k);
}

/// The result of a chi-square goodness-of-fit test.
struct ChiSquare {
    double statistic = 0.0;  ///< Σ (observed − expected)² / expected over the kept cells.
    int dof = 0;             ///< Kept cells − 1.
    double pValue = 1.0;     ///< P(χ²_dof > statistic).
    int pooledCells = 0;     ///< Cells that expected fewer than 5 samples, pooled into one.
};

/// Chi-square test of observed against expected counts. Cells expecting fewer than 5 are
/// pooled into one (merged with the smallest remaining cell if the pool still expects < 5).
/// A sample in a cell expecting nothing at all fails the test outright (p = 0).
inline ChiSquare chiSquareTest(const std::vector<double>& observed,
                               const std::vector<double>& expected) {
    ChiSquare result;
    std::vector<std::pair<double, double>> cells;  // (observed, expected)
    double poolObserved = 0.0, poolExpected = 0.0;
    for (size_t i = 0; i < observed.size(); ++i) {
        if (expected[i] <= 0.0 && observed[i] > 0.0) {
            result.pValue = 0.0;
            result.statistic = std::numeric_limits<double>::infinity();
            return result;
        }
        if (expected[i] < 5.0) {
            poolObserved += observed[i];
            poolExpected += expected[i];
            ++result.pooledCells;
        } else {
            cells.push_back({observed[i], expected[i]});
        }
    }
    if (poolExpected > 0.0) {
        if (poolExpected < 5.0 && !cells.empty()) {
            auto smallest = std::min_element(cells.begin(), cells.end(),
                                             [](auto& a, auto& b) { return a.second < b.second; });
            smallest->first += poolObserved;
            smallest->second += poolExpected;
        } else {
            cells.push_back({poolObserved, poolExpected});
        }
    }
    for (const auto& [o, e] : cells) result.statistic += (o - e) * (o - e) / e;
    result.dof = static_cast<int>(cells.size()) - 1;
    // One cell (or none) leaves nothing to test: the counts can only agree.
    result.pValue = result.dof > 0 ? chiSquareTail(result.statistic, result.dof) : 1.0;
    return result;
}

}  // namespace rb
