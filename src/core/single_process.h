/// \file
/// SingleProcess: the cluster of one process that rt is without MPI.
#pragma once

#include "core/cluster.h"

namespace rb {

/// One process: every collective is a no-op on its own data.
class SingleProcess final : public Cluster {
  public:
    int rank() const override { return 0; }
    int size() const override { return 1; }
    /// A failure is this process's own: thrown as an AgreedFailure that holds it.
    void agree(std::exception_ptr failure) override;
    /// Not used: one process renders through the core's own loop (render()).
    void renderTiles(const TileWork& work, Image& image, RayCounters& counters) override;
    std::vector<std::byte> joinInOrder(std::span<const std::byte> mine) override;
    std::vector<std::vector<std::byte>> gatherToFirst(std::span<const std::byte> mine) override;
};

}  // namespace rb
