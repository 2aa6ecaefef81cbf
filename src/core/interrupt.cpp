#include "core/interrupt.h"

#include <csignal>

namespace rb {

namespace {
/// How often a tile asks whether to stop: rarely enough that the signal check's system call is
/// never seen in a profile, often enough that no one waits for it.
constexpr std::chrono::milliseconds kPixelStopInterval{10};
}  // namespace

PixelStop::PixelStop(const std::function<bool()>& ask, std::atomic<bool>& stopped)
    : ask_(ask), stopped_(stopped), next_(std::chrono::steady_clock::now() + kPixelStopInterval) {}

void PixelStop::ask() {
    next_ = std::chrono::steady_clock::now() + kPixelStopInterval;
    if (!ask_()) return;
    stopped_ = true;
    throw TileAbandoned{};
}

void holdInterrupts() {
    sigset_t set;
    sigemptyset(&set);
    sigaddset(&set, SIGINT);
    sigaddset(&set, SIGTERM);
    pthread_sigmask(SIG_BLOCK, &set, nullptr);
}

int pendingInterrupt() {
    sigset_t pending;
    sigemptyset(&pending);
    if (sigpending(&pending) != 0) return 0;
    if (sigismember(&pending, SIGINT) == 1) return SIGINT;
    if (sigismember(&pending, SIGTERM) == 1) return SIGTERM;
    return 0;
}

RenderStopped interruptedBy(int signal) {
    if (signal == SIGINT) return {"interrupted (Ctrl-C): stopped without writing an image", 130};
    return {"terminated (SIGTERM): stopped without writing an image", 143};
}

}  // namespace rb
