/// \file
/// Tests of the lease schedule (src/mpi/lease_schedule.h): which tiles each rank renders next.
///
/// The schedule claims that every tile is leased exactly once, whatever order the ranks ask
/// in; that dynamic leases shrink towards the end (so the last leases are single tiles and no
/// rank is left with a long batch while the others idle), never exceeding the limit asked for;
/// that a rank's leases are sized by its threads (at least one tile per thread); and that a
/// static split gives each rank one contiguous band, as long as its share of the threads.
/// The tests drive it with a deterministic pattern of requests from four ranks.
#include "mpi/lease_schedule.h"

#include <algorithm>
#include <catch2/catch.hpp>
#include <numeric>
#include <vector>

namespace {

/// The tiles 0 .. count-1.
std::vector<int> tiles(int count) {
    std::vector<int> t(static_cast<std::size_t>(count));
    std::iota(t.begin(), t.end(), 0);
    return t;
}

}  // namespace

SCENARIO("dynamic leases hand out every tile once, in shrinking batches", "[mpi]") {
    GIVEN("1000 tiles and 4 ranks asking for at most 8 at a time, in an uneven pattern") {
        rb::LeaseSchedule schedule(tiles(1000), {1, 1, 1, 1}, rb::LeasePolicy::Dynamic);
        std::vector<int> seen, sizes;
        // Rank 0 asks three times as often as the others (its tiles are cheap).
        const int pattern[] = {0, 1, 0, 2, 0, 3};
        for (int i = 0; schedule.remaining() > 0; ++i) {
            const std::vector<int> lease = schedule.next(pattern[i % 6], 8);
            seen.insert(seen.end(), lease.begin(), lease.end());
            sizes.push_back(static_cast<int>(lease.size()));
        }
        THEN("every tile is leased exactly once, in the order given") {
            CHECK(seen == tiles(1000));
        }
        THEN("no lease exceeds the limit, the first are full and the last are single tiles") {
            CHECK(*std::max_element(sizes.begin(), sizes.end()) == 8);
            CHECK(sizes.front() == 8);
            // A quarter of a fair share of what is left: one tile once fewer than 32 remain.
            CHECK(std::count(sizes.end() - 16, sizes.end(), 1) == 16);
            CHECK(std::is_sorted(sizes.rbegin(), sizes.rend()));
        }
        THEN("once every tile is out, a rank gets an empty lease") {
            CHECK(schedule.next(2, 8).empty());
        }
    }
}

SCENARIO("a rank with more threads gets longer leases, never fewer tiles than threads", "[mpi]") {
    GIVEN("100 tiles for a rank of 4 threads and a rank of 1, at most 8 tiles per thread") {
        rb::LeaseSchedule schedule(tiles(100), {4, 1}, rb::LeasePolicy::Dynamic);
        THEN("its first lease is a quarter of its 4/5 share: 20 tiles; then the 1-thread rank's") {
            CHECK(schedule.next(0, 8).size() == 20);  // 100 * 4 / (4 * 5)
            CHECK(schedule.next(1, 8).size() == 4);   // 80 * 1 / 20
        }
        THEN("near the end the 4-thread rank still gets 4 tiles, one per thread") {
            while (schedule.remaining() > 6) schedule.next(1, 8);
            CHECK(schedule.next(0, 8).size() == 4);
            CHECK(schedule.next(0, 8).size() == 2);  // what is left
        }
    }
    GIVEN("the same ranks with a static split") {
        rb::LeaseSchedule schedule(tiles(100), {4, 1}, rb::LeasePolicy::Static);
        THEN("the bands are 80 and 20 tiles, by threads") {
            CHECK(schedule.next(0, 1000).size() == 80);
            CHECK(schedule.next(1, 1000).size() == 20);
        }
    }
}

SCENARIO("a static split gives each rank one contiguous band", "[mpi]") {
    GIVEN("10 tiles split over 4 ranks") {
        rb::LeaseSchedule schedule(tiles(10), {1, 1, 1, 1}, rb::LeasePolicy::Static);
        WHEN("each rank asks for everything it has") {
            std::vector<std::vector<int>> bands;
            for (int r = 0; r < 4; ++r) bands.push_back(schedule.next(r, 100));
            THEN("the bands are 2, 3, 2, 3 tiles long (floor(10 r / 4) boundaries), in order") {
                CHECK(bands[0] == std::vector<int>{0, 1});
                CHECK(bands[1] == std::vector<int>{2, 3, 4});
                CHECK(bands[2] == std::vector<int>{5, 6});
                CHECK(bands[3] == std::vector<int>{7, 8, 9});
                CHECK(schedule.remaining() == 0);
            }
        }
        WHEN("rank 2 asks twice") {
            const auto first = schedule.next(2, 1), second = schedule.next(2, 100);
            THEN("it gets its own band only, never another rank's tiles") {
                CHECK(first == std::vector<int>{5});
                CHECK(second == std::vector<int>{6});
                CHECK(schedule.next(2, 100).empty());
                CHECK(schedule.remaining() == 8);
            }
        }
    }
}
