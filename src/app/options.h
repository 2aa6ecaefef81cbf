/// \file
/// The command line of ./rt.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "core/feature.h"
#include "core/memory_budget.h"

namespace rb {

/// Everything the command line can say.
struct CommandLine {
    std::string scene;             ///< The scene script.
    std::string features = "all";  ///< --features=LIST.
    bool listFeatures = false;     ///< --list-features.
    int threads = 0;               ///< --threads N (0: all cores); also the seeds' "scene.lua N".
    std::uint64_t seed = 0;        ///< --seed S.
    int samplesPerPixel = 0;       ///< --spp N (0: the scene's choice, normally 1).
    int width = 0, height = 0;     ///< --size WxH (0: the scene's size).
    std::string output;            ///< --output FILE.
    std::string outputDir;         ///< --output-dir DIR: every image goes under DIR.
    std::vector<std::string> assetDirs;  ///< --assets DIR (repeatable): more places for files.
    int maxDepth = -1;                   ///< --max-depth N (-1: the scene's choice).
    bool stats = false;                  ///< --stats.
    bool quiet = false;                  ///< --quiet.
    bool legacy = false;                 ///< --legacy: pre-2015 course scenes.
    bool modern = false;   ///< --modern: force the current framework's transform order.
    bool lenient = false;  ///< --lenient: stand-ins for unknown calls and unreadable arguments.
    std::vector<std::string> dialects;  ///< --dialect FILE.lua (repeatable): run before the scene.
    std::string batchDir;               ///< --batch DIR: render every scene under DIR.
    double sceneTimeLimit = 300;        ///< --scene-time-limit S: per scene in --batch.
    double timeLimit = 0;    ///< --time-limit S: stop the whole run after S seconds (0: none).
    bool unsafeLua = false;  ///< --unsafe-lua: allow os and io.
    MemoryBudget memory;     ///< --max-memory SIZE (parseCommandLine: half the machine).
    bool partial = false;    ///< --partial: a stopped render writes NAME.partial.png.
    bool preview = false;    ///< --preview: a quarter of the size, one sample of everything.
    bool mpi = false;        ///< --mpi: join an MPI job even when mpirun did not start rt.
    bool resume = false;     ///< --resume: finish each image from the journal beside it.
    std::string mpiLease = "dynamic";  ///< --mpi-lease dynamic|static: how tiles are dealt.
    double tileTimeout = 0;  ///< --tile-timeout S: a lease overdue by S s stops the job (0: auto).
    double targetError = 0;  ///< --target-error E (0: the scene's target_error, else off).
    int minSpp = 0;          ///< --min-spp N: the target's floor (0: the scene's, else 16).
    int maxSpp = 0;          ///< --max-spp N: the target's ceiling (0: the scene's, else 4096).
    bool aovSampleCount = false;  ///< --aov sample-count: write NAME.samples.png, a heat map.
    bool help = false;            ///< --help.
    bool version = false;         ///< --version.
    std::map<std::string, std::string> featureOptions;  ///< --name=value added by chapters.
};

/// Parse argv. Options that built features add (FeatureOption) land in featureOptions.
/// Throws InputError for an unknown option or a bad value.
CommandLine parseCommandLine(int argc, const char* const* argv,
                             const std::vector<Feature>& built = {});

/// The chapter options --preview sets, unless the command line set them: no antialiasing, and
/// one sample of each distribution (area lights, glossy lobes, the lens) and one photon pass.
inline constexpr std::pair<const char*, const char*> kPreviewOptions[] = {
    {"aa", "none"},       {"light-samples", "1"}, {"glossy-samples", "1"},
    {"dof-samples", "1"}, {"photon-passes", "1"},
};

/// The size --preview renders a width x height request at: a quarter of each side (rounded,
/// at least 1 pixel), a sixteenth of the pixels.
std::pair<int, int> previewSize(int width, int height);

/// The sampling settings of a --preview run, as options: "--spp 1 --aa=none ...".
std::string previewSettings(const CommandLine& cl);

/// The --help text, with the options of the built features.
std::string usage(const std::vector<Feature>& built = {});

}  // namespace rb
