/// \file
/// Stopping a render early and cleanly: Ctrl-C (SIGINT), SIGTERM and --time-limit.
///
/// rt installs no signal handler and keeps no global flag. It blocks SIGINT and SIGTERM in the
/// main thread before any worker thread starts (workers inherit the mask), so the signals stay
/// pending; the render loop asks before each tile whether one is pending, and each tile asks
/// again after each of its pixels (PixelStop). A stopped render throws RenderStopped, and
/// nothing is written: no partial image, no temporary file.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>

namespace rb {

/// A render that stopped before it finished, and the exit code that says why.
struct RenderStopped : std::runtime_error {
    RenderStopped(const std::string& why, int code) : std::runtime_error(why), exitCode(code) {}
    int exitCode;  ///< 130 for SIGINT, 143 for SIGTERM (as shells report them), 124 for a time
                   ///< limit.
};

/// Thrown from inside a tile when the render is to stop. The tile is half-done: the render loop
/// drops it, so that a partial image (--partial) and the MPI journal hold whole tiles only.
struct TileAbandoned {};

/// Whether the render is to stop, asked after every pixel of a tile, so that a tile that takes
/// minutes stops within a pixel's time, not a tile's. The answer costs little: the steady clock
/// (40 ns here, a sixth of a chapter-1 pixel) is read after every 1,024 rays a tile traces
/// (milliseconds of work for the slowest rays seen, a fraction of a tile for fast ones, and
/// every pixel when a pixel traces more), and the question itself (a pending signal is a system
/// call) is put at most every 10 ms. One per tile, on the thread rendering it; the render's
/// `stopped` flag carries a stop one tile saw to every other.
class PixelStop {
  public:
    /// Asks `ask` (empty: never stops) and shares its answer through `stopped`. The tile has just
    /// asked before it started, so the first question waits 10 ms.
    PixelStop(const std::function<bool()>& ask, std::atomic<bool>& stopped);

    /// After a pixel, with the rays the thread has traced so far (RayCounters::total): throws
    /// TileAbandoned when the render is to stop.
    void afterPixel(std::uint64_t raysTraced) {
        if (ask_ && raysTraced >= lookAt_) look(raysTraced);
    }

  private:
    /// Read the clock and put the question when it is due; throws TileAbandoned if the answer
    /// is yes.
    void look(std::uint64_t raysTraced);

    const std::function<bool()>& ask_;
    std::atomic<bool>& stopped_;
    std::uint64_t lookAt_ = 0;                    ///< Rays traced at the next look.
    std::chrono::steady_clock::time_point next_;  ///< When to put the question again.
};

/// Block SIGINT and SIGTERM in the calling thread and the threads it starts later, so that
/// they wait, pending, until pendingInterrupt() sees them.
void holdInterrupts();

/// SIGINT or SIGTERM when one is pending for the process, else 0.
int pendingInterrupt();

/// The RenderStopped for a pending signal (SIGINT or SIGTERM).
RenderStopped interruptedBy(int signal);

}  // namespace rb
