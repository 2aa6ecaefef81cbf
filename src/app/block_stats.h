/// \file
/// The statistical golden check: does a Monte Carlo render estimate the same image as the
/// reference, whatever random numbers it drew? Block means of the render are compared with the
/// mean and spread of the same blocks over several reference renders (different seeds).
#pragma once

#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

#include "app/image_compare.h"

namespace rb::golden {

/// For groups of g × g blocks of `block` × `block` pixels (g = 1, 2, 4, 8), per group and per
/// channel: the mean of the group's mean over the reference renders, and the standard deviation
/// of one render's group mean, measured across the renders (not pooled from the pixels: a
/// photon map's pixels share photons, so their noise is correlated over a few pixels).
struct BlockStats {
    int w = 0, h = 0;  ///< Image size.
    int block = 8;     ///< Block side in pixels (the last row and column of blocks may be smaller).
    int renders = 0;   ///< How many reference renders the statistics come from.
    /// The group sizes, in blocks a side.
    static constexpr int kGroups[4] = {1, 2, 4, 8};
    std::vector<double> mean[4];   ///< Per group size: 3 per group, groups row by row.
    std::vector<double> sigma[4];  ///< Per group size: 3 per group, one render's spread.

    int blocksX() const { return (w + block - 1) / block; }  ///< Blocks per row.
    int blocksY() const { return (h + block - 1) / block; }  ///< Rows of blocks.
    int blocks() const { return blocksX() * blocksY(); }     ///< Blocks in all.
    /// Groups of g blocks a side per row, and rows of them.
    int groupsX(int g) const { return (blocksX() + g - 1) / g; }
    int groupsY(int g) const { return (blocksY() + g - 1) / g; }
};

/// The statistics of `renders` (at least 4, all the same size). Throws std::runtime_error.
BlockStats block_stats(const std::vector<Image>& renders, int block = 8);

/// Writes / reads a statistics file (a text header, then for each group size a "groups G"
/// line and "mean sigma" × 3 per group).
void save_block_stats(const std::filesystem::path& path, const BlockStats& stats);
BlockStats load_block_stats(const std::filesystem::path& path);
/// Reads a statistics file's text from `in`; `source` names it in the message of the
/// std::runtime_error thrown for text that is not one.
BlockStats parse_block_stats(std::istream& in, const std::string& source);

/// How the statistical check decides.
struct StatisticalLimits {
    /// The render's pixels may vary up to this many times as much as the reference's (another
    /// correct stratification may be noisier) without failing.
    double variance_ratio = 2.0;
    /// A block's mean is "off" when a channel's |z| exceeds the two-sided normal quantile of
    /// this probability divided by 3 (one per channel).
    double block_alpha = 1e-3;
    /// The false-alarm rate of each of the five tests (off groups of 1, 2, 4 and 8 blocks a
    /// side, and Σ z² of the grey block means): an unbiased render with at most
    /// variance_ratio times the variance fails with probability at most 5 × this.
    double alpha = 1e-3;
    /// A floor for a block mean's standard deviation: a quarter of an 8-bit level over a block
    /// (where the references agree exactly, the render may still round differently).
    double sigma_floor = 0.25 / 255.0 / 8.0;
};

/// The statistical check's result.
struct StatisticalComparison {
    bool passed = false;
    int group = 1;            ///< The group size (blocks a side) reported below: the worst.
    int blocks = 0;           ///< Groups of that size compared.
    int off_blocks = 0;       ///< Groups with a channel beyond the block threshold.
    int allowed_off = 0;      ///< Most off groups an unbiased render shows (at alpha).
    double chi2 = 0.0;        ///< Σ z² of the blocks' grey means.
    double chi2_limit = 0.0;  ///< Its upper quantile at alpha (Wilson–Hilferty).
    double mean_shift = 0.0;  ///< The mean of the grey z: a sign of a global bias.
    std::string reason;       ///< Set when the check could not run (size mismatch).
};

/// Compares one render with the reference statistics.
StatisticalComparison compare_statistically(const BlockStats& stats, const Image& actual,
                                            const StatisticalLimits& limits = {});

/// The verdict in words, e.g. "the same estimate as the reference (0 of 576 blocks off,
/// allowed 4; chi-square of the block means 301 <= 666; mean shift 0.01 sigma)".
std::string describe(const StatisticalComparison& c);

/// The standard normal quantile Φ⁻¹(p), 0 < p < 1 (bisection on std::erfc; for limits only).
double normal_quantile(double p);

/// The smallest c with P(Binomial(n, p) > c) <= alpha.
int binomial_upper(int n, double p, double alpha);

}  // namespace rb::golden
