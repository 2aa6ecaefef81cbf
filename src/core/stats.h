/// \file
/// Ray counters kept per thread, so counting never needs a lock or an atomic.
#pragma once

#include <array>
#include <cstdint>

namespace rb {

/// The kinds of ray raybook counts. Chapters add secondary kinds here as they appear.
enum class RayKind : int {
    Camera,
    Shadow,
    Reflection,
    Refraction,
    Glossy,
    Photon,
    Scatter,
    Path,  ///< A path tracer's bounce (chapter 18).
    Count
};

/// Names for RayKind, in order.
inline constexpr std::array<const char*, static_cast<int>(RayKind::Count)> kRayKindNames = {
    "camera", "shadow", "reflection", "refraction", "glossy", "photon", "scatter", "path"};

/// One thread's ray counts. Aligned to a cache line so threads never share one.
struct alignas(64) RayCounters {
    std::array<std::uint64_t, static_cast<int>(RayKind::Count)> count{};
    /// Count one ray of kind k.
    void add(RayKind k) {
        ++count[static_cast<int>(k)];
        ++all;
    }
    /// Add another thread's counts to these.
    void merge(const RayCounters& other) {
        for (size_t i = 0; i < count.size(); ++i) count[i] += other.count[i];
        all += other.all;
    }
    /// All rays of every kind (kept as they are counted: the render loop asks after each pixel).
    std::uint64_t total() const { return all; }

  private:
    std::uint64_t all = 0;  ///< The sum of count.
};

}  // namespace rb
