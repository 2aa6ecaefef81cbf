/// \file
/// Rendering to an error, not a sample count (--target-error E). Two stages, after Stein:
/// every pixel first takes a few pilot samples, which measure how much its samples spread and
/// are then set aside; from the spreads, each pixel is given its own count of fresh samples,
/// more where the spread is wide, so that the image's expected RMS error is E; the pixel is
/// the mean of its fresh samples alone. Because a pixel's count is fixed before its fresh
/// samples are drawn, their mean is unbiased and their spread an unbiased estimate of the
/// error, which is what --stats reports.
/// Source: C. Stein, "A two-sample test for a linear hypothesis whose power is independent of
/// the variance", Annals of Mathematical Statistics 16(3), 1945 (the two stages); J. Neyman,
/// "On the two different aspects of the representative method", JRSS 97(4), 1934 (counts in
/// proportion to the spread minimise the total variance for a given number of samples).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "core/image.h"
#include "core/vec.h"

namespace rb {

/// What --target-error asks of the image.
struct TargetError {
    double error = 0.0;     ///< E: the image's RMS error, in linear units (1 = white); 0: off.
    int minSamples = 8;     ///< The floor: pilot samples, and the fewest fresh ones a pixel takes.
    int maxSamples = 4096;  ///< The ceiling: the most fresh samples a pixel takes.
    /// Whether the render samples to an error at all.
    bool on() const { return error > 0.0; }
};

/// The floor and ceiling allowed (--min-spp, --max-spp). Two samples are the fewest that
/// give a spread; the ceiling keeps a pixel's count in 32 bits with room to spare.
inline constexpr int kTargetMinSamples = 2;
inline constexpr int kTargetMaxSamples = 1 << 20;

/// Refuse a target that cannot work: E not a positive finite number, a floor or ceiling
/// outside [kTargetMinSamples, kTargetMaxSamples], or a ceiling below the floor. `where`
/// names the source (the option or the scene line). Throws InputError.
void checkTargetError(const TargetError& target, const std::string& where);

/// Running mean and variance of a pixel's samples, one per channel, by Welford's update, which
/// loses no precision to a large mean.
/// Source: B. P. Welford, "Note on a method for calculating corrected sums of squares and
/// products", Technometrics 4(3), 1962.
class RunningMoments {
  public:
    /// Count one more sample.
    void add(const Colour& x);
    /// Samples so far.
    int count() const { return n_; }
    /// Their mean.
    Colour mean() const { return mean_; }
    /// The unbiased sample variance s², per channel (0 below two samples).
    Colour variance() const;
    /// s² averaged over the three channels: the spread of one sample.
    double channelVariance() const;

  private:
    int n_ = 0;
    Colour mean_{0.0};
    Colour m2_{0.0};  // sum of squared deviations from the running mean
};

/// Stage 2: each pixel's count of fresh samples, from the pilot's channel variances s²
/// (row-major, width × height). A pixel is planned with the larger of its own s² and the mean
/// of its 3 × 3 neighbourhood's (a pilot of a few samples misses rare paths; its neighbours
/// may not). Counts are k·s, clamped to [floor, ceiling], with the smallest k whose predicted
/// RMS error, the root of the mean of s²/n, is at most E (or the ceiling everywhere).
/// Every step is a pure function of the pilot, in a fixed order: the same counts on any
/// thread count or rank.
std::vector<std::uint32_t> planSamples(const std::vector<float>& pilotVariance, int width,
                                       int height, const TargetError& target);

/// What a render to a target error spent and estimated, per pixel (row-major).
struct SampleMap {
    int width = 0, height = 0;
    int pilot = 0;                       ///< Pilot samples every pixel took first.
    std::vector<std::uint32_t> samples;  ///< Fresh samples: the pixel's estimate.
    std::vector<float> meanVariance;     ///< The estimated variance of the pixel's mean,
                                         ///< averaged over channels.

    SampleMap() = default;
    SampleMap(int w, int h, int pilotSamples)
        : width(w),
          height(h),
          pilot(pilotSamples),
          samples(static_cast<std::size_t>(w) * h, 0),
          meanVariance(static_cast<std::size_t>(w) * h, 0.0f) {}
    /// Record that pixel (x, y) took `count` fresh samples, with `varianceOfMean`.
    void record(int x, int y, int count, double varianceOfMean);
    /// The pixels recorded: every pixel of a whole render, fewer when --resume took some from
    /// a journal (a pixel's fresh samples are at least the floor, so 0 means not recorded).
    std::size_t recordedPixels() const;
    /// Mean samples per recorded pixel, pilot included.
    double meanSamples() const;
    /// The most samples any pixel took, pilot included.
    std::uint32_t maxSamples() const;
    /// The estimated RMS error of the recorded pixels: the root of the mean, over them, of each
    /// pixel's estimated variance of its mean. Unbiased for the mean squared error, since each
    /// count was fixed before its samples were drawn.
    double rmsError() const;

    /// The recorded pixels as bytes, for another process's map (under MPI each rank records
    /// the pixels of its own tiles).
    std::vector<std::byte> packRecorded() const;
    /// Record the pixels another map packed (packRecorded), over this map's.
    void recordPacked(std::span<const std::byte> packed);
};

/// The samples each pixel of `map` took (pilot included) as a heat map: black at 0, through
/// blue, red and yellow to white at the most any pixel took (or 8 pilots, if more), on a
/// square-root scale.
Image sampleHeatMap(const SampleMap& map);

}  // namespace rb
