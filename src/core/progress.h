/// \file
/// An honest progress bar: the order the render visits its tiles in, the estimator that turns
/// the measured cost of finished tiles into a fraction done and an ETA, and the line it draws.
///
/// Rows of an image differ in cost by orders of magnitude (sky against glossy floor), so "rows
/// done" says little about "work done". Two things fix that. The renderer visits its tiles in a
/// progressive order (progressiveOrder) so that the finished tiles are, at every moment, spread
/// evenly over the image; and WorkEstimator prices each unfinished tile at the measured time per
/// pixel of the finished tiles near it (in its stratum). Everything here is pure: time comes in
/// as an argument, so the tests drive it with a simulated clock.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace rb {

/// The numbers 0..count-1 in bit-reversed (van der Corput) order: 0, count/2, count/4, 3count/4,
/// ... Any prefix of 2^k entries (for count a power of two) holds exactly one number from each
/// of 2^k equal segments of 0..count-1, so the first units done are a fair sample of all.
std::vector<int> progressiveOrder(int count);

/// One unit of work as the estimator sees it: its size and the stratum it belongs to.
struct WorkUnit {
    double pixels = 0.0;  ///< Size of the unit (pixels, or any measure its cost scales with).
    int stratum = 0;      ///< Units of one stratum share a cost-per-pixel estimate.
};

/// Estimates how much of a render is done, and how long the rest will take, from the measured
/// time of its finished units.
///
/// Time is passed in as seconds since the render began (a real or simulated clock). A unit's
/// cost is the time from its start to its finish on its thread. The cost of an unfinished unit
/// is estimated as its size times the cost per pixel measured on the finished units of its
/// stratum (or of the whole image, while its stratum has none). Units still running count the
/// time already spent on them as work done, so the rate of work never jumps when a costly unit
/// finishes.
class WorkEstimator {
  public:
    /// An estimator for `units`, none of them started; strata are numbered 0..strata-1.
    explicit WorkEstimator(const std::vector<WorkUnit>& units);

    /// Record that unit `index` started at time `now`. Starting a unit twice is ignored.
    void start(int index, double now);
    /// Record that unit `index` finished at time `now`. Ignored unless it was started and has
    /// not finished yet.
    void finish(int index, double now);

    /// Number of units finished so far.
    int unitsDone() const { return unitsDone_; }
    /// True once every unit is finished.
    bool allDone() const { return unitsDone_ == static_cast<int>(units_.size()); }
    /// True once every stratum has a finished unit, so that every part of the image has been
    /// measured at least once.
    bool representative() const { return stratumsMeasured_ == static_cast<int>(strata_.size()); }

    /// Thread-seconds of work done by time `now`: finished units, and running units so far.
    double workDone(double now) const;
    /// Estimated thread-seconds of work left at time `now` (0 before any unit has finished).
    double workLeft(double now) const;
    /// Estimated fraction of the total work done at time `now`, in [0, 1].
    double fractionDone(double now) const;
    /// Estimated seconds left at time `now`: the work left at the rate work was done so far.
    /// Empty until a unit has finished.
    std::optional<double> secondsLeft(double now) const;

  private:
    /// Per-stratum totals.
    struct Stratum {
        double pixels = 0.0;      ///< All units' pixels.
        double donePixels = 0.0;  ///< Finished units' pixels.
        double doneCost = 0.0;    ///< Finished units' measured seconds.
    };
    /// Estimated cost per pixel of units in stratum s (0 before any unit has finished).
    double density(int s) const;

    std::vector<WorkUnit> units_;
    std::vector<std::optional<double>> started_;  ///< Start time of each started unit.
    std::vector<bool> done_;
    std::vector<int> running_;  ///< Units started and not finished (about one per thread).
    std::vector<Stratum> strata_;
    int unitsDone_ = 0;
    int stratumsMeasured_ = 0;
    double donePixels_ = 0.0;
    double doneCost_ = 0.0;
};

/// Lets an event through at most once per `interval` of (simulated or real) seconds.
class RedrawThrottle {
  public:
    /// A throttle whose first event through is the first at or after time `interval`, so a
    /// render shorter than that draws nothing, and the first line has a measured rate to show.
    explicit RedrawThrottle(double interval) : interval_(interval) {}
    /// True when the last event let through (or time 0) was at least `interval` before `now`.
    bool due(double now);

  private:
    double interval_;
    double last_ = 0.0;
};

/// What the progress line shows.
struct ProgressReport {
    double fraction = 0.0;             ///< Estimated fraction of the work done.
    double elapsedSeconds = 0.0;       ///< Wall-clock seconds since the render started.
    std::optional<double> etaSeconds;  ///< Estimated seconds left; empty while unknown.
    double raysPerSecond = 0.0;        ///< Rays traced per wall-clock second.
    std::optional<double> error;       ///< Under --target-error: the finished pixels' RMS error.
    double targetError = 0.0;          ///< ... and the target.
};

/// A duration for people: "3.4 s" below a minute, "2 min 05 s" below an hour, else "1 h 02 min".
std::string formatDuration(double seconds);

/// The progress line, e.g. "[#########           ]  48%  elapsed 3.1 s  ETA 3.4 s  12.3
/// Mrays/s"; under a target error "... error 0.018/0.02" in place of the speed. "ETA ..."
/// while the ETA is unknown. Under 80 columns for any render under 100 h.
std::string formatProgressLine(const ProgressReport& report);

}  // namespace rb
