// libFuzzer targets: every input must either load or fail with a
// pathlab::Error (the one-line message the CLI prints). Anything else — a
// crash, a sanitizer report, another exception type, a hang — is a bug.
#pragma once

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

namespace pathlab::fuzz {

// The input as a file named `name` in a folder of this process's own, so
// loaders that take paths see it; returns the path.
inline std::string writeInput(const uint8_t* data, size_t size, const std::string& name) {
  static const std::filesystem::path folder = [] {
    auto dir = std::filesystem::temp_directory_path() / ("pathlab-fuzz-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    return dir;
  }();
  const std::filesystem::path path = folder / name;
  std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(data), std::streamsize(size));
  return path.string();
}

}  // namespace pathlab::fuzz
