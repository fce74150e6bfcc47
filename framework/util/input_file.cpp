#include "util/input_file.h"

#include <filesystem>

#include "util/error.h"
#include "util/platform.h"

namespace pathlab {
namespace {

// "an OBJ file", "a scene file"
std::string withArticle(std::string_view what) {
  const bool vowel = !what.empty() && std::string_view("AEIOUaeiou").find(what[0]) != std::string_view::npos;
  return (vowel ? "an " : "a ") + std::string(what);
}

std::string mib(uint64_t bytes) { return std::to_string(bytes >> 20) + " MiB"; }

}  // namespace

std::string readInputFile(const std::string& path, std::string_view what, size_t maxBytes) {
  const std::string name = shown(path, 200);
  FileRead read = readRegularFile(path, maxBytes);
  if (!read.opened) throw Error(name + ": cannot open " + std::string(what) + ": " + read.error);
  if (!read.error.empty()) throw Error(name + ": cannot read " + std::string(what) + ": " + read.error);
  if (read.kind != FileKind::Regular) {
    throw Error(name + ": " + describeFileKind(read.kind) + ", expected " + withArticle(what));
  }
  if (read.size > maxBytes) {
    throw Error(name + ": " + std::string(what) + " is " + mib(read.size) + ", more than the " + mib(maxBytes) +
                " PathLab reads");
  }
  return std::move(read.bytes);
}

size_t requireRegularFile(const std::string& path, std::string_view what) {
  const std::string name = shown(path, 200);
  const FileStatus status = fileStatus(path);
  if (!status.found) throw Error(name + ": cannot open " + std::string(what) + ": " + status.error);
  if (status.kind != FileKind::Regular) {
    throw Error(name + ": " + describeFileKind(status.kind) + ", expected " + withArticle(what));
  }
  return size_t(status.size);
}

void createFolders(const std::string& folder) {
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  if (error) throw Error(shown(folder, 200) + ": cannot create the folder: " + error.message());
}

std::string partialPathFor(const std::string& path) {
  const std::filesystem::path target(path);
  std::string partialName = ".";
  partialName.append(target.stem().string()).append(".partial").append(target.extension().string());
  return (target.parent_path() / partialName).string();
}

void writeFileAtomically(const std::string& path, std::string_view bytes) {
  const std::string partial = partialPathFor(path);
  std::string problem = writeFileDurably(partial, bytes);
  if (problem.empty()) {
    problem = replaceFile(partial, path);
    if (!problem.empty()) removeFileQuietly(partial);
  }
  if (!problem.empty()) throw Error(shown(path, 200) + ": cannot write: " + problem);
}

}  // namespace pathlab
