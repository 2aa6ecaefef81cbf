/// \file
/// LeaseSchedule: which tiles each rank renders next. Pure bookkeeping, no MPI: rank 0 asks it
/// whenever a rank needs work.
#pragma once

#include <cstddef>
#include <deque>
#include <vector>

namespace rb {

/// How the tiles are shared out.
enum class LeasePolicy {
    Dynamic,  ///< Small batches from one queue, to whichever rank asks (the default).
    Static,   ///< Each rank gets one contiguous band up front (for the balance benchmark).
};

/// The tiles still to lease, and the policy that deals them out.
class LeaseSchedule {
  public:
    /// Lease `tiles` (positions in render order, or in scanline order for Static, whose bands
    /// are contiguous runs of that order) to ranks with threads[r] threads each.
    LeaseSchedule(std::vector<int> tiles, std::vector<int> threads, LeasePolicy policy);

    /// The next tiles for `rank`: at most `perThread` per thread of that rank, empty when it
    /// has none left. A dynamic lease is a quarter of the rank's fair share (by threads) of
    /// what is left, but at least one tile per thread, so the leases shrink as the queue
    /// empties and no rank is left holding a long batch at the end.
    std::vector<int> next(int rank, int perThread);

    /// Tiles not leased yet, over every rank.
    std::size_t remaining() const;

  private:
    std::vector<std::deque<int>> queues_;  // Dynamic: one shared queue; Static: one per rank
    std::vector<int> threads_;
    int totalThreads_ = 0;
    LeasePolicy policy_;
};

}  // namespace rb
