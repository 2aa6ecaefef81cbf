/// \file
/// Cluster: the processes that share one run of rt (MPI ranks, src/mpi), as the core sees them.
/// One process is a cluster of one; the core's hooks then cost nothing.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "core/image.h"
#include "core/stats.h"

namespace rb {

struct ImageTile;

/// A failure every process of the cluster has agreed on (Cluster::agree): the whole run ends
/// with `exitCode`. Only the lowest failing process holds `cause` and prints it; the others
/// end silently, so the job says it once.
struct AgreedFailure {
    int exitCode = 1;
    std::exception_ptr cause;  ///< Null on the processes that only learned of the failure.
};

/// What makes a render the same render: name and value pairs (rt's version, the scene's bytes,
/// the size, the seed, the sampling options). A journal written under other values is refused.
struct RenderIdentity {
    std::string output;  ///< The image's path; the journal sits beside it.
    std::vector<std::pair<std::string, std::string>> fields;
};

/// One image's tiles, for a cluster to share out: every process renders tiles of the same
/// image with renderTile, and only the first writes the image.
struct TileWork {
    const std::vector<ImageTile>& tiles;  ///< In render order; work refers to them by position.
    int threads = 1;                      ///< OpenMP threads of this process.
    bool resume = false;                  ///< --resume: start from the journal beside the output.
    const RenderIdentity& identity;       ///< Checked against the journal, and across processes.
    /// Render tiles[k] into the image, counting rays; any thread may call it.
    std::function<void(int k, Image& image, RayCounters& rays)> renderTile;
    /// Asked between batches on the first process; true stops the render (Ctrl-C, --time-limit).
    std::function<bool()> shouldStop;
    /// For the progress bar, on every process: tile k of the job (any process's) is started,
    /// and finished having traced `rays` rays (a remote lease's rays go to its first tile).
    std::function<void(int k)> tileStarted;
    std::function<void(int k, std::uint64_t rays)> tileFinished;
    /// --partial: a render ended by a signal writes its finished tiles (render.h, writePartial).
    bool partial = false;
};

/// The processes of one run. Every call below is collective: each process makes it, in the
/// same order.
class Cluster {
  public:
    virtual ~Cluster() = default;
    /// This process's number, 0 for the one that writes images and reports.
    virtual int rank() const = 0;
    /// How many processes share the run.
    virtual int size() const = 0;
    /// True when the images and the report are this process's to write (rank 0).
    bool writesOutput() const { return rank() == 0; }
    /// True under MPI (even one rank): images render through renderTiles, with a journal.
    virtual bool distributed() const { return false; }

    /// Every process says whether it failed (a null `failure`: it did not). Returns when none
    /// did; otherwise throws AgreedFailure on every process, so none waits for another.
    virtual void agree(std::exception_ptr failure) = 0;

    /// Render every tile of `work` into `image` (width × height) with the other processes, and
    /// add every process's rays to `counters` on the first. Other processes return with their
    /// part only. Throws RenderStopped when stopped, AgreedFailure when a process failed.
    virtual void renderTiles(const TileWork& work, Image& image, RayCounters& counters) = 0;

    /// The image of the last renderTiles is written: its journal is no longer needed.
    virtual void imageWritten() {}

    /// Every process's `mine`, concatenated in process order, on every process.
    virtual std::vector<std::byte> joinInOrder(std::span<const std::byte> mine) = 0;

    /// Every process's `mine` on the first, in process order; empty elsewhere.
    virtual std::vector<std::vector<std::byte>> gatherToFirst(std::span<const std::byte> mine) = 0;

    /// Lines --stats adds about the last renderTiles (bytes sent, each process's busy time).
    virtual std::vector<std::string> statistics() const { return {}; }

    /// Where this process reports an error (the first process's stderr; the others keep
    /// theirs for errors only, since every process says the same warnings).
    virtual std::FILE* errorStream() const { return stderr; }
};

/// The exit code rt ends with after `failure`: a stopped render's own (124, 130, 143), else 1.
int exitCodeOf(std::exception_ptr failure);

/// The cluster this run is part of: MPI ranks when rt was started by mpirun (or --mpi, or
/// --resume, asks for MPI), else one process. Throws InputError when MPI is asked for and this
/// rt was built without it. Call once, before anything else.
std::unique_ptr<Cluster> joinCluster(int argc, char** argv);

}  // namespace rb
