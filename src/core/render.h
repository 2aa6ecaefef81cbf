/// \file
/// The render loop: one or more samples per pixel, in parallel over tiles with OpenMP.
#pragma once

#include <cstdint>
#include <cstdio>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/camera.h"
#include "core/cluster.h"
#include "core/image.h"
#include "core/integrator.h"
#include "core/progress.h"
#include "core/target_error.h"

namespace rb {

/// What a stopped render had finished: its image, with the tiles not reached left black.
struct PartialImage {
    std::optional<Image> image;  ///< Set when the render stopped.
    std::size_t tilesDone = 0;   ///< Tiles rendered completely.
    std::size_t tiles = 0;       ///< Tiles in the whole image.
};

/// Where --partial puts a stopped render: "out.png" becomes "out.partial.png".
std::string partialPath(const std::string& output);

/// Write `partial`'s image (the film's linear values, clamped as a PNG) beside `output` at
/// partialPath, and say so on `log`.
void writePartial(const PartialImage& partial, const std::string& output, std::FILE* log);

/// How to sample the image.
struct RenderSettings {
    int threads = 0;          ///< 0: all cores.
    std::uint64_t seed = 0;   ///< Selects the random stream (--seed).
    int samplesPerPixel = 1;  ///< 1: one ray through each pixel centre, as A4 does.
    bool progress = false;    ///< Draw a progress bar with an ETA on stderr.
    /// For tests: when set, resized to the tile count and filled with the OpenMP thread number
    /// that rendered each tile (index = position in tilesInRenderOrder). Null: nothing recorded.
    std::vector<int>* tileThreads = nullptr;
    /// Asked before each tile and, through PixelStop, after a tile's pixels; once it says true,
    /// no further tile starts, the running ones give up (a half-done tile is dropped), and
    /// render() throws RenderStopped. Empty: never stops.
    std::function<bool()> shouldStop;
    /// When set and the render stops, receives what was rendered (--partial). Null: dropped.
    PartialImage* partial = nullptr;
    /// The budget the pipeline's pre-passes (chapter 16's photon maps) charge before they
    /// allocate (--max-memory). Null: no limit.
    const MemoryBudget* memory = nullptr;
    /// The processes sharing the render (MPI ranks); when distributed, its renderTiles deals
    /// out the tiles instead of the loop below. Null: this process renders every tile.
    Cluster* cluster = nullptr;
    /// Under a distributed cluster: what this render is, for its journal and for the check
    /// that every rank renders the same image.
    const RenderIdentity* identity = nullptr;
    bool resume = false;  ///< --resume: start from the journal beside the output.
    /// --target-error: each pixel samples until its error is at most target.error (between a
    /// floor and a ceiling), in place of samplesPerPixel and of any pixel sampler (chapter 8).
    TargetError target;
    /// Under a target: receives each pixel's sample count and spread (under a cluster, each
    /// process its own tiles', and the first all of them once the render ends). Null: not kept.
    SampleMap* sampleMap = nullptr;
};

/// Side of the square tiles the render loop hands to threads, in pixels.
inline constexpr int kTileSize = 16;
/// Strata of the progress estimate: bands of tiles in scanline order that each get their own
/// cost-per-pixel estimate.
inline constexpr int kProgressStrata = 32;

/// A rectangle of pixels [x0, x1) × [y0, y1), the unit of work the render loop hands out.
struct ImageTile {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    int stratum = 0;  ///< Band of the image, in scanline order, the tile lies in.
    /// Number of pixels in the tile.
    int pixels() const { return (x1 - x0) * (y1 - y0); }
};

/// The tiles of a width × height image in the order the render loop starts them: progressive
/// (bit-reversed scanline) order, so that finished tiles are spread over the whole image.
std::vector<ImageTile> tilesInRenderOrder(int width, int height);

/// The progress estimator's view of `tiles`: one WorkUnit per tile, in the same order.
std::vector<WorkUnit> workUnits(const std::vector<ImageTile>& tiles);

/// Start the OpenMP threads a render with `threads` threads (0: all cores) will use, so that
/// render() finds them running, and make `threads` the thread count of every later parallel
/// loop. Optional: the first parallel region starts them otherwise.
void startRenderThreads(int threads);

/// Render an image of the scene through the camera. Counts rays into `counters`.
Image render(const Scene& scene, const Pipeline& pipeline, const PinholeCamera& camera, int width,
             int height, const RenderSettings& settings, RayCounters& counters);

}  // namespace rb
