#include "util/error.h"

#include <cstdint>
#include <cstdio>

namespace pathlab {
namespace {

// Appends text with control characters (C0, DEL, C1, the Unicode line
// separators and bidirectional overrides) and bytes that are not UTF-8 as
// \xNN escapes; other UTF-8 passes through. Stops before `limit` bytes of
// output, never inside a character or an escape; returns whether it did.
bool appendPrintable(std::string& out, std::string_view text, size_t limit) {
  for (size_t i = 0; i < text.size();) {
    const auto byte = static_cast<unsigned char>(text[i]);
    size_t length = 1;
    bool escaped = false;
    if (byte < 0x80) {
      escaped = byte < 0x20 || byte == 0x7f;
    } else {
      length = byte >= 0xf0 ? 4 : byte >= 0xe0 ? 3 : byte >= 0xc0 ? 2 : 0;
      uint32_t code = length == 4 ? byte & 0x07u : length == 3 ? byte & 0x0fu : byte & 0x1fu;
      bool valid = length != 0 && i + length <= text.size();
      for (size_t k = 1; valid && k < length; ++k) {
        const auto next = static_cast<unsigned char>(text[i + k]);
        valid = (next & 0xc0) == 0x80;
        code = (code << 6) | (next & 0x3fu);
      }
      static constexpr uint32_t kSmallest[5] = {0, 0, 0x80, 0x800, 0x10000};
      valid = valid && code >= kSmallest[length] && code <= 0x10ffff && !(code >= 0xd800 && code <= 0xdfff);
      const bool control = code <= 0x9f || code == 0x2028 || code == 0x2029 ||
                           (code >= 0x202a && code <= 0x202e) || (code >= 0x2066 && code <= 0x2069);
      escaped = !valid || control;
      if (escaped) length = 1;  // one byte at a time: the rest follow as escapes or text
    }
    const size_t cost = escaped ? 4 : length;
    if (out.size() + cost > limit) return false;
    if (escaped) {
      char buffer[5];
      std::snprintf(buffer, sizeof buffer, "\\x%02x", byte);
      out += buffer;
    } else {
      out.append(text.substr(i, length));
    }
    i += length;
  }
  return true;
}

std::string capped(std::string_view text, size_t limit) {
  std::string out;
  if (!appendPrintable(out, text, limit)) out += "…";
  return out;
}

}  // namespace

std::string shown(std::string_view userText, size_t limit) { return capped(userText, limit); }

std::string inQuotes(std::string_view userText, size_t limit) {
  std::string out = "\"";
  if (!appendPrintable(out, userText, limit + 1)) out += "…";
  out += '"';
  return out;
}

std::string printableLine(std::string_view message) { return capped(message, 1000); }

void printError(std::string_view program, std::string_view message) {
  std::fputs((printableLine(std::string(program) + ": " + std::string(message)) + "\n").c_str(), stderr);
}

void printWarning(std::string_view message) {
  std::fputs((printableLine("warning: " + std::string(message)) + "\n").c_str(), stderr);
}

}  // namespace pathlab
