#include "mpi/lease_schedule.h"

#include <algorithm>
#include <numeric>

namespace rb {

LeaseSchedule::LeaseSchedule(std::vector<int> tiles, std::vector<int> threads, LeasePolicy policy)
    : threads_(std::move(threads)), policy_(policy) {
    for (int& t : threads_) t = std::max(1, t);
    totalThreads_ = std::accumulate(threads_.begin(), threads_.end(), 0);
    if (policy_ == LeasePolicy::Dynamic) {
        queues_.emplace_back(tiles.begin(), tiles.end());
        return;
    }
    // Static: each rank takes one contiguous band, as long as its share of the threads.
    const std::size_t count = tiles.size();
    std::size_t before = 0;  // threads of the ranks before this one
    for (int t : threads_) {
        const std::size_t begin = count * before / totalThreads_;
        before += static_cast<std::size_t>(t);
        const std::size_t end = count * before / totalThreads_;
        queues_.emplace_back(tiles.begin() + static_cast<long>(begin),
                             tiles.begin() + static_cast<long>(end));
    }
}

std::vector<int> LeaseSchedule::next(int rank, int perThread) {
    std::deque<int>& queue = queues_[policy_ == LeasePolicy::Dynamic ? 0 : rank];
    const std::size_t threads = static_cast<std::size_t>(threads_[rank]);
    std::size_t take = queue.size();
    // Dynamic: a quarter of this rank's share of what is left, at least a tile per thread.
    if (policy_ == LeasePolicy::Dynamic)
        take = std::max(threads,
                        queue.size() * threads / (4 * static_cast<std::size_t>(totalThreads_)));
    take =
        std::min({take, queue.size(), threads * static_cast<std::size_t>(std::max(0, perThread))});
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
