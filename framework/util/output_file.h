// A program's output files, checked before the work that fills them: a
// render, a figure or a table that cannot be written fails at once with one
// line naming the flag and the problem, not after an hour of rendering; and
// no two of a program's files (its outputs, the inputs it reads) may be the
// same file, or one would silently overwrite the other.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace pathlab {

enum class OutputKind {
  Image,  // .png, .exr, .hdr or .jpg (util/image.h)
  Text,   // any name: a table, a JSON summary
};

// Throws an Error naming `flag` when `path` cannot be written: an empty
// name, an image format PathLab does not write, a folder that is missing or
// not writable, a folder where the file should go, a name too long.
void checkOutputFile(const std::string& flag, const std::string& path, OutputKind kind);

// Throws an Error when two of the named files (flag, path) are one file:
// the same name, or two names of one existing file. Empty paths are skipped.
void checkDistinctFiles(const std::vector<std::pair<std::string, std::string>>& files);

}  // namespace pathlab
