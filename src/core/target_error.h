/// \file
/// Rendering to an error, not a sample count (--target-error E). Two stages, after Stein:
/// every pixel first takes a pilot in three groups. The first, the planning group, measures
/// how much the pixel's samples spread, and is then set aside. The other two are kept: the
/// pixel is the mean of them and its fresh samples, and their spread plans its neighbours.
/// From its own planning group's spread and its neighbours' kept ones, each pixel is given its
/// count of fresh samples, more where the spread is wide, so that the image's expected RMS
/// error is E. Because a pixel's count is fixed by samples that are not part of it, the mean
/// of the ones that are is unbiased, and their spread an unbiased estimate of its error, which
/// is what --stats reports.
/// Source: C. Stein, "A two-sample test for a linear hypothesis whose power is independent of
/// the variance", Annals of Mathematical Statistics 16(3), 1945 (the two stages); J. Neyman,
/// "On the two different aspects of the representative method", JRSS 97(4), 1934 (counts in
/// proportion to the spread minimise the total variance for a given number of samples; in
/// proportion to the spread over the root of a sample's cost, for a given cost).
#pragma once

#include <algorithm>
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
    int minSamples = 8;     ///< The floor: the kept pilot (made even; fresh samples come too).
    int maxSamples = 4096;  ///< The ceiling: the most fresh samples a pixel takes.
    /// The pilot's planning group, set aside once it has planned: half the floor, at least 2.
    int planningSamples() const { return std::max(2, minSamples / 2); }
    /// The pilot's kept samples: the floor, made even (they come in two equal groups).
    int keptPilotSamples() const { return minSamples + minSamples % 2; }
    /// Every pilot sample, set aside or kept.
    int pilotSamples() const { return planningSamples() + keptPilotSamples(); }
    /// The fewest fresh samples: two, one a group (the kept pilot already makes the floor).
    int freshFloor() const { return 2; }
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

/// Stage 2: each pixel's count of fresh samples, from two channel variances s² per pixel
/// (row-major, width × height): its planning group's, `planning`, set aside, and its kept
/// pilot's, `kept`. A pixel is planned from its 3 × 3 block's mean s², its own planning s²
/// with its 8 neighbours' kept s², or from its own planning s² if that is larger: a few
/// samples miss rare paths, and its neighbours often see them. No s² of its own kept samples
/// plans it. With q kept pilot samples, q + n = k·w, w the root of that planning variance and n
/// clamped to [fresh floor, ceiling], with the smallest k whose predicted RMS error, the root
/// of the mean of s²/(q + n) over the pixels' kept s², is at most E (or the ceiling
/// everywhere). The prediction uses the kept s², of twice as many samples as the planning
/// group's and independent of them: predicted from the planning s² that also set the counts, a
/// pixel whose few planning samples happened to spread little would take few samples and be
/// counted as quiet, and the error would come out above E (on chapter 17's fog, by 40%). Every
/// step is a pure function of the pilot, in a fixed order: the same counts on any thread count
/// or rank.
///
/// With `cost` (rays a sample, per pixel, of the planning group and of the kept pilot), a
/// sample's price enters too: w is the root of that variance over the pixel's price, the mean
/// over its 3 × 3 block of its own planning group's rays a sample and its neighbours' kept
/// ones, so that a pixel twice as dear takes 1/√2 as many samples for its spread (Neyman's
/// allocation with costs, which minimises the rays for a given error). Its own kept samples
/// set no price either.
struct PilotCost {
    std::vector<float> planning;  ///< Rays a sample of each pixel's planning group.
    std::vector<float> kept;      ///< Rays a sample of each pixel's kept pilot.
};
std::vector<std::uint32_t> planSamples(const std::vector<float>& planning,
                                       const std::vector<float>& kept, int width, int height,
                                       const TargetError& target, const PilotCost* cost = nullptr);

/// One pixel's estimate: the mean of its samples and the estimated variance of that mean,
/// averaged over the channels.
struct PixelEstimate {
    Colour mean{0.0};
    double varianceOfMean = 0.0;
};

/// Stage 3's pixel: the mean of all its kept samples, `pilotCount` kept pilot samples (their
/// estimate `pilot`) and `freshCount` fresh ones (`fresh`), each weighed by its count. The
/// variance of that mean is (p²·u + n²·v)/(p + n)², from the pilot's u and the fresh samples'
/// v.
PixelEstimate withPilot(const PixelEstimate& pilot, int pilotCount, const PixelEstimate& fresh,
                        int freshCount);

/// What a render to a target error spent and estimated, per pixel (row-major).
struct SampleMap {
    int width = 0, height = 0;
    int pilot = 0;                       ///< Pilot samples every pixel took first, all groups.
    std::vector<std::uint32_t> samples;  ///< Fresh samples, after the pilot's.
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
    /// count was fixed by planning groups that are set aside, not by the samples it averages.
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
