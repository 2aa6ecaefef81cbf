/// \file
/// The memory budget: how much one run of rt may use (--max-memory), and the estimates that let
/// a scene that would not fit fail with a clear message before it allocates, instead of driving
/// the machine into swap or the OOM killer.
#pragma once

#include <cstdint>
#include <limits>
#include <string>

namespace rb {

/// Peak bytes per triangle while a mesh loads: the parsed OBJ arrays, the Mesh and its BVH
/// build, together. Source: peak RSS (/usr/bin/time -f %M) of ./rt on 500k- and 2M-triangle
/// grids and a 500k-triangle soup with 3 vertices per triangle (2026-11-23): 263 B per triangle
/// and 46 B per vertex, rounded up here.
inline constexpr std::uint64_t kMeshBytesPerTriangle = 272;
/// Peak bytes per OBJ vertex (position, texture coordinate or normal) while a mesh loads.
inline constexpr std::uint64_t kMeshBytesPerVertex = 48;
/// Peak bytes per pixel of rendering and writing an image: the float film (12), its 8-bit copy
/// (3), stb's filtered rows (3) and its zlib output buffer, which grows by doubling (up to 6).
/// Source: 17.7 B per pixel measured (peak RSS) on a 4000×4000 image that compresses well;
/// the bound above is for one that does not.
inline constexpr std::uint64_t kImageBytesPerPixel = 24;

/// How many bytes the whole process may hold, and who said so.
struct MemoryBudget {
    /// The limit in bytes; the largest value means no limit.
    std::uint64_t limit = std::numeric_limits<std::uint64_t>::max();
    /// What set the limit, for messages: "--max-memory 64M", or the machine's default share.
    std::string origin = "no limit";

    /// Bytes still free under the limit: the limit less what the process holds now.
    std::uint64_t available() const;
    /// Throw InputError "where: what needs about B, but only F of the memory limit L (origin)
    /// is free" when `bytes` more than the process holds now would pass the limit.
    void require(std::uint64_t bytes, const std::string& where, const std::string& what) const;
    /// The message require() throws, for callers that measure against their own baseline.
    std::string refusal(std::uint64_t bytes, std::uint64_t free, const std::string& where,
                        const std::string& what) const;
};

/// The default budget: half of the machine's memory, or of the container's (cgroup) limit when
/// that is smaller. Half leaves room for the system and a second program.
MemoryBudget defaultMemoryBudget();

/// The budget that --max-memory SIZE asks for. SIZE is bytes, or a number with the suffix
/// K, M, G or T (powers of 1024; "KiB", "MB" and friends are accepted too). Throws InputError
/// for anything else, or for less than 1 MiB.
MemoryBudget memoryBudgetFromOption(const std::string& size);

/// The resident set size of this process, in bytes (0 if /proc cannot tell).
std::uint64_t residentBytes();

/// A byte count for people: "812 KiB", "1.5 GiB".
std::string formatBytes(std::uint64_t bytes);

/// a × b, or the largest value when the product would overflow: estimates saturate.
std::uint64_t saturatingProduct(std::uint64_t a, std::uint64_t b);

}  // namespace rb
