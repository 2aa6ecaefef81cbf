#include "core/target_error.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "core/error.h"

namespace rb {

void checkTargetError(const TargetError& target, const std::string& where) {
    const auto range = [](int lo, int hi) {
        return "a whole number from " + std::to_string(lo) + " to " + std::to_string(hi);
    };
    if (!(target.error > 0.0) || !std::isfinite(target.error))
        throw InputError(where +
                         ": the target error must be a number above 0 (for example "
                         "0.02, a fiftieth of white), got " +
                         std::to_string(target.error));
    if (target.minSamples < kTargetMinSamples || target.minSamples > kTargetMaxSamples)
        throw InputError(where + ": the floor (--min-spp) must be " +
                         range(kTargetMinSamples, kTargetMaxSamples) + ", got " +
                         std::to_string(target.minSamples));
    if (target.maxSamples < kTargetMinSamples || target.maxSamples > kTargetMaxSamples)
        throw InputError(where + ": the ceiling (--max-spp) must be " +
                         range(kTargetMinSamples, kTargetMaxSamples) + ", got " +
                         std::to_string(target.maxSamples));
    if (target.maxSamples < target.minSamples)
        throw InputError(where + ": the ceiling (--max-spp " + std::to_string(target.maxSamples) +
                         ") is below the floor (--min-spp " + std::to_string(target.minSamples) +
                         "); it must be at least the floor");
}

void RunningMoments::add(const Colour& x) {
    // Welford: move the mean by the new sample's share, and add the product of its deviations
    // from the old and the new mean to the sum of squares.
    ++n_;
    const Colour delta = x - mean_;
    mean_ += delta / static_cast<double>(n_);
    m2_ += delta * (x - mean_);
}

Colour RunningMoments::variance() const {
    return n_ < 2 ? Colour(0.0) : m2_ / static_cast<double>(n_ - 1);
}

double RunningMoments::channelVariance() const {
    const Colour v = variance();
    return (v.r + v.g + v.b) / 3.0;
}

namespace {

/// The fresh count k·w − q clamped to [lo, hi], for a planning weight w and q kept pilot
/// samples: together, the kept pilot and the fresh samples are k·w.
double plannedCount(double w, double k, int q, int lo, int hi) {
    return std::clamp(std::ceil(k * w - q), static_cast<double>(lo), static_cast<double>(hi));
}

/// The predicted mean squared error of counts k·w for the kept pilots' variances `s2`: the
/// mean of s²/(q + n).
double predictedMse(const std::vector<double>& w, const std::vector<float>& s2, double k, int q,
                    int lo, int hi) {
    double sum = 0.0;
    for (std::size_t i = 0; i < w.size(); ++i)
        sum += s2[i] / (q + plannedCount(w[i], k, q, lo, hi));
    return sum / static_cast<double>(w.size());
}

}  // namespace

// [plan-samples]
std::vector<std::uint32_t> planSamples(const std::vector<float>& planning,
                                       const std::vector<float>& kept, int width, int height,
                                       const TargetError& target, const PilotCost* cost) {
    const int q = target.keptPilotSamples(), lo = target.freshFloor(), hi = target.maxSamples;
    // Step 1: each pixel's planning weight w, the root of the larger of its planning group's
    // spread and its 3 × 3 block's mean spread, the neighbours' kept pilots' (the block cut at
    // the image's edges); with costs, over the root of the block's mean price of a sample.
    std::vector<double> w(planning.size(), 0.0);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const std::size_t i = static_cast<std::size_t>(y) * width + x;
            double sum = 0.0, price = 0.0;
            int count = 0;
            for (int qy = std::max(0, y - 1); qy <= std::min(height - 1, y + 1); ++qy)
                for (int qx = std::max(0, x - 1); qx <= std::min(width - 1, x + 1); ++qx) {
                    const std::size_t j = static_cast<std::size_t>(qy) * width + qx;
                    sum += j == i ? planning[i] : kept[j];
                    if (cost) price += j == i ? cost->planning[i] : cost->kept[j];
                    ++count;
                }
            w[i] = std::sqrt(std::max(static_cast<double>(planning[i]), sum / count));
            if (cost && price > 0.0) w[i] /= std::sqrt(price / count);
        }
    // Step 2: the smallest k whose predicted error is at most E. The error falls as k grows,
    // until every pixel with any weight sits at the ceiling; find a k that is enough (or
    // that reaches the ceiling everywhere), then bisect.
    const double target2 = target.error * target.error;
    double kLow = 0.0, kHigh = 1.0;
    const double wMin = [&] {
        double m = 0.0;
        for (double wi : w)
            if (wi > 0.0 && (m == 0.0 || wi < m)) m = wi;
        return m;
    }();
    // k·wMin ≥ q + the ceiling puts every pixel with a weight at the ceiling.
    const double kCeiling = wMin > 0.0 ? (q + hi) / wMin : 1.0;
    while (kHigh < kCeiling && predictedMse(w, kept, kHigh, q, lo, hi) > target2) {
        kLow = kHigh;
        kHigh *= 2.0;
    }
    for (int i = 0; i < 64; ++i) {
        const double mid = 0.5 * (kLow + kHigh);
        (predictedMse(w, kept, mid, q, lo, hi) > target2 ? kLow : kHigh) = mid;
    }
    // Step 3: the counts, made even (a pixel's fresh samples come in two equal groups)
    // without passing the ceiling.
    const auto evenCeiling = static_cast<std::uint32_t>(std::max(2, hi - hi % 2));
    std::vector<std::uint32_t> counts(w.size());
    for (std::size_t i = 0; i < w.size(); ++i) {
        const auto n = static_cast<std::uint32_t>(plannedCount(w[i], kHigh, q, lo, hi));
        counts[i] = std::min(n + n % 2, evenCeiling);
    }
    return counts;
}
// [plan-samples]

PixelEstimate withPilot(const PixelEstimate& pilot, int pilotCount, const PixelEstimate& fresh,
                        int freshCount) {
    const double p = pilotCount, n = freshCount, total = p + n;
    // Var((p·a + n·b)/(p + n)) = (p²·Var a + n²·Var b)/(p + n)², a and b independent.
    return {(p * pilot.mean + n * fresh.mean) / total,
            (p * p * pilot.varianceOfMean + n * n * fresh.varianceOfMean) / (total * total)};
}

void SampleMap::record(int x, int y, int count, double varianceOfMean) {
    const std::size_t i = static_cast<std::size_t>(y) * width + x;
    samples[i] = static_cast<std::uint32_t>(count);
    meanVariance[i] = static_cast<float>(varianceOfMean);
}

std::size_t SampleMap::recordedPixels() const {
    return samples.size() -
           static_cast<std::size_t>(std::count(samples.begin(), samples.end(), 0u));
}

double SampleMap::meanSamples() const {
    const std::size_t n = recordedPixels();
    double sum = 0.0;
    for (std::uint32_t k : samples) sum += k;
    return n == 0 ? 0.0 : pilot + sum / static_cast<double>(n);
}

std::uint32_t SampleMap::maxSamples() const {
    return recordedPixels() == 0 ? 0 : pilot + *std::max_element(samples.begin(), samples.end());
}

double SampleMap::rmsError() const {
    const std::size_t n = recordedPixels();
    if (n == 0) return 0.0;
    double sum = 0.0;  // A pixel not recorded adds its 0.
    for (float v : meanVariance) sum += v;
    return std::sqrt(sum / static_cast<double>(n));
}

namespace {
/// One recorded pixel as packRecorded writes it.
struct PackedPixel {
    std::uint32_t index;
    std::uint32_t samples;
    float meanVariance;
};
}  // namespace

std::vector<std::byte> SampleMap::packRecorded() const {
    std::vector<PackedPixel> pixels;
    for (std::size_t i = 0; i < samples.size(); ++i)
        if (samples[i] != 0)
            pixels.push_back({static_cast<std::uint32_t>(i), samples[i], meanVariance[i]});
    const auto bytes = std::as_bytes(std::span(pixels));
    return {bytes.begin(), bytes.end()};
}

void SampleMap::recordPacked(std::span<const std::byte> packed) {
    if (packed.size() % sizeof(PackedPixel) != 0)
        throw std::runtime_error("a sample map's bytes are not whole pixels");
    for (std::size_t at = 0; at < packed.size(); at += sizeof(PackedPixel)) {
        PackedPixel p;
        std::memcpy(&p, packed.data() + at, sizeof p);
        if (p.index >= samples.size())
            throw std::runtime_error("a sample map's pixel lies outside the image");
        samples[p.index] = p.samples;
        meanVariance[p.index] = p.meanVariance;
    }
}

Image sampleHeatMap(const SampleMap& map) {
    // A ramp of five stops, in linear RGB.
    static const Colour kStops[] = {
        {0.0, 0.0, 0.0}, {0.05, 0.1, 0.6}, {0.8, 0.1, 0.1}, {1.0, 0.85, 0.1}, {1.0, 1.0, 1.0}};
    constexpr int kSegments = 4;
    Image image(map.width, map.height);
    // White is the most any pixel took, but at least 8 pilots' worth (4 times the fewest a
    // pixel can take), so that a picture at the floor everywhere is mid-scale, not white.
    const auto least = 8 * static_cast<std::uint32_t>(map.pilot);
    const double top =
        std::sqrt(static_cast<double>(std::max<std::uint32_t>({1, map.maxSamples(), least})));
    for (int y = 0; y < map.height; ++y)
        for (int x = 0; x < map.width; ++x) {
            const std::uint32_t n =
                map.pilot + map.samples[static_cast<std::size_t>(y) * map.width + x];
            const double t = std::clamp(std::sqrt(static_cast<double>(n)) / top, 0.0, 1.0);
            const int k = std::min(kSegments - 1, static_cast<int>(t * kSegments));
            const double f = t * kSegments - k;
            image.set(x, y, kStops[k] * (1.0 - f) + kStops[k + 1] * f);
        }
    return image;
}

}  // namespace rb
