/// \file
/// Where the tests read scenes and meshes: the project's root folder. Only this file is
/// compiled with it (RB_SOURCE_DIR), so every other test file compiles to the same object in
/// whatever folder the project is: the assignments' round trip, make grade and the Monte Carlo
/// goldens build exports in several folders and share their objects (objcache.py).
#include <string>

namespace rbtest {

const std::string& sourceDir() {
    static const std::string dir = RB_SOURCE_DIR;
    return dir;
}

}  // namespace rbtest
