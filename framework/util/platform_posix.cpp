// platform.h on Linux and macOS (POSIX). platform_windows.cpp is the other
// half; each compiles to nothing on the other's systems.
#if !defined(_WIN32)

#include "util/platform.h"

#include <dlfcn.h>
#include <fcntl.h>
#include <pthread.h>
#if defined(__APPLE__)
#include <mach-o/dyld.h>
#endif
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#if defined(PATHLAB_SANITIZED)
#include <sanitizer/common_interface_defs.h>
#endif

#include <cerrno>
#include <climits>
#include <csignal>
#include <cstring>
#include <ctime>
#include <vector>

extern char** environ;  // the process's environment, for the programs it starts (POSIX)

namespace pathlab {
namespace {

FileKind kindOf(mode_t mode) {
  if (S_ISREG(mode)) return FileKind::Regular;
  if (S_ISDIR(mode)) return FileKind::Folder;
  if (S_ISFIFO(mode)) return FileKind::Pipe;
  if (S_ISCHR(mode) || S_ISBLK(mode)) return FileKind::Device;
  if (S_ISSOCK(mode)) return FileKind::Socket;
  return FileKind::Other;
}

// Closes the descriptor on every path out.
struct Descriptor {
  int fd = -1;
  ~Descriptor() {
    if (fd >= 0) ::close(fd);
  }
};

}  // namespace

FileStatus fileStatus(const std::string& path) {
  FileStatus status;
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0) {
    status.missing = errno == ENOENT;
    status.error = std::strerror(errno);
    return status;
  }
  status.found = true;
  status.kind = kindOf(info.st_mode);
  status.size = uint64_t(info.st_size);
  return status;
}

FileRead readRegularFile(const std::string& path, size_t maxBytes) {
  FileRead read;
  // O_NONBLOCK: opening a FIFO does not wait for a writer (it is refused below).
  Descriptor file{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC)};
  if (file.fd < 0) {
    read.error = std::strerror(errno);
    return read;
  }
  read.opened = true;
  struct stat info {};
  if (::fstat(file.fd, &info) != 0) {
    read.error = std::strerror(errno);
    return read;
  }
  read.kind = kindOf(info.st_mode);
  read.size = uint64_t(info.st_size);
  if (read.kind != FileKind::Regular || read.size > maxBytes) return read;
  read.bytes.resize(size_t(read.size));
  size_t done = 0;
  while (done < read.bytes.size()) {
    const ssize_t n = ::read(file.fd, read.bytes.data() + done, read.bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      read.error = std::strerror(errno);
      return read;
    }
    if (n == 0) break;  // the file shrank while we read: what is there is what we have
    done += size_t(n);
  }
  read.bytes.resize(done);
  return read;
}

std::string writeFileDurably(const std::string& path, std::string_view bytes) {
  // Created afresh, never through what is already there: a symbolic link
  // planted at this name would otherwise send the bytes to its target.
  constexpr int kCreate = O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC;
  Descriptor file{::open(path.c_str(), kCreate, 0644)};
  if (file.fd < 0 && errno == EEXIST && ::unlink(path.c_str()) == 0) {  // a leftover, or a link (unlink removes the link)
    file.fd = ::open(path.c_str(), kCreate, 0644);
  }
  if (file.fd < 0) return std::strerror(errno);
  auto fail = [&](int error) {
    ::close(file.fd);
    file.fd = -1;
    ::unlink(path.c_str());
    return std::string(std::strerror(error));
  };
  size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(file.fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return fail(n < 0 ? errno : ENOSPC);
    done += size_t(n);
  }
  // A full disk or a failing device can report only here (NFS, delayed allocation).
  if (::fsync(file.fd) != 0 && errno != EINVAL && errno != EROFS) return fail(errno);
  const int descriptor = file.fd;
  file.fd = -1;
  if (::close(descriptor) != 0) {
    const int error = errno;
    ::unlink(path.c_str());
    return std::strerror(error);
  }
  return "";
}

std::string replaceFile(const std::string& from, const std::string& to) {
  return ::rename(from.c_str(), to.c_str()) == 0 ? "" : std::strerror(errno);
}

void removeFileQuietly(const std::string& path) { ::unlink(path.c_str()); }

bool folderIsWritable(const std::string& path) { return ::access(path.c_str(), W_OK) == 0; }

size_t maxFileNameBytes() { return NAME_MAX; }

long currentProcessId() { return long(::getpid()); }

double currentThreadCpuSeconds() {
  timespec now{};
  ::clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return double(now.tv_sec) + 1e-9 * double(now.tv_nsec);
}

std::string currentExecutablePath() {
#if defined(__APPLE__)
  uint32_t size = 0;
  _NSGetExecutablePath(nullptr, &size);  // asks for the size
  std::vector<char> path(size + 1, '\0');
  if (_NSGetExecutablePath(path.data(), &size) != 0) return "";
  char resolved[PATH_MAX];
  return ::realpath(path.data(), resolved) ? std::string(resolved) : std::string(path.data());
#else
  char self[PATH_MAX];
  const ssize_t n = ::readlink("/proc/self/exe", self, sizeof self - 1);
  return n > 0 ? std::string(self, size_t(n)) : std::string();
#endif
}

void* loadSharedLibrary(const std::string& path, std::string& error) {
  // RTLD_LOCAL: its symbols (and those of the libraries it needs) stay its own.
  void* library = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!library) {
    const char* why = ::dlerror();
    error = why ? why : "dlopen failed";
  }
  return library;
}

void* sharedLibraryFunction(void* library, const char* name) { return ::dlsym(library, name); }

int runProgram(const std::string& path, const std::vector<std::string>& arguments, std::string& error) {
  std::vector<char*> argv{const_cast<char*>(path.c_str())};
  for (const std::string& argument : arguments) argv.push_back(const_cast<char*>(argument.c_str()));
  argv.push_back(nullptr);
  // Checked first: where posix_spawn cannot see its child's exec fail (glibc
  // before 2.24, or under qemu-user), a missing program would look like a
  // program that exited with 127.
  if (::access(path.c_str(), X_OK) != 0) {
    error = std::strerror(errno);
    return -1;
  }
  pid_t pid = 0;
  const int started = ::posix_spawn(&pid, path.c_str(), nullptr, nullptr, argv.data(), environ);
  if (started != 0) {
    error = std::strerror(started);
    return -1;
  }
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) {
      error = std::strerror(errno);
      return -1;
    }
  }
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  error = "ended by signal " + std::to_string(WTERMSIG(status)) + " (" + strsignal(WTERMSIG(status)) + ")";
  return -1;
}

bool stderrIsTerminal() { return ::isatty(STDERR_FILENO) == 1; }

int silenceStderr() {
  const int saved = ::dup(STDERR_FILENO);
  const int null = ::open("/dev/null", O_WRONLY | O_CLOEXEC);
#if defined(PATHLAB_SANITIZED)
  // A sanitizer's report raised meanwhile (a bad read, another thread's
  // race) goes to the real stderr, not with the library's chatter.
  if (saved >= 0) __sanitizer_set_report_fd(reinterpret_cast<void*>(intptr_t(saved)));
#endif
  if (saved >= 0 && null >= 0) ::dup2(null, STDERR_FILENO);
  if (null >= 0) ::close(null);
  return saved;
}

void restoreStderr(int token) {
  if (token < 0) return;
  ::dup2(token, STDERR_FILENO);
#if defined(PATHLAB_SANITIZED)
  __sanitizer_set_report_fd(reinterpret_cast<void*>(intptr_t(STDERR_FILENO)));
#endif
  ::close(token);
}

void withStopSignalsBlockedInNewThreads(const std::function<void()>& body) {
  // Threads inherit the mask of the thread that starts them. Under
  // ThreadSanitizer too this matters: it defers a signal that lands in a
  // thread busy computing until that thread calls into the C library.
  sigset_t stop, previous;
  sigemptyset(&stop);
  sigaddset(&stop, SIGINT);
  sigaddset(&stop, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &stop, &previous);
  try {
    body();
  } catch (...) {
    pthread_sigmask(SIG_SETMASK, &previous, nullptr);
    throw;
  }
  pthread_sigmask(SIG_SETMASK, &previous, nullptr);
}

void exitFromSignalHandler(std::string_view message, int code) {
  [[maybe_unused]] const ssize_t ignored = ::write(STDERR_FILENO, message.data(), message.size());
  ::_exit(code);
}

}  // namespace pathlab

#endif  // !_WIN32
