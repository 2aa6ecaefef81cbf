#include "core/progress.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace rb {

// [progressive-order]
std::vector<int> progressiveOrder(int count) {
    std::vector<int> order;
    if (count <= 0) return order;
    order.reserve(count);
    // Count i up through the next power of two and reverse its bits: 0, 1/2, 1/4, 3/4, 1/8,
    // ... of that power. Values past the end are skipped, so every number appears once.
    int bits = 0;
    while ((std::int64_t{1} << bits) < count) ++bits;
    for (std::uint32_t i = 0; i < (std::uint32_t{1} << bits); ++i) {
        std::uint32_t reversed = 0;
        for (int b = 0; b < bits; ++b) reversed |= ((i >> b) & 1u) << (bits - 1 - b);
        if (reversed < static_cast<std::uint32_t>(count))
            order.push_back(static_cast<int>(reversed));
    }
    return order;
}
// [progressive-order]

WorkEstimator::WorkEstimator(const std::vector<WorkUnit>& units)
    : units_(units), started_(units.size()), done_(units.size(), false) {
    int strata = 0;
    for (const WorkUnit& u : units_) strata = std::max(strata, u.stratum + 1);
    strata_.resize(strata);
    for (const WorkUnit& u : units_) strata_[u.stratum].pixels += u.pixels;
    // A stratum without pixels has nothing to measure: count it as measured already.
    for (const Stratum& s : strata_)
        if (s.pixels <= 0.0) ++stratumsMeasured_;
}

void WorkEstimator::start(int index, double now) {
    if (index < 0 || index >= static_cast<int>(units_.size()) || started_[index]) return;
    started_[index] = now;
    running_.push_back(index);
}

void WorkEstimator::finish(int index, double now) {
    if (index < 0 || index >= static_cast<int>(units_.size()) || !started_[index] || done_[index])
        return;
    done_[index] = true;
    running_.erase(std::find(running_.begin(), running_.end(), index));
    const double cost = std::max(0.0, now - *started_[index]);
    const WorkUnit& u = units_[index];
    Stratum& s = strata_[u.stratum];
    if (s.donePixels == 0.0 && u.pixels > 0.0) ++stratumsMeasured_;
    s.donePixels += u.pixels;
    s.doneCost += cost;
    donePixels_ += u.pixels;
    doneCost_ += cost;
    ++unitsDone_;
}

// [work-estimate]
double WorkEstimator::density(int s) const {
    // A stratum's own seconds per pixel once it has been measured; until then the image's.
    const Stratum& stratum = strata_[s];
    if (stratum.donePixels > 0.0) return stratum.doneCost / stratum.donePixels;
    return donePixels_ > 0.0 ? doneCost_ / donePixels_ : 0.0;
}

double WorkEstimator::workDone(double now) const {
    double work = doneCost_;
    for (int i : running_) work += std::max(0.0, now - *started_[i]);
    return work;
}

double WorkEstimator::workLeft(double now) const {
    // Step 1: price every unfinished pixel at its stratum's measured seconds per pixel.
    double left = 0.0;
    for (int s = 0; s < static_cast<int>(strata_.size()); ++s)
        left += (strata_[s].pixels - strata_[s].donePixels) * density(s);
    // Step 2: a running unit has already had some of its work done; a unit that overruns its
    // estimate is taken to be about to finish.
    for (int i : running_) {
        const double estimate = units_[i].pixels * density(units_[i].stratum);
        left -= std::min(estimate, std::max(0.0, now - *started_[i]));
    }
    return std::max(0.0, left);
}

double WorkEstimator::fractionDone(double now) const {
    if (allDone()) return 1.0;
    if (unitsDone_ == 0) return 0.0;
    const double done = workDone(now);
    const double total = done + workLeft(now);
    return total > 0.0 ? done / total : 0.0;
}

std::optional<double> WorkEstimator::secondsLeft(double now) const {
    if (allDone()) return 0.0;
    const double done = workDone(now);
    if (unitsDone_ == 0 || done <= 0.0 || now <= 0.0) return std::nullopt;
    // Work (thread-seconds) was done at done / now per second; the rest goes at that rate.
    return workLeft(now) * (now / done);
}
// [work-estimate]

bool RedrawThrottle::due(double now) {
    if (now - last_ < interval_) return false;
    last_ = now;
    return true;
}

std::string formatDuration(double seconds) {
    char text[32];
    seconds = std::max(0.0, seconds);
    if (seconds < 59.95) {
        std::snprintf(text, sizeof text, "%.1f s", seconds);
    } else if (seconds < 3599.5) {
        const long s = std::lround(seconds);
        std::snprintf(text, sizeof text, "%ld min %02ld s", s / 60, s % 60);
    } else {
        const long m = std::lround(seconds / 60.0);
        std::snprintf(text, sizeof text, "%ld h %02ld min", m / 60, m % 60);
    }
    return text;
}

std::string formatProgressLine(const ProgressReport& report) {
    // Under a target error the bar is shorter, to leave room for the error.
    const int barWidth = report.error ? 14 : 20;
    const double fraction = std::clamp(report.fraction, 0.0, 1.0);
    const int filled = static_cast<int>(barWidth * fraction);
    const std::string bar = std::string(filled, '#') + std::string(barWidth - filled, ' ');
    const std::string eta = report.etaSeconds ? formatDuration(*report.etaSeconds) : "...";
    // The speed, or under a target error the finished pixels' error against the target.
    char last[48];
    if (report.error)
        std::snprintf(last, sizeof last, "error %.3g/%.3g", *report.error, report.targetError);
    else if (report.raysPerSecond >= 1e6)
        std::snprintf(last, sizeof last, "%.1f Mrays/s", report.raysPerSecond / 1e6);
    else
        std::snprintf(last, sizeof last, "%.1f krays/s", report.raysPerSecond / 1e3);
    char line[160];
    std::snprintf(line, sizeof line, "[%s] %3d%%  elapsed %s  ETA %s  %s", bar.c_str(),
                  static_cast<int>(100 * fraction), formatDuration(report.elapsedSeconds).c_str(),
                  eta.c_str(), last);
    return line;
}

}  // namespace rb
