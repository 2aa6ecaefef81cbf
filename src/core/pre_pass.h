/// \file
/// PrePass: work a chapter does once per image, after the aggregate is built and before the
/// first camera ray. Chapter 16 traces its photons here.
#pragma once

#include <cstdint>
#include <string>

#include "core/camera.h"
#include "core/memory_budget.h"
#include "core/stats.h"

namespace rb {

class Cluster;
struct Scene;
struct Pipeline;

/// What a pre-pass may use: the render's seed and camera, the memory budget to charge before
/// it allocates, and the counters its rays go to.
struct PrePassContext {
    std::uint64_t seed = 0;       ///< --seed: the pre-pass draws from its own streams.
    const PinholeCamera& camera;  ///< The image's camera (for footprints).
    int width = 0, height = 0;    ///< The image's size in pixels.
    const MemoryBudget* memory;   ///< Null: no limit.
    RayCounters& counters;        ///< Where its rays are counted.
    /// The processes sharing the image (MPI ranks): each may trace a share and join them with
    /// joinInOrder. Null: this process does all of it.
    Cluster* cluster = nullptr;
};

/// One chapter's work before the render. run() is called once per image, from one thread; it
/// may start its own parallel loops. It must give the same result for any thread count.
class PrePass {
  public:
    virtual ~PrePass() = default;
    /// Do the work; throws InputError when the budget or the scene forbids it.
    virtual void run(const Scene& scene, const Pipeline& pipeline, const PrePassContext& ctx) = 0;
    /// One line for --stats (what it did and how long it took), or "".
    virtual std::string statistics() const = 0;
};

}  // namespace rb
