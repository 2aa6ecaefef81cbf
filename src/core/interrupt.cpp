#include "core/interrupt.h"

#include <csignal>

namespace rb {

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
