// What PathLab asks of the operating system, in one place: file checks,
// durable writes, the terminal, stderr and Ctrl-C. Answered by
// platform_posix.cpp on Linux and macOS and by platform_windows.cpp on
// Windows; everything else in the framework is standard C++.
// Paths are UTF-8. Failures come back as the system's own words ("No such
// file or directory"), for the caller to put in a message.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace pathlab {

enum class FileKind { Regular, Folder, Pipe, Device, Socket, Other };

// "is a folder", "is a FIFO (a pipe)", ...: what a path is, when a file was expected.
inline std::string describeFileKind(FileKind kind) {
  switch (kind) {
    case FileKind::Folder: return "is a folder";
    case FileKind::Pipe: return "is a FIFO (a pipe)";
    case FileKind::Device: return "is a device";
    case FileKind::Socket: return "is a socket";
    default: return "is not a regular file";
  }
}

// A path looked up, links followed.
struct FileStatus {
  bool found = false;
  bool missing = false;  // not found because nothing is there (not: no permission, a loop, ...)
  std::string error;     // why it was not found
  FileKind kind = FileKind::Other;
  uint64_t size = 0;     // bytes, for a regular file
};
FileStatus fileStatus(const std::string& path);

// A regular file read whole, if it holds at most maxBytes: opened first and
// then looked at, so what is read is what was checked. Opening never waits
// (a pipe with no writer is refused, not waited for).
struct FileRead {
  bool opened = false;
  std::string error;  // why it could not be opened or read
  FileKind kind = FileKind::Other;
  uint64_t size = 0;  // when larger than maxBytes, nothing is read
  std::string bytes;
};
FileRead readRegularFile(const std::string& path, size_t maxBytes);

// Creates `path` as a new file (one already there, or a link, is removed
// first, never written through), writes `bytes` and flushes them to the
// device; on failure removes what it wrote. Returns "" or why it failed.
std::string writeFileDurably(const std::string& path, std::string_view bytes);
// Renames `from` to `to`, replacing `to`. Returns "" or why it failed.
std::string replaceFile(const std::string& from, const std::string& to);
void removeFileQuietly(const std::string& path);
bool folderIsWritable(const std::string& path);
// The longest file name (one path component) the system takes, in bytes.
size_t maxFileNameBytes();

// This process's id: names a scratch folder no other process shares.
long currentProcessId();
// CPU seconds the calling thread has run: times one thread's work without
// counting the moments a busy machine gave its core to another process.
double currentThreadCpuSeconds();
// The running program's own file, as an absolute path ("" if the system will
// not say): finds the files built beside it.
std::string currentExecutablePath();

// A shared library opened at run time (the image codec: OpenImageIO and the
// libraries it brings load only when a program first reads or writes an
// image). Returns its handle, or null with `error` set to the system's words.
// Libraries stay loaded until the process ends.
void* loadSharedLibrary(const std::string& path, std::string& error);
// The address of the function `name` in a library loadSharedLibrary opened, or null.
void* sharedLibraryFunction(void* library, const char* name);

// Runs the program at `path` with `arguments` and waits for it to end. No
// shell: each argument reaches it whole, spaces and quotes included. Its
// output goes where this process's goes. Returns its exit code, or -1 with
// `error` set when it could not start or did not exit by itself (a signal).
int runProgram(const std::string& path, const std::vector<std::string>& arguments, std::string& error);

bool stderrIsTerminal();
// Sends stderr to the null device until restoreStderr(token); a library's
// chatter during a read stays off the user's screen. Process-wide: callers
// serialise.
int silenceStderr();
void restoreStderr(int token);

// Runs `body` with Ctrl-C and termination requests kept from the threads it
// starts (POSIX: SIGINT and SIGTERM blocked, so the waiting caller's handler
// runs at once; Windows runs console handlers on a thread of their own).
void withStopSignalsBlockedInNewThreads(const std::function<void()>& body);
// From a signal handler: writes `message` to stderr and ends the process
// with `code`, without running anything that is unsafe there.
[[noreturn]] void exitFromSignalHandler(std::string_view message, int code);

}  // namespace pathlab
