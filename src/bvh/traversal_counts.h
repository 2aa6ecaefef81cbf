/// \file
/// What a wide BVH traversal counts as it goes: nothing by default (NoCounts, whose calls
/// compile away), or the nodes it visits, the triangle packs it filters and the exact tests it
/// runs (TraversalCounts), for the benchmarks that put those counts beside the instruction
/// counts (tests/perf/bvh_vs_embree --callgrind, chapter 3's "Where the cycles go").
#pragma once

#include <cstdint>

namespace rb {

/// Counts nothing: the traversal the renderer runs.
struct NoCounts {
    void node() {}
    void pack() {}
    void exact() {}
};

/// Counts one query's work, or a set of queries' summed.
struct TraversalCounts {
    std::uint64_t nodes = 0;       ///< Wide nodes whose children's boxes were tested.
    std::uint64_t packs = 0;       ///< Packs of four triangles through the float test.
    std::uint64_t exactTests = 0;  ///< Triangles through the exact double test.
    void node() { ++nodes; }
    void pack() { ++packs; }
    void exact() { ++exactTests; }
};

}  // namespace rb
