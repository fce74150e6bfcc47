// The one exception type for bad input. Its message is a single line that
// names the file (or flag) and the problem; the CLI prints it and exits 1.
#pragma once

#include <stdexcept>
#include <string>

namespace pathlab {

class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace pathlab
