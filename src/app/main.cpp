// ./rt: run a scene script, then render each gr.render call it made.
#include <sys/resource.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <optional>
#include <tuple>

#include "app/batch.h"
#include "app/compare.h"
#include "app/options.h"
#include "app/render_warnings.h"
#include "app/version.h"
#include "core/cluster.h"
#include "core/error.h"
#include "core/interrupt.h"
#include "core/post_process.h"
#include "core/render.h"
#include "core/world.h"
#include "lab/warp_test.h"
#include "mpi/journal.h"
#include "scene/lua_scene.h"

namespace rb {
namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) {
    return std::chrono::duration<double>(Clock::now() - t).count();
}

/// Peak resident set size in MiB.
double peakMemoryMiB() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_maxrss / 1024.0;  // Linux reports KiB
}

/// Where --output-dir DIR puts an image named `path`: DIR/path, or DIR/its file name when the
/// path is absolute or climbs out of its folder with "..", so nothing lands outside DIR. The
/// folders under DIR are made here (DIR is the caller's; --batch owns its report folder).
std::string underOutputDir(const std::string& dir, const std::string& path) {
    namespace fs = std::filesystem;
    const fs::path p = fs::path(path).lexically_normal();
    const bool leaves = p.is_absolute() || (!p.empty() && *p.begin() == "..");
    const fs::path file = fs::path(dir) / (leaves ? p.filename() : p);
    std::error_code ec;  // a folder that cannot be made is reported by the caller's check
    fs::create_directories(file.parent_path(), ec);
    return file.string();
}

/// The output path of render number `index` (of `count`) after --output and --output-dir.
std::string outputPath(const CommandLine& cl, const RenderJob& job, size_t index, size_t count) {
    std::string path = job.output;
    if (!cl.output.empty() && (count == 1 || index == 0)) {
        path = cl.output;
    } else if (!cl.output.empty()) {
        const auto dot = cl.output.rfind('.');
        const std::string stem = dot == std::string::npos ? cl.output : cl.output.substr(0, dot);
        const std::string ext = dot == std::string::npos ? ".png" : cl.output.substr(dot);
        path = stem + "-" + std::to_string(index + 1) + ext;
    }
    return cl.outputDir.empty() ? path : underOutputDir(cl.outputDir, path);
}

void printFeatures(const FeatureSet& set) {
    for (const Feature& f : set.built())
        std::printf("%2d  %-14s %-4s %s%s\n", f.chapter, f.name, set.enabled(f.name) ? "on" : "off",
                    f.title, f.switchable ? "" : " (core)");
}

/// The target error of render `job`: the command line's --target-error, --min-spp and
/// --max-spp, else the scene's target_error, min_spp and max_spp, else off. Throws InputError
/// for a target that cannot work.
TargetError targetErrorFor(const CommandLine& cl, const RenderJob& job) {
    TargetError target;
    const auto scene = [&](const char* name, double fallback) {
        const auto it = job.options.find(name);
        return it == job.options.end() ? fallback : it->second;
    };
    target.error = cl.targetError > 0 ? cl.targetError : scene("target_error", 0.0);
    target.minSamples =
        cl.minSpp > 0 ? cl.minSpp : static_cast<int>(scene("min_spp", target.minSamples));
    target.maxSamples =
        cl.maxSpp > 0 ? cl.maxSpp : static_cast<int>(scene("max_spp", target.maxSamples));
    if (!target.on()) {
        if (cl.minSpp > 0 || cl.maxSpp > 0)
            throw InputError(
                "--min-spp and --max-spp bound --target-error, which is not given "
                "(on the command line or as the scene's target_error)");
        return target;
    }
    checkTargetError(target, cl.targetError > 0 ? std::string("--target-error") : job.where);
    return target;
}

/// Where --aov sample-count puts the heat map: "out.png" becomes "out.samples.png".
std::string sampleMapPath(const std::string& output) {
    std::filesystem::path path(output);
    return path.replace_extension(".samples.png").string();
}

/// "N bytes, hash H" of the file at `path`: its content, for a render's identity.
std::string contentOf(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    char hash[17];
    std::snprintf(hash, sizeof hash, "%016llx",
                  static_cast<unsigned long long>(fnv1a64(
                      {reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size()})));
    return std::to_string(bytes.size()) + " bytes, hash " + hash;
}

/// What makes render `job` of the command line `cl` the same render: rt's version, the scene
/// file's bytes, the size, the seed, the sampling options and every file the scene read
/// (`files`, as SceneLoadReport::files), by content. A journal (--resume) written under other
/// values is refused, and so are ranks that disagree.
RenderIdentity renderIdentity(const CommandLine& cl, const RenderJob& job,
                              const std::string& output,
                              const std::vector<std::pair<std::string, std::string>>& files) {
    std::ifstream in(cl.scene, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::string sampling =
        "features " + cl.features + ", spp " + std::to_string(cl.samplesPerPixel) + ", max-depth " +
        std::to_string(cl.maxDepth) + (cl.legacy ? ", legacy" : "") +
        (cl.modern ? ", modern" : "") + (cl.lenient ? ", lenient" : "") +
        (cl.targetError > 0 ? ", target-error " + std::to_string(cl.targetError) : "") +
        (cl.minSpp > 0 ? ", min-spp " + std::to_string(cl.minSpp) : "") +
        (cl.maxSpp > 0 ? ", max-spp " + std::to_string(cl.maxSpp) : "");
    for (const auto& [name, value] : cl.featureOptions) sampling += ", " + name + " " + value;
    for (const std::string& dialect : cl.dialects) sampling += ", dialect " + dialect;
    RenderIdentity identity{output,
                            {{"version", std::string(versionNumber()) + " (" + gitCommit() + ")"},
                             {"scene", std::filesystem::path(cl.scene).filename().string() + " (" +
                                           std::to_string(bytes.size()) + " bytes, hash " +
                                           std::to_string(std::hash<std::string>{}(bytes)) + ")"},
                             {"size", std::to_string(job.width) + "x" + std::to_string(job.height)},
                             {"seed", std::to_string(cl.seed)},
                             {"sampling", sampling}}};
    // Named as the scene names them, so a resume from another folder still matches.
    for (const auto& [name, path] : files)
        identity.fields.emplace_back("file " + name, contentOf(path));
    return identity;
}

int run(int argc, char** argv, Cluster& cluster) {
    const std::vector<Feature> built = builtFeatures();
    // The sampling lab (src/lab/): ./rt --warptest NAME ... has a command line of its own.
    if (argc >= 2 && std::string(argv[1]) == "--warptest")
        return warpTestCommand(std::vector<std::string>(argv + 2, argv + argc), built, std::cout,
                               std::cerr);
    // Two images compared (src/app/compare.cpp): ./rt --compare A.png B.png ...
    if (argc >= 2 && std::string(argv[1]) == "--compare")
        return compareCommand(std::vector<std::string>(argv + 2, argv + argc), std::cout,
                              std::cerr);
    const CommandLine cl = parseCommandLine(argc, argv, built);
    if (cl.help) {
        std::cout << usage(built);
        return 0;
    }
    if (cl.version) {
        std::cout << versionText(built);
        return 0;
    }
    const FeatureSet features(built, cl.features);
    if (cl.listFeatures) {
        printFeatures(features);
        return 0;
    }
    if (!cl.batchDir.empty()) return runBatch(cl, argc, argv, cluster);
    // From here on Ctrl-C and SIGTERM wait, pending, until the render loop looks for them.
    holdInterrupts();
    const auto runStart = Clock::now();
    // Under MPI, Ctrl-C and SIGTERM are the cluster's: mpirun kills every rank a second after
    // them, and the cluster's watcher speaks and exits before that (src/mpi/mpi_cluster.h).
    const auto stopRequested = [&] {
        return (!cluster.distributed() && pendingInterrupt() != 0) ||
               (cl.timeLimit > 0 && since(runStart) > cl.timeLimit);
    };

    // Start the render threads once per process, before anything else, as POV-Ray and pbrt
    // start their thread pools. On a small VM the first parallel region takes up to a scheduler
    // tick (1-7 ms here: the new thread waits on its creator's core while libgomp's master
    // spins), which would otherwise land in the first render, a fixed cost that no number of
    // cores shortens. --stats reports it as "threads".
    auto t0 = Clock::now();
    startRenderThreads(cl.threads);
    const double threadSeconds = since(t0);

    // Run the script. Rendering starts only after it finished, so the command line can
    // override what it asked for.
    t0 = Clock::now();
    SceneLoadOptions loadOptions;
    loadOptions.era = cl.legacy   ? EraChoice::Legacy
                      : cl.modern ? EraChoice::Modern
                                  : EraChoice::Detect;
    loadOptions.unsafeLua = cl.unsafeLua;
    loadOptions.assetDirs = cl.assetDirs;
    loadOptions.lenient = cl.lenient;
    loadOptions.dialects = cl.dialects;
    loadOptions.featureOptions = cl.featureOptions;
    loadOptions.memory = cl.memory;
    loadOptions.memoryLimit = static_cast<size_t>(
        std::min<std::uint64_t>(loadOptions.memoryLimit, cl.memory.available()));
    SceneLoadReport load;
    std::vector<LoadedRender> renders = loadScene(cl.scene, features, loadOptions, &load);
    const SceneLoadTimes& loadTimes = load.times;
    // The era, when the scene renders pre-2015 or the order was guessed and matters (--stats
    // always names it), and what the scene did that the course framework would have let pass.
    if (load.era.show && !cl.quiet) std::fprintf(stderr, "rt: era: %s\n", load.era.line.c_str());
    for (const std::string& warning : load.warnings)
        std::fprintf(stderr, "rt: warning: %s\n", warning.c_str());

    for (size_t k = 0; k < renders.size(); ++k) {
        LoadedRender& r = renders[k];
        RenderJob& job = r.job;
        const std::string requested = std::to_string(job.width) + "x" + std::to_string(job.height);
        if (cl.width > 0) {
            job.width = cl.width;
            job.height = cl.height;
        } else if (cl.preview) {
            std::tie(job.width, job.height) = previewSize(job.width, job.height);
        }
        // A preview says what it is, with the settings it rendered with.
        if (cl.preview && !cl.quiet)
            std::fprintf(stderr,
                         "rt: preview: %dx%d (%s), %s; drop --preview for the full render\n",
                         job.width, job.height,
                         cl.width > 0 ? "--size" : ("a quarter of " + requested).c_str(),
                         previewSettings(cl).c_str());
        checkImageSize(job.width, job.height, job.where + ": ");
        // The film and the PNG encoder's buffers must fit beside the scene, before they exist.
        cl.memory.require(saturatingProduct(static_cast<std::uint64_t>(job.width) * job.height,
                                            kImageBytesPerPixel),
                          job.where,
                          "the image of " + std::to_string(job.width) + "x" +
                              std::to_string(job.height) + " pixels");
        const std::string output = outputPath(cl, job, k, renders.size());
        // A format a chapter writes (chapter 12: .hdr) needs that chapter switched on; --output
        // let it pass because the chapter is built.
        const OutputFormat* format = outputFormatFor(features.on(), output);
        if (!format && !cl.output.empty() && !hasPngExtension(output)) {
            const OutputFormat* off = outputFormatFor(features.built(), output);
            std::string owner;
            for (const Feature& f : features.built())
                for (const OutputFormat& o : f.outputFormats)
                    if (&o == off)
                        owner = std::string(f.name) + ", chapter " + std::to_string(f.chapter);
            throw InputError("--output " + output + ": writing " + (off ? off->description : "it") +
                             " needs " + owner + ", which --features switched off");
        }
        // Refuse an output path that cannot be written before spending time on the render.
        const std::filesystem::path folder = std::filesystem::path(output).parent_path();
        if (!folder.empty() && !std::filesystem::is_directory(folder))
            throw InputError(job.where + ": cannot write " + output + ": the folder '" +
                             folder.string() + "' does not exist");

        // Build the world: instances, lights, settings, the features' shading, the aggregate.
        t0 = Clock::now();
        // --spp reaches the features too, as the option "spp": a pixel sampler (chapter 8)
        // that takes n x n rays reads it.
        std::map<std::string, std::string> featureOptions = cl.featureOptions;
        if (cl.samplesPerPixel > 0) featureOptions["spp"] = std::to_string(cl.samplesPerPixel);
        const std::unique_ptr<World> world =
            buildWorld(std::move(r), features, featureOptions, cl.maxDepth);
        const Scene& scene = world->scene;
        const Pipeline& pipeline = world->pipeline;
        const double buildSeconds = since(t0);
        // A post-process (chapter 12's tone map) needs working memory beside the film.
        if (pipeline.postProcess) {
            const RenderJob& built = world->source.job;
            cl.memory.require(
                saturatingProduct(static_cast<std::uint64_t>(built.width) * built.height,
                                  kImageBytesPerPixel + pipeline.postProcess->bytesPerPixel()),
                built.where,
                "the image of " + std::to_string(built.width) + "x" + std::to_string(built.height) +
                    " pixels and its tone map");
        }

        const PinholeCamera camera(world->source.job.camera, world->source.job.width,
                                   world->source.job.height);
        // Say what would surprise; the image is made all the same.
        for (const std::string& warning : world->warnings)
            std::fprintf(stderr, "rt: warning: %s\n", warning.c_str());
        for (const std::string& warning :
             renderWarnings(world->source.job, scene.instances, camera, features, output))
            std::fprintf(stderr, "rt: warning: %s\n", warning.c_str());
        if (pipeline.radiance)  // path traced (chapter 18): materials that would make light
            for (const std::string& warning : energyWarnings(world->source.job, scene.instances))
                std::fprintf(stderr, "rt: warning: %s\n", warning.c_str());
        if (format && pipeline.postProcess)
            std::fprintf(stderr,
                         "rt: warning: %s: the tone map is not applied to %s, which keeps the "
                         "film's linear radiance; write a .png to see it\n",
                         world->source.job.where.c_str(), output.c_str());
        RenderSettings settings;
        settings.threads = cl.threads;
        settings.seed = cl.seed;
        settings.samplesPerPixel = cl.samplesPerPixel > 0 ? cl.samplesPerPixel : 1;
        settings.progress = !cl.quiet && isatty(STDERR_FILENO);
        settings.shouldStop = stopRequested;
        settings.memory = &cl.memory;
        settings.cluster = &cluster;
        // Only MPI renders keep a journal or compare ranks: one process reads no file twice.
        const RenderIdentity identity =
            cluster.distributed() ? renderIdentity(cl, world->source.job, output, load.files)
                                  : RenderIdentity{output, {}};
        settings.identity = &identity;
        settings.resume = cl.resume;
        settings.target = targetErrorFor(cl, world->source.job);
        if (cl.aovSampleCount && !settings.target.on())
            throw InputError(
                "--aov sample-count maps the samples of a --target-error render; "
                "give --target-error E (or the scene's target_error)");
        // The samples each pixel took, and its estimated error: under MPI each rank records
        // its own tiles', and the first gathers them after the render.
        std::optional<SampleMap> sampleMap;
        if (settings.target.on()) {
            sampleMap.emplace(world->source.job.width, world->source.job.height,
                              settings.target.pilotSamples());
            settings.sampleMap = &*sampleMap;
        }
        PartialImage partial;
        if (cl.partial) settings.partial = &partial;
        RayCounters counters;
        t0 = Clock::now();
        std::optional<Image> rendered;
        try {
            rendered.emplace(render(scene, pipeline, camera, world->source.job.width,
                                    world->source.job.height, settings, counters));
        } catch (const RenderStopped& stopped) {
            // Under --partial, keep what was rendered, under a name that says so.
            if (partial.image) writePartial(partial, output, stderr);
            // Say why: a pending signal, else the time limit. The image itself is not written;
            // under MPI the cluster says what the journal holds and how to resume.
            if (const int signal = pendingInterrupt()) throw interruptedBy(signal);
            throw RenderStopped(
                "stopped after the time limit of " +
                    std::to_string(static_cast<long long>(cl.timeLimit)) +
                    " s (--time-limit), without writing an image" +
                    (cluster.distributed() ? "; " + std::string(stopped.what()) : std::string()),
                124);
        }
        Image& image = *rendered;
        const double renderSeconds = since(t0);
        // Under MPI only rank 0 holds the whole film; it writes the image and the report.
        if (!cluster.writesOutput()) continue;

        // The post-process (chapter 12's tone map) turns the film into display values; a
        // format of its own (.hdr) keeps the film's linear radiance instead.
        t0 = Clock::now();
        if (!format && pipeline.postProcess) pipeline.postProcess->apply(image);
        const double postSeconds = since(t0);
        t0 = Clock::now();
        try {
            if (format)
                format->write(image, output);
            else
                writePng(image, output);
        } catch (const InputError& e) {
            throw InputError(world->source.job.where + ": " + e.what());
        }
        const double writeSeconds = since(t0);
        if (cl.aovSampleCount) {
            const std::string path = sampleMapPath(output);
            writePng(sampleHeatMap(*sampleMap), path);
            if (!cl.quiet) std::fprintf(stderr, "wrote %s (samples per pixel)\n", path.c_str());
        }
        cluster.imageWritten();
        if (!cl.quiet)
            std::fprintf(stderr, "wrote %s (%dx%d)\n", output.c_str(), world->source.job.width,
                         world->source.job.height);

        if (cl.stats) {
            std::fprintf(stderr, "stats for %s\n", output.c_str());
            std::fprintf(stderr, "  rays      ");
            for (size_t i = 0; i < counters.count.size(); ++i)
                if (counters.count[i])
                    std::fprintf(stderr, " %s %llu", kRayKindNames[i],
                                 static_cast<unsigned long long>(counters.count[i]));
            std::fprintf(stderr, " (total %llu)\n",
                         static_cast<unsigned long long>(counters.total()));
            if (k == 0) {
                std::fprintf(stderr, "  era        %s\n", load.era.line.c_str());
                std::fprintf(
                    stderr,
                    "  time       threads %.3f s, lua %.3f s, load %.3f s, mesh bvh %.3f s\n",
                    threadSeconds, loadTimes.total - loadTimes.meshLoad - loadTimes.meshBvh,
                    loadTimes.meshLoad, loadTimes.meshBvh);
            }
            std::fprintf(stderr, "  time       build %.3f s, render %.4f s, write %.3f s\n",
                         buildSeconds, renderSeconds, writeSeconds);
            if (pipeline.postProcess)
                std::fprintf(stderr, "  time       post-process %.3f s\n", postSeconds);
            for (const auto& pass : pipeline.prePasses)
                if (const std::string line = pass->statistics(); !line.empty())
                    std::fprintf(stderr, "  %s\n", line.c_str());
            if (settings.target.on()) {
                std::fprintf(stderr,
                             "  target     error %.4g; a pilot of %d samples (%d plan, %d kept), "
                             "then %d to %d per pixel\n",
                             settings.target.error, settings.target.pilotSamples(),
                             settings.target.planningSamples(), settings.target.keptPilotSamples(),
                             settings.target.freshFloor(), settings.target.maxSamples);
                std::fprintf(
                    stderr, "  samples    mean %.1f, max %u per pixel; estimated RMS error %.4g",
                    sampleMap->meanSamples(), sampleMap->maxSamples(), sampleMap->rmsError());
                const std::size_t all = sampleMap->samples.size();
                if (const std::size_t n = sampleMap->recordedPixels(); n < all)
                    std::fprintf(stderr,
                                 " (over the %zu of %zu pixels rendered now; --resume "
                                 "took the others from the journal)",
                                 n, all);
                std::fputc('\n', stderr);
            }
            std::fprintf(stderr, "  speed      %.2f Mrays/s\n",
                         counters.total() / std::max(renderSeconds, 1e-9) / 1e6);
            std::fprintf(stderr, "  instances  %zu\n", scene.instances.size());
            const std::string structure = scene.aggregate->statistics();
            if (!structure.empty()) std::fprintf(stderr, "  bvh        %s\n", structure.c_str());
            std::fprintf(stderr, "  memory     peak %.1f MiB\n", peakMemoryMiB());
            for (const std::string& line : cluster.statistics())
                std::fprintf(stderr, "  %s\n", line.c_str());
        }
    }
    // Under --lenient, stderr ends with everything that was ignored: unknown names, then
    // known calls whose arguments could not be read.
    if (!load.ignored.empty() || !load.unreadable.empty()) {
        const size_t names = load.ignored.size(), calls = load.unreadable.size();
        std::string what;
        if (names) what = std::to_string(names) + " unknown name" + (names == 1 ? "" : "s");
        if (names && calls) what += " and ";
        if (calls)
            what += "unreadable arguments in " + std::to_string(calls) + " call" +
                    (calls == 1 ? "" : "s");
        std::fprintf(stderr, "rt: --lenient ignored %s:\n", what.c_str());
        for (const auto* list : {&load.ignored, &load.unreadable})
            for (const std::string& line : *list) std::fprintf(stderr, "rt:   %s\n", line.c_str());
    }
    return 0;
}

}  // namespace
}  // namespace rb

namespace {

/// Say why the run failed, as one line on `out`.
void report(std::exception_ptr failure, std::FILE* out) {
    try {
        std::rethrow_exception(failure);
    } catch (const rb::RenderStopped& e) {
        std::fprintf(out, "rt: %s\n", e.what());
    } catch (const rb::InputError& e) {
        std::fprintf(out, "rt: error: %s\n", e.what());
    } catch (const std::bad_alloc&) {
        std::fprintf(out, "rt: error: out of memory\n");
    } catch (const std::exception& e) {
        std::fprintf(out, "rt: error: %s\n", e.what());
    }
    std::fflush(out);
}

/// End the run on every process of the cluster: they agree on whether one failed, the lowest
/// failing process says why, once, and all end with its exit code. Returns the exit code.
int finish(rb::Cluster& cluster, std::exception_ptr failure, int code) {
    try {
        try {
            if (failure) std::rethrow_exception(failure);
        } catch (const rb::AgreedFailure&) {
            throw;
        } catch (...) {
            cluster.agree(std::current_exception());  // throws AgreedFailure
        }
        cluster.agree(nullptr);
        return code;
    } catch (const rb::AgreedFailure& agreed) {
        if (agreed.cause) report(agreed.cause, cluster.errorStream());
        return agreed.exitCode;
    }
}

}  // namespace

int main(int argc, char** argv) {
    // Past a file-size limit (ulimit -f), let write() fail with EFBIG, reported like a full
    // disk, instead of SIGXFSZ killing rt with a core dump.
    std::signal(SIGXFSZ, SIG_IGN);
    std::unique_ptr<rb::Cluster> cluster;
    try {
        cluster = rb::joinCluster(argc, argv);
    } catch (...) {
        report(std::current_exception(), stderr);
        return 1;
    }
    std::exception_ptr failure;
    int code = 0;
    try {
        code = rb::run(argc, argv, *cluster);
    } catch (...) {
        failure = std::current_exception();
    }
    return finish(*cluster, failure, code);
}
