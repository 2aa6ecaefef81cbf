/// \file
/// The command line of ./rt.
#pragma once

#include <cstdint>
#include <string>

namespace rb {

/// Everything the command line can say.
struct CommandLine {
    std::string scene;               ///< The scene script.
    std::string features = "all";    ///< --features=LIST.
    bool listFeatures = false;       ///< --list-features.
    int threads = 0;                 ///< --threads N (0: all cores); also the seeds' "scene.lua N".
    std::uint64_t seed = 0;          ///< --seed S.
    int samplesPerPixel = 0;         ///< --spp N (0: the scene's choice, normally 1).
    int width = 0, height = 0;       ///< --size WxH (0: the scene's size).
    std::string output;              ///< --output FILE.
    int maxDepth = -1;               ///< --max-depth N (-1: the scene's choice).
    bool stats = false;              ///< --stats.
    bool quiet = false;              ///< --quiet.
    bool legacy = false;             ///< --legacy: pre-2015 course scenes.
    bool unsafeLua = false;          ///< --unsafe-lua: allow os and io.
    bool help = false;               ///< --help.
    bool version = false;            ///< --version.
};

/// Parse argv. Throws InputError for an unknown option or a bad value.
CommandLine parseCommandLine(int argc, const char* const* argv);

/// The --help text.
std::string usage();

}  // namespace rb
