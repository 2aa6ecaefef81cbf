/// \file
/// Stopping a render early and cleanly: Ctrl-C (SIGINT), SIGTERM and --time-limit.
///
/// rt installs no signal handler and keeps no global flag. It blocks SIGINT and SIGTERM in the
/// main thread before any worker thread starts (workers inherit the mask), so the signals stay
/// pending; the render loop asks before each tile whether one is pending. A stopped render
/// throws RenderStopped, and nothing is written: no partial image, no temporary file.
#pragma once

#include <stdexcept>
#include <string>

namespace rb {

/// A render that stopped before it finished, and the exit code that says why.
struct RenderStopped : std::runtime_error {
    RenderStopped(const std::string& why, int code) : std::runtime_error(why), exitCode(code) {}
    int exitCode;  ///< 130 for SIGINT, 143 for SIGTERM (as shells report them), 124 for a time
                   ///< limit.
};

/// Block SIGINT and SIGTERM in the calling thread and the threads it starts later, so that
/// they wait, pending, until pendingInterrupt() sees them.
void holdInterrupts();

/// SIGINT or SIGTERM when one is pending for the process, else 0.
int pendingInterrupt();

/// The RenderStopped for a pending signal (SIGINT or SIGTERM).
RenderStopped interruptedBy(int signal);

}  // namespace rb
