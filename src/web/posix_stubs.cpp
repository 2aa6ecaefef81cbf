// What emscripten's C library lacks of the calls rt makes: only --batch makes them (it forks a
// process per scene), and the page never runs --batch; fork() itself fails there.
#include <cerrno>

extern "C" int prctl(int, ...) {
    errno = ENOSYS;
    return -1;
}
