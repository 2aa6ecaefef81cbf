/// \file
/// MpiCluster: the ranks of an mpirun job as one Cluster. Rank 0 leases tiles in small batches
/// to every rank (itself included), takes the finished tiles back into the image, and journals
/// them beside the output as they arrive.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/cluster.h"
#include "mpi/journal.h"
#include "mpi/lease_schedule.h"

namespace rb {

/// What one rank did in one image's render, for --stats and the balance benchmark.
struct RankWork {
    std::uint64_t tiles = 0;      ///< Tiles it rendered.
    double busySeconds = 0.0;     ///< CPU time its threads spent inside tiles (thread CPU clocks).
    std::uint64_t bytesSent = 0;  ///< Bytes it sent in the tile exchange.
};

/// The ranks of MPI_COMM_WORLD. Constructed once per process (it calls MPI_Init_thread) and
/// destroyed at exit (MPI_Finalize).
class MpiCluster final : public Cluster {
  public:
    /// Join the job; `policy` deals the tiles (--mpi-lease).
    MpiCluster(int argc, char** argv, LeasePolicy policy);
    ~MpiCluster() override;
    MpiCluster(const MpiCluster&) = delete;
    MpiCluster& operator=(const MpiCluster&) = delete;

    int rank() const override { return rank_; }
    int size() const override { return size_; }
    bool distributed() const override { return true; }
    void agree(std::exception_ptr failure) override;
    void renderTiles(const TileWork& work, Image& image, RayCounters& counters) override;
    void imageWritten() override;
    std::vector<std::byte> joinInOrder(std::span<const std::byte> mine) override;
    std::vector<std::vector<std::byte>> gatherToFirst(std::span<const std::byte> mine) override;
    std::vector<std::string> statistics() const override;
    std::FILE* errorStream() const override { return errors_; }

  private:
    /// Rank 0's part: lease `todo` to ranks of threads[r] threads, render its own batches,
    /// take the others' tiles back.
    void lead(const TileWork& work, Image& image, RayCounters& counters,
              const std::vector<int>& todo, const std::vector<int>& threads);
    /// Every other rank's part: render the leases rank 0 sends until it sends none.
    void follow(const TileWork& work, Image& image, RayCounters& counters);
    /// Throw InputError on every rank unless all ranks were given the same render.
    void checkSameRender(const RenderIdentity& identity) const;

    int rank_ = 0, size_ = 1;
    LeasePolicy policy_;
    std::FILE* errors_ = stderr;
    std::unique_ptr<JournalWriter> journal_;  // rank 0, from renderTiles until imageWritten
    std::vector<RankWork> work_;              // rank 0: each rank's share of the last image
    std::uint64_t filmBytes_ = 0, joinBytes_ = 0;
    int threads_ = 1;
};

}  // namespace rb
