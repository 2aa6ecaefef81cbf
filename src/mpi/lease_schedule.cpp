#include "mpi/lease_schedule.h"

#include <algorithm>

namespace rb {

LeaseSchedule::LeaseSchedule(std::vector<int> tiles, int ranks, LeasePolicy policy)
    : ranks_(std::max(1, ranks)), policy_(policy) {
    if (policy_ == LeasePolicy::Dynamic) {
        queues_.emplace_back(tiles.begin(), tiles.end());
        return;
    }
    // Static: rank r takes the r-th of `ranks` contiguous bands, sized within one tile.
    const std::size_t count = tiles.size();
    for (int r = 0; r < ranks_; ++r) {
        const std::size_t begin = count * r / ranks_, end = count * (r + 1) / ranks_;
        queues_.emplace_back(tiles.begin() + static_cast<long>(begin),
                             tiles.begin() + static_cast<long>(end));
    }
}

std::vector<int> LeaseSchedule::next(int rank, int limit) {
    std::deque<int>& queue = queues_[policy_ == LeasePolicy::Dynamic ? 0 : rank];
    // Dynamic: a quarter of this rank's fair share of what is left, at least one tile.
    std::size_t take = queue.size();
    if (policy_ == LeasePolicy::Dynamic)
        take = std::max<std::size_t>(1, queue.size() / (4 * ranks_));
    take = std::min({take, queue.size(), static_cast<std::size_t>(std::max(0, limit))});
    std::vector<int> lease(queue.begin(), queue.begin() + static_cast<long>(take));
    queue.erase(queue.begin(), queue.begin() + static_cast<long>(take));
    return lease;
}

std::size_t LeaseSchedule::remaining() const {
    std::size_t left = 0;
    for (const auto& q : queues_) left += q.size();
    return left;
}

}  // namespace rb
