#include "core/render.h"

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <mutex>
#include <span>
#include <string>
#include <vector>

#include "core/camera_rays.h"
#include "core/interrupt.h"
#include "core/pixel_sampler.h"

namespace rb {

std::vector<ImageTile> tilesInRenderOrder(int width, int height) {
    // Step 1: cut the image into tiles in scanline order; the last row and column of tiles
    // may be narrower.
    const int tilesX = (width + kTileSize - 1) / kTileSize;
    const int tilesY = (height + kTileSize - 1) / kTileSize;
    const int count = tilesX * tilesY;
    const int strata = std::min(kProgressStrata, count);
    std::vector<ImageTile> scanline;
    scanline.reserve(count);
    for (int i = 0; i < count; ++i) {
        ImageTile t;
        t.x0 = (i % tilesX) * kTileSize;
        t.y0 = (i / tilesX) * kTileSize;
        t.x1 = std::min(width, t.x0 + kTileSize);
        t.y1 = std::min(height, t.y0 + kTileSize);
        // Step 2: band the scanline sequence into equal strata for the progress estimate.
        t.stratum = static_cast<int>(static_cast<std::int64_t>(i) * strata / count);
        scanline.push_back(t);
    }
    // Step 3: visit them in bit-reversed order, so any prefix is spread over the image.
    std::vector<ImageTile> tiles;
    tiles.reserve(count);
    for (int i : progressiveOrder(count)) tiles.push_back(scanline[i]);
    return tiles;
}

std::vector<WorkUnit> workUnits(const std::vector<ImageTile>& tiles) {
    std::vector<WorkUnit> units;
    units.reserve(tiles.size());
    for (const ImageTile& t : tiles) units.push_back({static_cast<double>(t.pixels()), t.stratum});
    return units;
}

namespace {

/// Seconds on the steady clock since `start`.
double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// Draws "[#####     ]  48%  elapsed 3.1 s  ETA 3.4 s  12.3 Mrays/s" on stderr, at most ten
/// times a second. Any thread may report a finished tile; a lock serialises the reports
/// (one per tile, so it is never contended for long).
class ProgressBar {
  public:
    /// A bar for the units of `tiles`; draws nothing unless `enabled`.
    ProgressBar(bool enabled, const std::vector<ImageTile>& tiles, const TargetError& target,
                std::vector<WorkUnit> units)
        : enabled_(enabled), estimator_(std::move(units)), tiles_(tiles), target_(target) {}

    /// Record that a thread starts tile `index`.
    void tileStarted(int index) {
        if (!enabled_) return;
        const std::lock_guard<std::mutex> lock(mutex_);
        estimator_.start(index, secondsSince(start_));
    }

    /// Record that tile `index` is finished, having traced `rays` rays; under a target error,
    /// the sum of its pixels' variances of the mean is `varianceSum`.
    void tileDone(int index, std::uint64_t rays, double varianceSum = 0.0) {
        if (!enabled_) return;
        const std::lock_guard<std::mutex> lock(mutex_);
        const double elapsed = secondsSince(start_);
        estimator_.finish(index, elapsed);
        rays_ += rays;
        varianceSum_ += varianceSum;
        pixelsDone_ += tiles_[index].pixels();
        if (throttle_.due(elapsed) && elapsed > 0.0) draw(elapsed);
    }

    /// Clear the line, leaving the cursor where the bar began.
    void finish() {
        if (!enabled_ || width_ == 0) return;
        std::fprintf(stderr, "\r%*s\r", width_, "");
        std::fflush(stderr);
    }

  private:
    /// Redraw the line over the previous one.
    void draw(double elapsed) {
        ProgressReport report;
        report.fraction = estimator_.fractionDone(elapsed);
        report.elapsedSeconds = elapsed;
        // Until every band of the image has been measured, an ETA would be a guess.
        if (estimator_.representative()) report.etaSeconds = estimator_.secondsLeft(elapsed);
        report.raysPerSecond = static_cast<double>(rays_) / elapsed;
        // Under a target error: the RMS error of the pixels finished so far, against it.
        if (target_.on() && pixelsDone_ > 0) {
            report.error = std::sqrt(varianceSum_ / static_cast<double>(pixelsDone_));
            report.targetError = target_.error;
        }
        const std::string line = formatProgressLine(report);
        // Pad with spaces to cover a longer previous line.
        const int length = static_cast<int>(line.size());
        std::fprintf(stderr, "\r%s%*s", line.c_str(), std::max(0, width_ - length), "");
        std::fflush(stderr);
        width_ = std::max(width_, length);
    }

    bool enabled_;
    std::mutex mutex_;
    WorkEstimator estimator_;       // guarded by mutex_
    RedrawThrottle throttle_{0.1};  // guarded by mutex_: at most 10 redraws a second
    const std::vector<ImageTile>& tiles_;
    TargetError target_;
    std::uint64_t rays_ = 0;        // guarded by mutex_
    double varianceSum_ = 0.0;      // guarded by mutex_: finished pixels' variances of the mean
    std::uint64_t pixelsDone_ = 0;  // guarded by mutex_
    int width_ = 0;                 // guarded by mutex_: widest line drawn
    std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

/// Render the pixels of one tile into `image`, counting rays into `rays`, and asking `stop`
/// after each. A camera-ray generator (`lens`, or null for the pinhole) may ask for more rays
/// per pixel than `spp`.
void renderTile(const ImageTile& tile, const Integrator& integrator, const PinholeCamera& camera,
                const CameraRayGenerator* lens, int width, int spp, std::uint64_t seed,
                Image& image, RayCounters& rays, PixelStop& stop) {
    const int count = lens ? std::max(spp, lens->raysPerPixel()) : spp;
    for (int y = tile.y0; y < tile.y1; ++y)
        for (int x = tile.x0; x < tile.x1; ++x) {
            const std::uint64_t pixelIndex = static_cast<std::uint64_t>(y) * width + x;
            Colour sum(0.0);
            for (int s = 0; s < count; ++s) {
                Sampler sampler(seed, pixelIndex, s);
                // One sample: the pixel centre (A4), or a uniformly jittered position.
                const Vec2 offset = spp == 1 ? Vec2(0.5) : sampler.next2D();
                const Vec2 film(x + offset.x, y + offset.y);
                const Ray ray =
                    lens ? lens->generate(camera, film, {seed, pixelIndex, s, count}, sampler)
                         : camera.generateRay(film.x, film.y);
                rays.add(RayKind::Camera);
                sum += integrator.trace(ray, sampler, rays, 0);
            }
            // One sample is its own average (no division, the same bits).
            image.set(x, y, count == 1 ? sum : sum / static_cast<double>(count));
            stop.afterPixel(rays.total());
        }
}

// [target-error-tile]
/// A permutation of 0 … m − 1, drawn from `sampler` (Fisher and Yates's shuffle).
std::vector<std::uint32_t> shuffled(int m, Sampler& sampler) {
    std::vector<std::uint32_t> order(static_cast<std::size_t>(m));
    for (int i = 0; i < m; ++i) order[i] = static_cast<std::uint32_t>(i);
    for (int i = m - 1; i > 0; --i) {
        const int j = std::min(i, static_cast<int>(sampler.next1D() * (i + 1)));
        std::swap(order[i], order[j]);
    }
    return order;
}

/// Streams of rb::Sampler far beyond any sample's: the shuffles of a pixel's groups.
constexpr std::uint64_t kShuffleStream = std::uint64_t{1} << 40;

/// The mean of one group of m samples of pixel (x, y), sample streams first … first + m − 1:
/// a Latin hypercube over the pixel, its x and its y each cut into m strata that the group's
/// samples take one each, in an order shuffled per group; through a lens (chapter 13) its own
/// m strata are paired with the samples the same way (RaySlot index i of m). Each sample is
/// also added to `spread`.
Colour sampleGroup(int x, int y, int group, int first, int m, const Integrator& integrator,
                   const PinholeCamera& camera, const CameraRayGenerator* lens, int width,
                   std::uint64_t seed, RayCounters& rays, RunningMoments& spread) {
    const std::uint64_t pixelIndex = static_cast<std::uint64_t>(y) * width + x;
    Sampler shuffle(seed, pixelIndex, kShuffleStream + group);
    const std::vector<std::uint32_t> columns = shuffled(m, shuffle), rows = shuffled(m, shuffle);
    // The lens's pairing key: the pixel's and the group's.
    const std::uint64_t lensKey = pixelIndex ^ (static_cast<std::uint64_t>(group + 1) << 48);
    Colour sum(0.0);
    for (int i = 0; i < m; ++i) {
        Sampler sampler(seed, pixelIndex, first + i);
        const Vec2 u = sampler.next2D();
        const Vec2 film(x + (columns[i] + u.x) / m, y + (rows[i] + u.y) / m);
        const Ray ray = lens ? lens->generate(camera, film, {seed, lensKey, i, m}, sampler)
                             : camera.generateRay(film.x, film.y);
        rays.add(RayKind::Camera);
        const Colour value = integrator.trace(ray, sampler, rays, 0);
        spread.add(value);
        sum += value;
    }
    return sum / static_cast<double>(m);
}

/// Two independent groups of m samples each (groups `group` and `group` + 1, sample streams
/// first … first + 2m − 1), and their mean. Strata lower the noise of each group's mean, and
/// since the groups are independent, the squared difference of their means over 4 is an
/// unbiased estimate of the variance of the pixel's mean, strata or not (one degree of
/// freedom a pixel; the image's sum of them has many). `spread` gets every sample.
PixelEstimate sampleTwoGroups(int x, int y, int group, int first, int m,
                              const Integrator& integrator, const PinholeCamera& camera,
                              const CameraRayGenerator* lens, int width, std::uint64_t seed,
                              RayCounters& rays, RunningMoments& spread) {
    const Colour a =
        sampleGroup(x, y, group, first, m, integrator, camera, lens, width, seed, rays, spread);
    const Colour b = sampleGroup(x, y, group + 1, first + m, m, integrator, camera, lens, width,
                                 seed, rays, spread);
    const Colour d = a - b;
    return {0.5 * (a + b), (d.r * d.r + d.g * d.g + d.b * d.b) / 12.0};
}

/// Stage 1's result for the image (row-major): each pixel's kept pilot estimate, which is
/// part of its final one, its kept samples' channel variance s², which plans its neighbours,
/// and its planning group's, which plans it.
struct PilotImage {
    std::vector<PixelEstimate> estimate;
    std::vector<float> kept;
    std::vector<float> planning;
    PilotCost cost;  ///< Rays a sample, of the planning group and of the kept pilot.
};

/// The kept pilot's groups; the fresh samples' are 0 and 1, the planning group's 4.
constexpr int kPilotGroup = 2;
constexpr int kPlanningGroup = 4;

/// Stage 1 for one tile: each pixel's pilot. Its planning group (samples 0 … a − 1) gives
/// a spread that plans the pixel and is set aside; its two kept groups (a … a + q − 1) come
/// as the fresh ones do, make part of the pixel, and their spread plans its neighbours. All
/// go into `pilot`; `stop` is asked after each pixel.
void pilotTile(const ImageTile& tile, const Integrator& integrator, const PinholeCamera& camera,
               const CameraRayGenerator* lens, int width, std::uint64_t seed,
               const TargetError& target, PilotImage& pilot, RayCounters& rays, PixelStop& stop) {
    const int a = target.planningSamples(), m = target.keptPilotSamples() / 2;
    for (int y = tile.y0; y < tile.y1; ++y)
        for (int x = tile.x0; x < tile.x1; ++x) {
            const std::size_t i = static_cast<std::size_t>(y) * width + x;
            RunningMoments planning, kept;
            const std::uint64_t start = rays.total();
            sampleGroup(x, y, kPlanningGroup, 0, a, integrator, camera, lens, width, seed, rays,
                        planning);
            const std::uint64_t planned = rays.total();
            pilot.planning[i] = static_cast<float>(planning.channelVariance());
            pilot.estimate[i] = sampleTwoGroups(x, y, kPilotGroup, a, m, integrator, camera, lens,
                                                width, seed, rays, kept);
            pilot.kept[i] = static_cast<float>(kept.channelVariance());
            // What a sample cost, in rays (counted, so the same on any machine or thread).
            pilot.cost.planning[i] = static_cast<float>(planned - start) / a;
            pilot.cost.kept[i] = static_cast<float>(rays.total() - planned) / (2 * m);
            stop.afterPixel(rays.total());
        }
}

/// Stage 3 for one tile: each pixel's planned fresh samples, after the pilot's; the pixel is
/// the mean of them and the kept pilot's. Returns the sum over the tile's pixels of their
/// estimated variance of the mean (for the progress line). `stop` is asked after each pixel.
double renderTileToError(const ImageTile& tile, const Integrator& integrator,
                         const PinholeCamera& camera, const CameraRayGenerator* lens, int width,
                         std::uint64_t seed, const TargetError& target, const PilotImage& pilot,
                         const std::vector<std::uint32_t>& plan, Image& image, SampleMap* map,
                         RayCounters& rays, PixelStop& stop) {
    const int p = target.pilotSamples(), q = target.keptPilotSamples();
    double varianceSum = 0.0;
    for (int y = tile.y0; y < tile.y1; ++y)
        for (int x = tile.x0; x < tile.x1; ++x) {
            const std::size_t i = static_cast<std::size_t>(y) * width + x;
            const auto count = static_cast<int>(plan[i]);
            RunningMoments unused;
            const PixelEstimate fresh = sampleTwoGroups(x, y, 0, p, count / 2, integrator, camera,
                                                        lens, width, seed, rays, unused);
            const PixelEstimate e = withPilot(pilot.estimate[i], q, fresh, count);
            image.set(x, y, e.mean);
            if (map) map->record(x, y, count, e.varianceOfMean);
            varianceSum += e.varianceOfMean;
            stop.afterPixel(rays.total());
        }
    return varianceSum;
}
// [target-error-tile]

/// Render one tile with the pipeline's pixel sampler (chapter 8) when one is installed, else
/// with the core's loop, so a scene without antialiasing pays one test per tile. Under a target
/// error the core's adaptive loop renders it (returning its variance sum; 0 otherwise). When
/// the render is to stop, throws TileAbandoned with the tile half-done.
double renderImageTile(const ImageTile& tile, const Pipeline& pipeline,
                       const Integrator& integrator, const PinholeCamera& camera, int width,
                       int height, const RenderSettings& settings, const PilotImage& pilot,
                       const std::vector<std::uint32_t>& plan, SampleMap* map, Image& image,
                       RayCounters& rays, PixelStop& stop) {
    const int spp = std::max(1, settings.samplesPerPixel);
    const std::uint64_t seed = settings.seed;
    if (settings.target.on())
        return renderTileToError(tile, integrator, camera, pipeline.cameraRays.get(), width, seed,
                                 settings.target, pilot, plan, image, map, rays, stop);
    if (pipeline.pixelSampler)
        pipeline.pixelSampler->renderTile(tile, integrator, camera, width, height, seed, image,
                                          rays, stop);
    else
        renderTile(tile, integrator, camera, pipeline.cameraRays.get(), width, spp, seed, image,
                   rays, stop);
    return 0.0;
}

/// Under many processes, the samples each rank recorded for its tiles, into the first's `map`.
/// Collective: every process calls it after the same renderTiles.
void gatherSampleMap(Cluster& cluster, SampleMap& map) {
    const std::vector<std::byte> mine = map.packRecorded();
    for (const std::vector<std::byte>& part : cluster.gatherToFirst(mine)) map.recordPacked(part);
}

/// Black out a tile a stop left half-done, as the tiles not reached are.
void dropTile(const ImageTile& tile, Image& image) {
    for (int y = tile.y0; y < tile.y1; ++y)
        for (int x = tile.x0; x < tile.x1; ++x) image.set(x, y, Colour(0.0));
}

/// The progress estimator's view of a target-error render: each tile's work is the fresh
/// samples planned for its pixels.
std::vector<WorkUnit> plannedWork(const std::vector<ImageTile>& tiles,
                                  const std::vector<std::uint32_t>& plan, int width) {
    std::vector<WorkUnit> units;
    units.reserve(tiles.size());
    for (const ImageTile& t : tiles) {
        double samples = 0.0;
        for (int y = t.y0; y < t.y1; ++y)
            for (int x = t.x0; x < t.x1; ++x)
                samples += plan[static_cast<std::size_t>(y) * width + x];
        units.push_back({samples, t.stratum});
    }
    return units;
}

/// One pixel's pilot as the processes exchange it.
struct PackedPilot {
    double r, g, b, varianceOfMean;
    float kept, planning, planningCost, keptCost;
};

/// Stage 1 of a target-error render: every pixel's pilot mean and variances. On one process
/// the tiles go to threads; under a cluster, process r takes tiles r, r + size, ... and every
/// process receives every tile's values. Throws RenderStopped when asked to stop, and a
/// tile's exception after the others finish.
PilotImage pilotPass(const std::vector<ImageTile>& tiles, const Integrator& integrator,
                     const PinholeCamera& camera, const CameraRayGenerator* lens, int width,
                     int height, const RenderSettings& settings,
                     [[maybe_unused]] int threads,  // The WebAssembly build has no OpenMP.
                     std::vector<RayCounters>& perThread) {
    const auto pixels = static_cast<std::size_t>(width) * height;
    PilotImage pilot{std::vector<PixelEstimate>(pixels),
                     std::vector<float>(pixels, 0.0f),
                     std::vector<float>(pixels, 0.0f),
                     {std::vector<float>(pixels, 0.0f), std::vector<float>(pixels, 0.0f)}};
    Cluster* cluster =
        settings.cluster && settings.cluster->distributed() ? settings.cluster : nullptr;
    const int rank = cluster ? cluster->rank() : 0, size = cluster ? cluster->size() : 1;
    const int count = static_cast<int>(tiles.size());
    std::atomic<bool> stopped{false}, failed{false};
    std::exception_ptr failure;
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
    for (int k = rank; k < count; k += size) {
        if (stopped.load(std::memory_order_relaxed) || failed.load(std::memory_order_relaxed))
            continue;
        if (settings.shouldStop && settings.shouldStop()) {
            stopped = true;
            continue;
        }
        try {
            PixelStop stop(settings.shouldStop, stopped);
            pilotTile(tiles[k], integrator, camera, lens, width, settings.seed, settings.target,
                      pilot, perThread[omp_get_thread_num()], stop);
        } catch (const TileAbandoned&) {
            // stopped is set: the pilot is not used.
        } catch (...) {
#pragma omp critical(rb_render_failure)
            if (!failure) failure = std::current_exception();
            failed = true;
        }
    }
    if (failure) std::rethrow_exception(failure);
    if (stopped) throw RenderStopped("the render was stopped before it finished", 1);
    if (!cluster) return pilot;
    // Under a cluster: this process's tiles' values, in tile order, to every process.
    std::vector<PackedPilot> mine;
    for (int k = rank; k < count; k += size)
        for (int y = tiles[k].y0; y < tiles[k].y1; ++y)
            for (int x = tiles[k].x0; x < tiles[k].x1; ++x) {
                const std::size_t i = static_cast<std::size_t>(y) * width + x;
                const PixelEstimate& e = pilot.estimate[i];
                mine.push_back({e.mean.r, e.mean.g, e.mean.b, e.varianceOfMean, pilot.kept[i],
                                pilot.planning[i], pilot.cost.planning[i], pilot.cost.kept[i]});
            }
    const std::vector<std::byte> all = cluster->joinInOrder(std::as_bytes(std::span(mine)));
    std::size_t at = 0;
    for (int r = 0; r < size; ++r)
        for (int k = r; k < count; k += size)
            for (int y = tiles[k].y0; y < tiles[k].y1; ++y)
                for (int x = tiles[k].x0; x < tiles[k].x1; ++x) {
                    PackedPilot one;
                    std::memcpy(&one, all.data() + at, sizeof one);
                    at += sizeof one;
                    const std::size_t i = static_cast<std::size_t>(y) * width + x;
                    pilot.estimate[i] = {Colour(one.r, one.g, one.b), one.varianceOfMean};
                    pilot.kept[i] = one.kept;
                    pilot.planning[i] = one.planning;
                    pilot.cost.planning[i] = one.planningCost;
                    pilot.cost.kept[i] = one.keptCost;
                }
    return pilot;
}

}  // namespace

void startRenderThreads(int threads) {
    // --threads holds for every later parallel loop too (chapter 12's tone map).
    if (threads > 0) omp_set_num_threads(threads);
    // Unused without OpenMP (the WebAssembly build).
    [[maybe_unused]] const int n = threads > 0 ? threads : omp_get_max_threads();
    std::atomic<int> started{0};
#pragma omp parallel num_threads(n)
    ++started;  // a body, so the region is not optimised away
}

std::string partialPath(const std::string& output) {
    std::filesystem::path path(output);
    return path.replace_extension(".partial.png").string();
}

void writePartial(const PartialImage& partial, const std::string& output, std::FILE* log) {
    const std::string path = partialPath(output);
    writePng(*partial.image, path);
    std::fprintf(log, "rt: wrote the %zu of %zu tiles rendered so far to %s\n", partial.tilesDone,
                 partial.tiles, path.c_str());
}

// [render-loop]
Image render(const Scene& scene, const Pipeline& pipeline, const PinholeCamera& camera, int width,
             int height, const RenderSettings& settings, RayCounters& counters) {
    // Work before the first camera ray (chapter 16's photons), with the same seed.
    for (const auto& pass : pipeline.prePasses)
        pass->run(
            scene, pipeline,
            {settings.seed, camera, width, height, settings.memory, counters, settings.cluster});
    Image image(width, height);
    const Integrator integrator(scene, pipeline);
    const int threads = settings.threads > 0 ? settings.threads : omp_get_max_threads();
    std::vector<RayCounters> perThread(threads);
    const std::vector<ImageTile> tiles = tilesInRenderOrder(width, height);
    if (settings.tileThreads) settings.tileThreads->assign(tiles.size(), -1);
    // Under a target error (--target-error): the pilot, and each pixel's plan of fresh samples.
    PilotImage pilot;
    std::vector<std::uint32_t> plan;
    if (settings.target.on()) {
        // The pilot runs before the bar can price the work: say what is happening meanwhile.
        if (settings.progress)
            std::fprintf(stderr,
                         "rt: target error %.3g: a pilot of %d samples a pixel measures the "
                         "noise, then the bar follows the planned samples\n",
                         settings.target.error, settings.target.pilotSamples());
        pilot = pilotPass(tiles, integrator, camera, pipeline.cameraRays.get(), width, height,
                          settings, threads, perThread);
        plan = planSamples(pilot.planning, pilot.kept, width, height, settings.target, &pilot.cost);
    }
    ProgressBar progress(settings.progress, tiles, settings.target,
                         plan.empty() ? workUnits(tiles) : plannedWork(tiles, plan, width));
    // Many processes (MPI): the cluster deals out the tiles and brings them back.
    if (settings.cluster && settings.cluster->distributed()) {
        // A tile asks after each pixel here too (a rank's --time-limit; signals are the
        // cluster's): a half-done one throws TileAbandoned, and its lease is neither
        // journaled nor sent (src/mpi/mpi_cluster.cpp).
        std::atomic<bool> clusterStopped{false};
        const auto renderOne = [&](int k, Image& film, RayCounters& rays) {
            PixelStop stop(settings.shouldStop, clusterStopped);
            renderImageTile(tiles[k], pipeline, integrator, camera, width, height, settings, pilot,
                            plan, settings.sampleMap, film, rays, stop);
        };
        std::atomic<std::size_t> tilesDone{0};  // in this film (rank 0: every rank's)
        const auto started = [&](int k) { progress.tileStarted(k); };
        const auto finished = [&](int k, std::uint64_t rays) {
            progress.tileDone(k, rays);
            ++tilesDone;
        };
        try {
            settings.cluster->renderTiles(
                {tiles, threads, settings.resume, *settings.identity, renderOne,
                 settings.shouldStop, started, finished, settings.partial != nullptr},
                image, counters);
        } catch (const RenderStopped&) {
            // Stopped (--time-limit): every lease came back, so the film holds what is done.
            progress.finish();
            if (settings.partial) *settings.partial = {std::move(image), tilesDone, tiles.size()};
            throw;
        } catch (...) {
            progress.finish();
            throw;
        }
        progress.finish();
        // Each rank recorded the samples of its own tiles: the first gathers them (--stats).
        if (settings.sampleMap) gatherSampleMap(*settings.cluster, *settings.sampleMap);
        return image;
    }

    // Tiles go to threads dynamically, in progressive order. Nothing a pixel computes depends
    // on which thread runs it or when: its random numbers come from (seed, pixel, sample), so
    // any schedule and any tile order give the same image.
    // A stop (Ctrl-C, SIGTERM, --time-limit) skips the tiles not yet started (OpenMP cannot
    // leave a parallel loop early), and the running ones give up after the pixel they are on
    // (PixelStop): a half-done tile is dropped, so a partial image holds whole tiles only.
    // An exception may not leave an OpenMP region (it would end the program): a tile that
    // throws (an exercise stub, std::bad_alloc) keeps the first exception, the other tiles are
    // skipped, and it is thrown again after the loop.
    std::atomic<bool> stopped{false};
    std::atomic<bool> failed{false};
    std::exception_ptr failure;
    std::atomic<std::size_t> tilesDone{0};
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
    for (int k = 0; k < static_cast<int>(tiles.size()); ++k) {
        if (stopped.load(std::memory_order_relaxed) || failed.load(std::memory_order_relaxed))
            continue;
        if (settings.shouldStop && settings.shouldStop()) {
            stopped = true;
            continue;
        }
        RayCounters& rays = perThread[omp_get_thread_num()];
        const std::uint64_t raysBefore = rays.total();
        progress.tileStarted(k);
        if (settings.tileThreads) (*settings.tileThreads)[k] = omp_get_thread_num();
        double varianceSum = 0.0;
        try {
            PixelStop stop(settings.shouldStop, stopped);
            varianceSum =
                renderImageTile(tiles[k], pipeline, integrator, camera, width, height, settings,
                                pilot, plan, settings.sampleMap, image, rays, stop);
        } catch (const TileAbandoned&) {
            dropTile(tiles[k], image);  // stopped is set
            continue;
        } catch (...) {
#pragma omp critical(rb_render_failure)
            if (!failure) failure = std::current_exception();
            failed = true;
            continue;
        }
        progress.tileDone(k, rays.total() - raysBefore, varianceSum);
        ++tilesDone;
    }
    progress.finish();
    if (failure) std::rethrow_exception(failure);
    for (const RayCounters& c : perThread) counters.merge(c);
    if (stopped) {
        // Every tile that started has finished or been dropped: hand over the image, if asked.
        if (settings.partial) *settings.partial = {std::move(image), tilesDone, tiles.size()};
        throw RenderStopped("the render was stopped before it finished", 1);
    }
    return image;
}
// [render-loop]

}  // namespace rb
