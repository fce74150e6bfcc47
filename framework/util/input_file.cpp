#include "util/input_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

#include "util/error.h"

namespace pathlab {
namespace {

std::string describeType(mode_t mode) {
  if (S_ISDIR(mode)) return "is a folder";
  if (S_ISFIFO(mode)) return "is a FIFO (a pipe)";
  if (S_ISCHR(mode) || S_ISBLK(mode)) return "is a device";
  if (S_ISSOCK(mode)) return "is a socket";
  return "is not a regular file";
}

// "an OBJ file", "a scene file"
std::string withArticle(std::string_view what) {
  const bool vowel = !what.empty() && std::string_view("AEIOUaeiou").find(what[0]) != std::string_view::npos;
  return (vowel ? "an " : "a ") + std::string(what);
}

std::string mib(size_t bytes) { return std::to_string(bytes >> 20) + " MiB"; }

// Closes the descriptor on every path out.
struct Descriptor {
  int fd = -1;
  ~Descriptor() {
    if (fd >= 0) ::close(fd);
  }
};

}  // namespace

std::string readInputFile(const std::string& path, std::string_view what, size_t maxBytes) {
  const std::string name = shown(path, 200);
  // O_NONBLOCK: opening a FIFO does not wait for a writer (it is refused below).
  Descriptor file{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC)};
  if (file.fd < 0) {
    throw Error(name + ": cannot open " + std::string(what) + ": " + std::strerror(errno));
  }
  struct stat info {};
  if (::fstat(file.fd, &info) != 0) throw Error(name + ": cannot read " + std::string(what) + ": " + std::strerror(errno));
  if (!S_ISREG(info.st_mode)) {
    throw Error(name + ": " + describeType(info.st_mode) + ", expected " + withArticle(what));
  }
  if (size_t(info.st_size) > maxBytes) {
    throw Error(name + ": " + std::string(what) + " is " + mib(size_t(info.st_size)) + ", more than the " +
                mib(maxBytes) + " PathLab reads");
  }
  std::string text(size_t(info.st_size), '\0');
  size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::read(file.fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw Error(name + ": cannot read " + std::string(what) + ": " + std::strerror(errno));
    if (n == 0) break;  // the file shrank while we read: what is there is what we have
    done += size_t(n);
  }
  text.resize(done);
  return text;
}

size_t requireRegularFile(const std::string& path, std::string_view what) {
  const std::string name = shown(path, 200);
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0) {
    throw Error(name + ": cannot open " + std::string(what) + ": " + std::strerror(errno));
  }
  if (!S_ISREG(info.st_mode)) {
    throw Error(name + ": " + describeType(info.st_mode) + ", expected " + withArticle(what));
  }
  return size_t(info.st_size);
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
  const std::string name = shown(path, 200);
  const std::string partial = partialPathFor(path);
  Descriptor file{::open(partial.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644)};
  if (file.fd < 0) throw Error(name + ": cannot write: " + std::strerror(errno));
  auto fail = [&](int error) {
    ::close(file.fd);
    file.fd = -1;
    ::unlink(partial.c_str());
    throw Error(name + ": cannot write: " + std::strerror(error));
  };
  size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(file.fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) fail(n < 0 ? errno : ENOSPC);
    done += size_t(n);
  }
  // A full disk or a failing device can report only here (NFS, delayed allocation).
  if (::fsync(file.fd) != 0 && errno != EINVAL && errno != EROFS) fail(errno);
  const int descriptor = file.fd;
  file.fd = -1;
  if (::close(descriptor) != 0) {
    const int error = errno;
    ::unlink(partial.c_str());
    throw Error(name + ": cannot write: " + std::strerror(error));
  }
  if (::rename(partial.c_str(), path.c_str()) != 0) {
    const int error = errno;
    ::unlink(partial.c_str());
    throw Error(name + ": cannot write: " + std::strerror(error));
  }
}

}  // namespace pathlab
