/// \file
/// MpiCluster: the ranks of an mpirun job as one Cluster. Rank 0 leases tiles in small batches
/// to every rank (itself included), takes the finished tiles back into the image, and journals
/// them beside the output as they arrive.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "core/cluster.h"
#include "core/render.h"
#include "mpi/job_end.h"
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
///
/// Ctrl-C and SIGTERM are the cluster's: Open MPI 4.1 has no fault tolerance, so when a rank
/// dies mpirun sends SIGTERM to the others and SIGKILL a second later, and Ctrl-C to mpirun does
/// the same. A watcher thread on every rank sees the pending signal (rt holds it from before
/// MPI_Init), and the rank that speaks for the job (job_end.h) says which rank was lost, what the
/// journal holds and how to resume, writes --partial's image from the journal, and exits 1.
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
    /// The image being rendered, as the watcher needs it: its journal, what --partial writes.
    struct Rendering {
        RenderIdentity identity;
        std::vector<ImageTile> tiles;
        int width = 0, height = 0;
        bool partial = false;
    };
    /// The watcher thread: wait for SIGINT or SIGTERM, then end the job (endJob); on rank 0,
    /// also for its own lease to run overdue (endForOwnHang).
    void watch();
    /// Say why the job ends (if this rank speaks for it), write --partial's image, exit 1.
    [[noreturn]] void endJob();
    /// Rank 0, under the watcher's lock: --partial's image of the journal's tiles, if asked for.
    void writeJournalPartial();
    /// A worker that returned nothing for too long, and the tiles of the lease it is rendering.
    struct HungRank {
        int rank = 0;
        std::vector<int> tiles;
    };
    /// Rank 0's own lease, as the watcher sees it: its tiles, when it started, and the seconds
    /// it may take (not finite: no limit yet).
    struct OwnLease {
        std::vector<int> tiles;
        std::chrono::steady_clock::time_point start;
        double limit = 0;
        const TileWork* work = nullptr;
    };
    /// Rank 0: say that the ranks `hung` finished nothing within `limit` seconds, naming each
    /// and its tiles, with what the journal holds and how to resume.
    void sayHang(const std::vector<HungRank>& hung, double limit, const TileWork& work);
    /// Rank 0: the workers `hung` returned nothing within `limit` seconds. Say so (sayHang),
    /// then end the job (exit 1).
    [[noreturn]] void endForHang(const std::vector<HungRank>& hung, double limit,
                                 const TileWork& work);
    /// Rank 0, under the watcher's lock: its own lease has run past its limit.
    bool ownLeaseOverdue() const;
    /// Rank 0's watcher: its own lease `own` is overdue (a tile that never finishes). Say so,
    /// then end the job without an MPI call (exit 1).
    [[noreturn]] void endForOwnHang(const OwnLease& own);
    /// Rank 0: the lease it renders now, or none.
    void setOwnLease(std::optional<OwnLease> lease) {
        std::lock_guard lock(mutex_);
        ownLease_ = std::move(lease);
    }
    /// The journal's note for the end message; rank 0 counts its own, the others read it.
    std::optional<JournalNote> journalNote() const;
    /// Rank 0: journal one finished tile (under the watcher's lock, so the count it says is
    /// what the journal holds).
    void journalTile(int position, std::span<const float> pixels);
    /// Wait for the watcher to end the process once a signal is pending: no collective call
    /// may start then, since the ranks are being killed.
    void parkIfEnding() const;
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
    double tileTimeout_ = 0;  // --tile-timeout's seconds; 0: automatic (lead)
    std::FILE* errors_ = stderr;
    std::unique_ptr<JournalWriter> journal_;  // rank 0, from renderTiles until imageWritten
    std::vector<RankWork> work_;              // rank 0: each rank's share of the last image
    std::uint64_t filmBytes_ = 0, joinBytes_ = 0;
    int threads_ = 1;
    std::vector<RankPlace> places_;  // every rank's machine and pid
    std::string resumeCommand_;      // this run's command with --resume
    mutable std::mutex mutex_;  // guards rendering_, journaled_, ownLease_, the journal's appends
    std::optional<Rendering> rendering_;
    std::size_t journaled_ = 0;         // rank 0: tiles the journal holds
    std::optional<OwnLease> ownLease_;  // rank 0: the lease it renders now
    std::atomic<bool> ending_{false};   // the watcher saw a signal
    std::atomic<bool> said_{false};     // rank 0 ended the job itself and said why
    bool closing_ = false;              // the destructor stops the watcher (under mutex_)
    std::condition_variable wake_;
    std::thread watcher_;
};

}  // namespace rb
