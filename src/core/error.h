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

/// What the stub of an exercise region throws in an assignment (make assignment N): the
/// exercise's number and title, and the section of the chapter page that explains it.
class ExerciseNotDone : public std::logic_error {
  public:
    ExerciseNotDone(const std::string& number, const std::string& title, const std::string& anchor)
        : std::logic_error("exercise " + number + " (" + title +
                           ") is not written yet: read the section " + anchor +
                           " of the chapter page, then replace this stub") {}
};

}  // namespace rb
