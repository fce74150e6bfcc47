// The one exception type for bad input, and the one way any message about
// input reaches the terminal. An Error's message is a single line that
// names the file (or flag) and the problem; the CLI prints it and exits 1.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

namespace pathlab {

class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& message) : std::runtime_error(message) {}
};

// User text inside a message (a key, a name, a path, a token read from a
// file): control characters and bytes that are not UTF-8 escaped as \xNN,
// cut to `limit` bytes with "…" so a 200 MB key prints as 80 characters.
std::string shown(std::string_view userText, size_t limit = 80);
// shown() in double quotes: "key".
std::string inQuotes(std::string_view userText, size_t limit = 80);

// The whole line as printed: every control character escaped (a newline in a
// message can never start a second line) and at most 1000 bytes.
std::string printableLine(std::string_view message);

// "PROGRAM: MESSAGE" and "warning: MESSAGE" on stderr, through printableLine.
void printError(std::string_view program, std::string_view message);
void printWarning(std::string_view message);

}  // namespace pathlab
