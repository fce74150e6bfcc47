#include "util/output_file.h"

#include <filesystem>
#include <system_error>

#include "util/error.h"
#include "util/image.h"
#include "util/platform.h"

namespace pathlab {

// (The platform's look-ups, not std::filesystem's: those throw on a symlink
// loop or a name too long, which must be an error line, not an internal error.)
void checkOutputFile(const std::string& flag, const std::string& path, OutputKind kind) {
  const std::string name = flag + " " + shown(path, 200);
  if (path.empty()) throw Error(flag + ": expected an output file name");
  if (kind == OutputKind::Image && !isWritableImagePath(path)) {
    throw Error(name + ": unsupported output format (use .png, .exr, .hdr or .jpg)");
  }
  const std::filesystem::path folderPath = std::filesystem::path(path).parent_path();
  const std::string parent = folderPath.empty() ? std::string(".") : folderPath.string();
  const FileStatus folder = fileStatus(parent);
  if (!folder.found) {
    std::string why = "output folder ";
    why += folder.missing ? "does not exist" : "cannot be used: ";
    if (!folder.missing) why += folder.error;
    throw Error(name + ": " + why);
  }
  if (folder.kind != FileKind::Folder) throw Error(name + ": output folder does not exist (" + shown(parent) + " is not a folder)");
  if (!folderIsWritable(parent)) throw Error(name + ": output folder is not writable");
  const FileStatus output = fileStatus(path);
  if (output.found) {
    if (output.kind == FileKind::Folder) throw Error(name + ": is a folder, expected a file name");
  } else if (!output.missing) {
    throw Error(name + ": cannot write: " + output.error);
  }
  if (std::filesystem::path(path).filename().string().size() + 9 > maxFileNameBytes()) {  // + ".partial" and the dot
    throw Error(name + ": file name too long (the temporary name it is written through must fit " +
                std::to_string(maxFileNameBytes()) + " bytes)");
  }
}

namespace {

// Two names of one file: equal once made absolute and normal, links in the
// folders resolved (std::filesystem with error codes: nothing throws), or
// one existing file.
bool sameFile(const std::string& a, const std::string& b) {
  std::error_code error;
  const auto normal = [&](const std::string& p) {
    const std::filesystem::path absolute = std::filesystem::absolute(p, error).lexically_normal();
    const std::filesystem::path canonical = std::filesystem::weakly_canonical(absolute, error);
    return error ? absolute : canonical;
  };
  if (normal(a) == normal(b)) return true;
  const bool both = std::filesystem::exists(a, error) && std::filesystem::exists(b, error);
  return both && std::filesystem::equivalent(a, b, error) && !error;
}

}  // namespace

void checkDistinctFiles(const std::vector<std::pair<std::string, std::string>>& files) {
  for (size_t i = 0; i < files.size(); ++i) {
    for (size_t j = i + 1; j < files.size(); ++j) {
      const auto& [flagA, a] = files[i];
      const auto& [flagB, b] = files[j];
      if (!a.empty() && !b.empty() && sameFile(a, b)) {
        throw Error(flagA + " and " + flagB + " name the same file (" + shown(a, 200) +
                    "): one would overwrite the other");
      }
    }
  }
}

}  // namespace pathlab
