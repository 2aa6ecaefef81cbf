/// \file
/// Fuzz target: the block-statistics reader (src/app/block_stats.cpp) that run_golden.sh
/// --statistical and the grader run on golden/NAME.stats, then the statistical check of a
/// flat grey render of the size the file states (up to 256 × 256) against what it read. Bad
/// input must end in std::runtime_error, the error rt --compare reports.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <string>

#include "app/block_stats.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
    try {
        const rb::golden::BlockStats stats = rb::golden::parse_block_stats(in, "fuzz.stats");
        // Larger images only cost time: the check's loops are the same.
        if (stats.w > 256 || stats.h > 256) return 0;
        const auto render = rb::golden::Image::filled(stats.w, stats.h, 0.5f, 0.25f, 0.75f);
        const auto result = rb::golden::compare_statistically(stats, render);
        // Touch the result so the build cannot optimise the call away.
        if (rb::golden::describe(result).empty()) return 0;
    } catch (const std::runtime_error&) {
        // Bad input, reported as it should be.
    }
    return 0;
}
