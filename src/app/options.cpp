#include "app/options.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>

#include "core/error.h"
#include "core/from_chars.h"
#include "core/image.h"
#include "core/target_error.h"

namespace rb {

namespace {

/// An integer option value in [lo, hi].
long long parseInteger(const std::string& option, const std::string& text, long long lo,
                       long long hi) {
    long long v = 0;
    const auto [end, ec] = rb::fromChars(text.data(), text.data() + text.size(), v);
    if (ec != std::errc() || end != text.data() + text.size() || v < lo || v > hi)
        throw InputError(option + ": expected a whole number from " + std::to_string(lo) + " to " +
                         std::to_string(hi) + ", got '" + text + "'");
    return v;
}

/// A positive finite number (--target-error).
double parsePositive(const std::string& option, const std::string& text) {
    double v = 0;
    const auto [end, ec] = rb::fromChars(text.data(), text.data() + text.size(), v);
    if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(v) || v <= 0)
        throw InputError(option + ": expected a number above 0 (for example 0.02), got '" + text +
                         "'");
    return v;
}

}  // namespace

/// The feature that declares option `name`, or null.
const FeatureOption* findFeatureOption(const std::vector<Feature>& built, const std::string& name) {
    for (const Feature& f : built)
        for (const FeatureOption& o : f.options)
            if (name == std::string("--") + o.name) return &o;
    return nullptr;
}

CommandLine parseCommandLine(int argc, const char* const* argv, const std::vector<Feature>& built) {
    CommandLine cl;
    cl.memory = defaultMemoryBudget();
    bool haveThreadsPositional = false;
    for (int i = 1; i < argc; ++i) {
        std::string arg = argv[i];
        // Split --name=value; otherwise options with values take the next argument.
        std::string name = arg, value;
        bool hasValue = false;
        if (arg.rfind("--", 0) == 0 && arg.find('=') != std::string::npos) {
            name = arg.substr(0, arg.find('='));
            value = arg.substr(arg.find('=') + 1);
            hasValue = true;
        }
        auto next = [&]() -> std::string {
            if (hasValue) return value;
            if (i + 1 >= argc) throw InputError(name + ": missing value");
            return argv[++i];
        };
        if (name == "--help" || name == "-h")
            cl.help = true;
        else if (name == "--version")
            cl.version = true;
        else if (name == "--list-features")
            cl.listFeatures = true;
        else if (name == "--features")
            cl.features = next();
        else if (name == "--threads")
            cl.threads = static_cast<int>(parseInteger(name, next(), 1, 1024));
        else if (name == "--seed")
            cl.seed = static_cast<std::uint64_t>(parseInteger(name, next(), 0, 1LL << 62));
        else if (name == "--spp")
            cl.samplesPerPixel = static_cast<int>(parseInteger(name, next(), 1, 1 << 16));
        else if (name == "--max-depth")
            cl.maxDepth = static_cast<int>(parseInteger(name, next(), 0, 1000));
        else if (name == "--size") {
            const std::string v = next();
            const auto x = v.find('x');
            if (x == std::string::npos) throw InputError("--size: expected WxH, got '" + v + "'");
            cl.width = static_cast<int>(parseInteger("--size", v.substr(0, x), 1, 1 << 16));
            cl.height = static_cast<int>(parseInteger("--size", v.substr(x + 1), 1, 1 << 16));
        } else if (name == "--output" || name == "-o") {
            cl.output = next();
            // PNG, or a format a built chapter writes (chapter 12: .hdr).
            std::vector<std::string> formats;
            for (const Feature& f : built)
                for (const OutputFormat& format : f.outputFormats)
                    formats.push_back(format.extension);
            checkOutputName(cl.output, "--output", formats);
        } else if (name == "--output-dir")
            cl.outputDir = next();
        else if (name == "--assets")
            cl.assetDirs.push_back(next());
        else if (name == "--stats")
            cl.stats = true;
        else if (name == "--quiet" || name == "-q")
            cl.quiet = true;
        else if (name == "--legacy")
            cl.legacy = true;
        else if (name == "--modern")
            cl.modern = true;
        else if (name == "--lenient")
            cl.lenient = true;
        else if (name == "--dialect")
            cl.dialects.push_back(next());
        else if (name == "--batch")
            cl.batchDir = next();
        else if (name == "--time-limit")
            cl.timeLimit = static_cast<double>(parseInteger(name, next(), 1, 86400 * 30));
        else if (name == "--scene-time-limit")
            cl.sceneTimeLimit = static_cast<double>(parseInteger(name, next(), 1, 86400));
        else if (name == "--max-memory")
            cl.memory = memoryBudgetFromOption(next());
        else if (name == "--partial")
            cl.partial = true;
        else if (name == "--preview")
            cl.preview = true;
        else if (name == "--warptest")  // the sampling lab has a command line of its own
            throw InputError(
                "--warptest must come first: ./rt --warptest NAME [PARAMETER=VALUE ...]");
        else if (name == "--mpi")
            cl.mpi = true;
        else if (name == "--resume")
            cl.resume = true;
        else if (name == "--mpi-lease") {
            cl.mpiLease = next();
            if (cl.mpiLease != "dynamic" && cl.mpiLease != "static")
                throw InputError("--mpi-lease: expected dynamic or static, got '" + cl.mpiLease +
                                 "'");
        } else if (name == "--tile-timeout") {
            // Seconds, up to a day: a lease that takes longer is no lease a render should wait for.
            const std::string text = next();
            double v = 0;
            const auto [end, ec] = rb::fromChars(text.data(), text.data() + text.size(), v);
            if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(v) ||
                v <= 0 || v > 86400)
                throw InputError(
                    "--tile-timeout: expected seconds above 0 and at most 86400 (a day), got '" +
                    text + "'");
            cl.tileTimeout = v;
        } else if (name == "--target-error")
            cl.targetError = parsePositive(name, next());
        else if (name == "--min-spp")
            cl.minSpp =
                static_cast<int>(parseInteger(name, next(), kTargetMinSamples, kTargetMaxSamples));
        else if (name == "--max-spp")
            cl.maxSpp =
                static_cast<int>(parseInteger(name, next(), kTargetMinSamples, kTargetMaxSamples));
        else if (name == "--aov") {
            const std::string what = next();
            if (what != "sample-count")
                throw InputError(
                    "--aov: expected sample-count (a heat map of the samples each "
                    "pixel took, under --target-error), got '" +
                    what + "'");
            cl.aovSampleCount = true;
        } else if (name == "--unsafe-lua")
            cl.unsafeLua = true;
        else if (findFeatureOption(built, name))
            cl.featureOptions[name.substr(2)] = next();
        else if (!arg.empty() && arg[0] == '-')
            throw InputError("unknown option '" + arg + "' (see ./rt --help)");
        else if (cl.scene.empty())
            cl.scene = arg;
        else if (!haveThreadsPositional) {
            // The seeds' form: ./rt scene.lua N, with N threads.
            cl.threads = static_cast<int>(parseInteger("thread count", arg, 1, 1024));
            haveThreadsPositional = true;
        } else
            throw InputError("unexpected argument '" + arg + "'");
    }
    if (cl.legacy && cl.modern) throw InputError("--legacy and --modern contradict each other");
    // --preview: one ray per pixel and one sample of everything, unless asked otherwise (its
    // size is applied per render: see previewSize).
    if (cl.preview) {
        if (cl.samplesPerPixel == 0) cl.samplesPerPixel = 1;
        for (const auto& [option, value] : kPreviewOptions)
            if (findFeatureOption(built, std::string("--") + option))
                cl.featureOptions.try_emplace(option, value);
    }
    if (!cl.batchDir.empty() && !cl.scene.empty())
        throw InputError("--batch renders a folder of scenes; give either --batch DIR or a scene");
    if (cl.scene.empty() && cl.batchDir.empty() && !cl.help && !cl.version && !cl.listFeatures)
        throw InputError("no scene file given (usage: ./rt [options] scene.lua)");
    return cl;
}

std::pair<int, int> previewSize(int width, int height) {
    return {std::max(1, (width + 2) / 4), std::max(1, (height + 2) / 4)};
}

std::string previewSettings(const CommandLine& cl) {
    std::string text = "--spp " + std::to_string(cl.samplesPerPixel);
    for (const auto& [option, value] : kPreviewOptions)
        if (auto it = cl.featureOptions.find(option); it != cl.featureOptions.end())
            text += " --" + it->first + "=" + it->second;
    return text;
}

std::string usage(const std::vector<Feature>& built) {
    std::string text = R"(usage: ./rt [options] scene.lua [threads]

Renders every gr.render call of a CS488 A4 Lua scene (or a seed dialect).
  --features=LIST    switch chapter modules: all, name, -name (e.g. all,-glossy;
                     -glossy alone means all,-glossy)           default: all
  --list-features    list the chapter modules in this build
  --threads N        worker threads; also ./rt scene.lua N      default: all cores
  --seed S           random stream (output is bit-identical for a given seed)
                                                                default: 0
  --spp N            samples per pixel                          default: 1, one ray
                                                                through each pixel centre
  --target-error E   render to an RMS error of E (linear units, 1 = white; e.g.
                     0.02): a pilot measures each pixel's spread, then each
                     pixel takes fresh samples in proportion to its own and its
                     neighbours'; replaces --spp and the scene's antialiasing
                                   default: the scene's target_error, else off
  --min-spp N        the floor: a pixel keeps a pilot of N (made even), after
                     N/2 (at least 2) that plan it, then takes 2 or more fresh
                                                                default: 8
  --max-spp N        the most fresh samples a pixel takes       default: 4096
  --aov sample-count write NAME.samples.png beside the image: a heat map of the
                     samples each pixel took (black none, white the most, or
                     8 times the pilot if no pixel took that many)
  --max-depth N      recursion limit for secondary rays         default: the scene's
                                                                max_depth, else 5
  --size WxH         override the image size                    default: gr.render's
  --output FILE      override the output image (.png; .hdr with chapter 12)
                                                                default: gr.render's
  --output-dir DIR   write every image under DIR, at the path the scene (or --output)
                     names, instead of beside it; a path that leaves its folder (..,
                     or absolute) keeps only its file name. --batch uses it, so a
                     class's own images are never written over
  --assets DIR       also look for meshes, textures and require()d files in DIR, after
                     the working directory and the scene's folder (may be repeated)
  --time-limit S     stop the render after S seconds, writing nothing (exit code 124);
                     Ctrl-C and SIGTERM stop it the same way (exit codes 130, 143)
                                                                default: no limit
  --partial          when a render is stopped, write what it rendered so far to
                     NAME.partial.png (tiles not reached are black)
  --max-memory SIZE  refuse, before allocating, a mesh or image that would take the
                     run past SIZE bytes (K, M, G, T: powers of 1024)
                                                   default: half of the machine's memory
  --preview          a quick look: a quarter of the width and height (unless --size),
                     one ray per pixel, no antialiasing, one sample of each area light,
                     glossy lobe and lens, one photon pass (options given win)
  --mpi              render with the other ranks of an MPI job (mpirun -np N ./rt
                     scene.lua does it without asking): rank 0 leases tiles to every
                     rank and writes the image, the same bytes as one process
  --resume           finish each image from the journal of tiles beside it
                     (NAME.png.journal), which an MPI render keeps until the image
                     is written; on any number of ranks
  --mpi-lease MODE   dynamic (small batches to whichever rank asks) or static (one
                     band per rank, to compare balance)       default: dynamic
  --tile-timeout S   stop the MPI job when a rank has returned nothing for S seconds
                     while it holds a lease of tiles (a hung rank): rank 0 names the
                     rank and its tiles, keeps the journal and says how to resume
                                   default: 50x the slowest lease so far, at least 300 s
  --stats            print ray counts, phase times, Mrays/s and memory
  --quiet            no progress bar or messages
  --legacy           treat the scene as pre-2015 (transforms post-multiply)
  --modern           treat the scene as current (transforms apply in the order written)
                                                   default: decided from the scene's calls
  --dialect FILE     a Lua file run before the scene, defining or overriding gr.* calls
                     and node methods (may be repeated)
  --lenient          unknown calls, methods and primitives, and arguments raybook
                     cannot read, get stand-ins, not errors; stderr ends with the list
  --batch DIR        render every scene under DIR, each from its own folder, and write
                     DIR/raybook-report.html; the renders go to DIR/raybook-report/,
                     beside any image a student made, never over it
  --scene-time-limit S
                     seconds each scene may take in --batch      default: 300
  --unsafe-lua       let the scene use os and io (off: scenes run in a sandbox)
  --warptest NAME [PARAMETER=VALUE ...]
                     the sampling lab: draw a chapter's sampler against its pdf, write
                     a figure and a chi-square verdict (./rt --warptest list names them;
                     first on the command line)
  --compare A.png B.png [--diff D.png] [--threshold RMSE]
                     compare two images: RMSE, PSNR, the largest difference and the
                     pixels over one 8-bit level; exit 1 when RMSE > --threshold
                     (default 0); with --thresholds NAME.txt, the golden check
                     (./rt --compare --help; first on the command line)
  --help, --version
)";
    bool first = true;
    for (const Feature& f : built)
        for (const FeatureOption& o : f.options) {
            if (first) text += "\nOptions the chapters in this build add:\n";
            first = false;
            // A long option gets its help on the next line, aligned with the others.
            std::string left = std::string("  --") + o.name + "=" + o.value;
            left = left.size() < 20 ? left + std::string(21 - left.size(), ' ')
                                    : left + "\n" + std::string(21, ' ');
            text += left + o.help + " (chapter " + std::to_string(f.chapter) + ")\n" +
                    std::string(21, ' ') + "default: " + o.defaultValue + "\n";
        }
    return text;
}

}  // namespace rb
