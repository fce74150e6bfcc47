// platform.h on Windows (Win32 and the C runtime). platform_posix.cpp is the
// other half; each compiles to nothing on the other's systems.
#if defined(_WIN32)

#include "util/platform.h"

#ifndef NOMINMAX
#define NOMINMAX
#endif
#define WIN32_LEAN_AND_MEAN
#include <windows.h>

#include <fcntl.h>
#include <io.h>
#include <process.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace pathlab {
namespace {

// Paths are UTF-8 in PathLab, UTF-16 for Windows' W functions.
std::wstring widen(const std::string& text) {
  if (text.empty()) return {};
  const int n = MultiByteToWideChar(CP_UTF8, 0, text.data(), int(text.size()), nullptr, 0);
  std::wstring wide(size_t(n > 0 ? n : 0), L'\0');
  if (n > 0) MultiByteToWideChar(CP_UTF8, 0, text.data(), int(text.size()), wide.data(), n);
  return wide;
}

// The system's words for an error code.
std::string describeError(DWORD code) {
  char* text = nullptr;
  const DWORD n = FormatMessageA(FORMAT_MESSAGE_ALLOCATE_BUFFER | FORMAT_MESSAGE_FROM_SYSTEM |
                                     FORMAT_MESSAGE_IGNORE_INSERTS,
                                 nullptr, code, 0, reinterpret_cast<char*>(&text), 0, nullptr);
  std::string message = n && text ? std::string(text, n) : "error " + std::to_string(code);
  if (text) LocalFree(text);
  while (!message.empty() && (message.back() == '\n' || message.back() == '\r' || message.back() == '.')) {
    message.pop_back();
  }
  return message;
}

bool isMissing(DWORD code) { return code == ERROR_FILE_NOT_FOUND || code == ERROR_PATH_NOT_FOUND; }

// Closes the handle on every path out.
struct Handle {
  HANDLE h = INVALID_HANDLE_VALUE;
  ~Handle() {
    if (h != INVALID_HANDLE_VALUE) CloseHandle(h);
  }
};

FileKind kindOfOpen(HANDLE h, bool folder) {
  if (folder) return FileKind::Folder;
  switch (GetFileType(h)) {
    case FILE_TYPE_DISK: return FileKind::Regular;
    case FILE_TYPE_PIPE: return FileKind::Pipe;
    case FILE_TYPE_CHAR: return FileKind::Device;
    default: return FileKind::Other;
  }
}

}  // namespace

FileStatus fileStatus(const std::string& path) {
  FileStatus status;
  WIN32_FILE_ATTRIBUTE_DATA data{};
  if (!GetFileAttributesExW(widen(path).c_str(), GetFileExInfoStandard, &data)) {
    const DWORD code = GetLastError();
    status.missing = isMissing(code);
    status.error = describeError(code);
    return status;
  }
  status.found = true;
  status.kind = (data.dwFileAttributes & FILE_ATTRIBUTE_DIRECTORY) ? FileKind::Folder : FileKind::Regular;
  status.size = (uint64_t(data.nFileSizeHigh) << 32) | data.nFileSizeLow;
  return status;
}

FileRead readRegularFile(const std::string& path, size_t maxBytes) {
  FileRead read;
  // FILE_FLAG_BACKUP_SEMANTICS opens a folder too, so it is named, not "access denied".
  Handle file{CreateFileW(widen(path).c_str(), GENERIC_READ, FILE_SHARE_READ | FILE_SHARE_WRITE, nullptr,
                          OPEN_EXISTING, FILE_FLAG_BACKUP_SEMANTICS, nullptr)};
  if (file.h == INVALID_HANDLE_VALUE) {
    read.error = describeError(GetLastError());
    return read;
  }
  read.opened = true;
  BY_HANDLE_FILE_INFORMATION info{};
  const bool folder = GetFileInformationByHandle(file.h, &info) && (info.dwFileAttributes & FILE_ATTRIBUTE_DIRECTORY);
  read.kind = kindOfOpen(file.h, folder);
  if (read.kind != FileKind::Regular) return read;
  LARGE_INTEGER size{};
  if (!GetFileSizeEx(file.h, &size)) {
    read.error = describeError(GetLastError());
    return read;
  }
  read.size = uint64_t(size.QuadPart);
  if (read.size > maxBytes) return read;
  read.bytes.resize(size_t(read.size));
  size_t done = 0;
  while (done < read.bytes.size()) {
    DWORD n = 0;
    const DWORD chunk = DWORD(std::min<size_t>(read.bytes.size() - done, 1u << 30));
    if (!ReadFile(file.h, read.bytes.data() + done, chunk, &n, nullptr)) {
      read.error = describeError(GetLastError());
      return read;
    }
    if (n == 0) break;  // the file shrank while we read: what is there is what we have
    done += n;
  }
  read.bytes.resize(done);
  return read;
}

std::string writeFileDurably(const std::string& path, std::string_view bytes) {
  const std::wstring wide = widen(path);
  // Created afresh (CREATE_NEW), never through a file or link already there.
  Handle file{CreateFileW(wide.c_str(), GENERIC_WRITE, 0, nullptr, CREATE_NEW, FILE_ATTRIBUTE_NORMAL, nullptr)};
  if (file.h == INVALID_HANDLE_VALUE && GetLastError() == ERROR_FILE_EXISTS && DeleteFileW(wide.c_str())) {
    file.h = CreateFileW(wide.c_str(), GENERIC_WRITE, 0, nullptr, CREATE_NEW, FILE_ATTRIBUTE_NORMAL, nullptr);
  }
  if (file.h == INVALID_HANDLE_VALUE) return describeError(GetLastError());
  auto fail = [&](DWORD code) {
    CloseHandle(file.h);
    file.h = INVALID_HANDLE_VALUE;
    DeleteFileW(wide.c_str());
    return describeError(code);
  };
  size_t done = 0;
  while (done < bytes.size()) {
    DWORD n = 0;
    const DWORD chunk = DWORD(std::min<size_t>(bytes.size() - done, 1u << 30));
    if (!WriteFile(file.h, bytes.data() + done, chunk, &n, nullptr)) return fail(GetLastError());
    if (n == 0) return fail(ERROR_DISK_FULL);
    done += n;
  }
  if (!FlushFileBuffers(file.h)) return fail(GetLastError());
  const HANDLE h = file.h;
  file.h = INVALID_HANDLE_VALUE;
  if (!CloseHandle(h)) {
    const DWORD code = GetLastError();
    DeleteFileW(wide.c_str());
    return describeError(code);
  }
  return "";
}

std::string replaceFile(const std::string& from, const std::string& to) {
  if (MoveFileExW(widen(from).c_str(), widen(to).c_str(), MOVEFILE_REPLACE_EXISTING | MOVEFILE_WRITE_THROUGH)) {
    return "";
  }
  return describeError(GetLastError());
}

void removeFileQuietly(const std::string& path) { DeleteFileW(widen(path).c_str()); }

bool folderIsWritable(const std::string& path) {
  // The read-only attribute is what a folder's writability means to the C runtime.
  return _waccess(widen(path).c_str(), 2) == 0;
}

size_t maxFileNameBytes() { return 255; }

long currentProcessId() { return long(GetCurrentProcessId()); }

double currentThreadCpuSeconds() {
  FILETIME created, exited, kernel, user;
  if (!GetThreadTimes(GetCurrentThread(), &created, &exited, &kernel, &user)) return 0.0;
  auto ticks = [](const FILETIME& t) { return (uint64_t(t.dwHighDateTime) << 32) | t.dwLowDateTime; };
  return 1e-7 * double(ticks(kernel) + ticks(user));  // 100-nanosecond ticks
}

std::string currentExecutablePath() {
  std::wstring path(MAX_PATH, L'\0');
  for (;;) {
    const DWORD n = GetModuleFileNameW(nullptr, path.data(), DWORD(path.size()));
    if (n == 0) return "";
    if (n < path.size()) {
      path.resize(n);
      break;
    }
    path.resize(path.size() * 2);  // truncated: try a longer buffer
  }
  const int bytes = WideCharToMultiByte(CP_UTF8, 0, path.data(), int(path.size()), nullptr, 0, nullptr, nullptr);
  std::string utf8(size_t(bytes > 0 ? bytes : 0), '\0');
  if (bytes > 0) WideCharToMultiByte(CP_UTF8, 0, path.data(), int(path.size()), utf8.data(), bytes, nullptr, nullptr);
  return utf8;
}

void* loadSharedLibrary(const std::string& path, std::string& error) {
  // The DLL's own dependencies are looked for beside it first, then on PATH.
  HMODULE library = LoadLibraryExW(widen(path).c_str(), nullptr, LOAD_WITH_ALTERED_SEARCH_PATH);
  if (!library) error = describeError(GetLastError());
  return reinterpret_cast<void*>(library);
}

void* sharedLibraryFunction(void* library, const char* name) {
  return reinterpret_cast<void*>(GetProcAddress(static_cast<HMODULE>(library), name));
}

namespace {
// One argument as the C runtime's command-line parser reads it back
// (CommandLineToArgvW's rules): quoted, a quote escaped with a backslash,
// and the backslashes before a quote or the closing quote doubled.
std::wstring quoteArgument(const std::wstring& argument) {
  std::wstring quoted = L"\"";
  size_t backslashes = 0;
  for (const wchar_t c : argument) {
    if (c == L'\\') {
      ++backslashes;
      continue;
    }
    quoted.append(c == L'"' ? 2 * backslashes + 1 : backslashes, L'\\');
    backslashes = 0;
    quoted.push_back(c);
  }
  quoted.append(2 * backslashes, L'\\');
  return quoted + L"\"";
}
}  // namespace

int runProgram(const std::string& path, const std::vector<std::string>& arguments, std::string& error) {
  // _wspawnv joins its arguments with spaces as they are: each is quoted here.
  std::vector<std::wstring> quoted{quoteArgument(widen(path))};
  for (const std::string& argument : arguments) quoted.push_back(quoteArgument(widen(argument)));
  std::vector<const wchar_t*> argv;
  for (const std::wstring& argument : quoted) argv.push_back(argument.c_str());
  argv.push_back(nullptr);
  const intptr_t code = _wspawnv(_P_WAIT, widen(path).c_str(), argv.data());
  if (code == -1) {
    error = std::strerror(errno);
    return -1;
  }
  return int(code);
}

bool stderrIsTerminal() { return _isatty(_fileno(stderr)) != 0; }

int silenceStderr() {
  const int saved = _dup(2);
  const int null = _open("NUL", _O_WRONLY);
  if (saved >= 0 && null >= 0) _dup2(null, 2);
  if (null >= 0) _close(null);
  return saved;
}

void restoreStderr(int token) {
  if (token < 0) return;
  _dup2(token, 2);
  _close(token);
}

// The C runtime calls a SIGINT handler on a thread of its own: the workers need no mask.
void withStopSignalsBlockedInNewThreads(const std::function<void()>& body) { body(); }

void exitFromSignalHandler(std::string_view message, int code) {
  _write(2, message.data(), unsigned(message.size()));
  _exit(code);
}

}  // namespace pathlab

#endif  // _WIN32
