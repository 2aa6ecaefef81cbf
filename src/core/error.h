/// \file
/// InputError: the one exception type for bad input (scene, OBJ, texture, command line).
#pragma once

#include <stdexcept>
#include <string>

namespace rb {

/// Bad input. The message already names the file, the line where one applies, and what was
/// expected, so `rt` prints it as it is and exits with code 1.
class InputError : public std::runtime_error {
  public:
    explicit InputError(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace rb
