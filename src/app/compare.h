/// \file
/// The command `rt --compare`: two images compared with numbers, and the golden check
/// (src/app/compare.cpp).
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

namespace rb {

/// Run ./rt --compare with the arguments after --compare: prints to `out` (errors to `err`)
/// and returns the exit code, 0 when the images pass, 1 when they do not or on bad input.
int compareCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace rb
