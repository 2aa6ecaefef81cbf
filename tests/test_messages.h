/// \file
/// Failure messages of the statistical tests that lead somewhere: a z-test names the value it
/// expected next to its z, and a sampler's chi-square test names the sampling lab's command
/// that draws the same sampler (warptestHint).
#pragma once

#include <sstream>
#include <string>

namespace rbtest {

/// A z-test's numbers for a failure message: the estimate, the value it should have, its
/// standard error, and z = (mean − expected) / error.
inline std::string zReport(double mean, double expected, double error) {
    std::ostringstream out;
    out << "mean " << mean << ", expected " << expected << ", standard error " << error
        << ": z = " << (mean - expected) / error;
    return out.str();
}

/// Where a failed chi-square test of a sampler leads: the sampling lab draws the same sampler
/// and shows, bin by bin, where its counts leave the pdf's.
inline std::string warptestHint(const std::string& warp) {
    return "./rt --warptest " + warp + " draws this sampler against its pdf and writes " +
           "warptest-" + warp + ".svg (observed, expected and their difference, bin by bin)";
}

}  // namespace rbtest
