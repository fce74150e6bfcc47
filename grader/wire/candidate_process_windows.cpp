// candidate_process.h on Windows: anonymous pipes, CreateProcess, exit
// codes. The candidate finds its request and answer pipes through
// PATHLAB_CANDIDATE_PIPES ("<request handle> <answer handle>", inherited).
#if defined(_WIN32)

#include "candidate_process.h"

#ifndef NOMINMAX
#define NOMINMAX
#endif
#define WIN32_LEAN_AND_MEAN
#include <windows.h>

#include <fcntl.h>
#include <io.h>

#include <cstdio>
#include <cstdlib>

#include "call.h"

namespace pathlab::remote {
namespace {

// TerminateProcess's exit code: a candidate the judge ended, not one that crashed.
constexpr UINT kKilledByJudge = 0x4A554447;  // "JUDG"

std::wstring widen(const std::string& text) {
  const int n = MultiByteToWideChar(CP_UTF8, 0, text.c_str(), -1, nullptr, 0);
  std::wstring wide(size_t(n > 0 ? n : 1), L'\0');
  if (n > 0) MultiByteToWideChar(CP_UTF8, 0, text.c_str(), -1, wide.data(), n);
  wide.resize(wide.size() - 1);
  return wide;
}

std::string lastError(const char* what) {
  return std::string(what) + " failed (error " + std::to_string(GetLastError()) + ")";
}

// The exceptions a crashing program ends with, as their names.
std::string exceptionName(DWORD code) {
  switch (code) {
    case EXCEPTION_ACCESS_VIOLATION: return "access violation";
    case EXCEPTION_STACK_OVERFLOW: return "stack overflow";
    case EXCEPTION_INT_DIVIDE_BY_ZERO: return "integer division by zero";
    case EXCEPTION_ILLEGAL_INSTRUCTION: return "illegal instruction";
    case EXCEPTION_ARRAY_BOUNDS_EXCEEDED: return "array bounds exceeded";
    case 0xC0000409: return "stack buffer overrun or fast fail";
    default: return "exception";
  }
}

// A pipe whose `inherited` end the child gets; the other end becomes a C
// runtime descriptor the judge keeps.
struct Pipe {
  HANDLE read = nullptr, write = nullptr;
};
Pipe makePipe(bool childReads) {
  SECURITY_ATTRIBUTES inherit{sizeof(SECURITY_ATTRIBUTES), nullptr, TRUE};
  Pipe pipe;
  if (!CreatePipe(&pipe.read, &pipe.write, &inherit, 1 << 20)) throw CandidateError(lastError("CreatePipe"));
  SetHandleInformation(childReads ? pipe.write : pipe.read, HANDLE_FLAG_INHERIT, 0);  // the judge's end
  return pipe;
}

int toDescriptor(HANDLE handle, int flags) {
  const int fd = _open_osfhandle(reinterpret_cast<intptr_t>(handle), flags | _O_BINARY);
  if (fd < 0) {
    CloseHandle(handle);
    throw CandidateError("_open_osfhandle failed");
  }
  return fd;
}

}  // namespace

CandidatePipes CandidateProcess::start(const std::string& path) {
  const Pipe requests = makePipe(true), answers = makePipe(false), output = makePipe(false);
  SECURITY_ATTRIBUTES inherit{sizeof(SECURITY_ATTRIBUTES), nullptr, TRUE};
  HANDLE nul =
      CreateFileW(L"NUL", GENERIC_READ, FILE_SHARE_READ | FILE_SHARE_WRITE, &inherit, OPEN_EXISTING, 0, nullptr);
  // The child learns its pipes' handle values (inherited handles keep their values).
  const std::string pipes = std::to_string(reinterpret_cast<uintptr_t>(requests.read)) + " " +
                            std::to_string(reinterpret_cast<uintptr_t>(answers.write));
  SetEnvironmentVariableA("PATHLAB_CANDIDATE_PIPES", pipes.c_str());
  STARTUPINFOW startup{};
  startup.cb = sizeof startup;
  startup.dwFlags = STARTF_USESTDHANDLES;
  startup.hStdInput = nul;
  startup.hStdOutput = output.write;
  startup.hStdError = output.write;
  PROCESS_INFORMATION process{};
  std::wstring commandLine = L"\"" + widen(path) + L"\"";
  const BOOL started = CreateProcessW(widen(path).c_str(), commandLine.data(), nullptr, nullptr, TRUE, CREATE_NO_WINDOW,
                                      nullptr, nullptr, &startup, &process);
  const DWORD error = GetLastError();
  SetEnvironmentVariableA("PATHLAB_CANDIDATE_PIPES", nullptr);
  for (HANDLE childEnd : {requests.read, answers.write, output.write, nul}) CloseHandle(childEnd);
  if (!started) {
    for (HANDLE judgeEnd : {requests.write, answers.read, output.read}) CloseHandle(judgeEnd);
    throw CandidateError("cannot start the candidate " + path + " (error " + std::to_string(error) + ")");
  }
  CloseHandle(process.hThread);
  handle_ = reinterpret_cast<long long>(process.hProcess);
  return {toDescriptor(requests.write, 0), toDescriptor(answers.read, _O_RDONLY), toDescriptor(output.read, _O_RDONLY)};
}

std::string CandidateProcess::reap(int graceMs) {
  HANDLE process = reinterpret_cast<HANDLE>(handle_);
  if (WaitForSingleObject(process, DWORD(graceMs)) != WAIT_OBJECT_0) {
    TerminateProcess(process, kKilledByJudge);  // still alive with its pipes closed
    WaitForSingleObject(process, INFINITE);
  }
  DWORD code = 0;
  GetExitCodeProcess(process, &code);
  CloseHandle(process);
  handle_ = 0;
  if (code == kKilledByJudge) return "the candidate stopped";
  if ((code & 0xF0000000u) == 0xC0000000u) {  // an NTSTATUS error: the process died of an exception
    char hex[16];
    std::snprintf(hex, sizeof hex, "0x%08lX", static_cast<unsigned long>(code));
    return "the task's code crashed (" + exceptionName(code) + ", " + hex + ")";
  }
  return "the candidate exited (exit code " + std::to_string(code) + ")";
}

void CandidateProcess::kill() {
  if (handle_ == 0) return;
  HANDLE process = reinterpret_cast<HANDLE>(handle_);
  TerminateProcess(process, kKilledByJudge);
  WaitForSingleObject(process, INFINITE);
  CloseHandle(process);
  handle_ = 0;
}

int CandidateProcess::waitReadable(int fd, int ms) {
  HANDLE pipe = reinterpret_cast<HANDLE>(_get_osfhandle(fd));
  for (int waited = 0;; waited += 5) {
    DWORD available = 0;
    if (!PeekNamedPipe(pipe, nullptr, 0, nullptr, &available, nullptr)) {
      return GetLastError() == ERROR_BROKEN_PIPE ? 1 : -1;  // its end: the read returns 0
    }
    if (available > 0) return 1;
    if (waited >= ms) return 0;
    Sleep(5);
  }
}

namespace {
int inheritedPipe(int which, int flags) {
  const char* pipes = std::getenv("PATHLAB_CANDIDATE_PIPES");
  if (!pipes) return -1;
  char* end = nullptr;
  unsigned long long handle = std::strtoull(pipes, &end, 10);
  if (which == 1) handle = std::strtoull(end, nullptr, 10);
  if (handle == 0) return -1;
  return _open_osfhandle(static_cast<intptr_t>(handle), flags | _O_BINARY);
}
}  // namespace

int candidateRequestFd() {
  static const int fd = inheritedPipe(0, _O_RDONLY);
  return fd;
}
int candidateResponseFd() {
  static const int fd = inheritedPipe(1, 0);
  return fd;
}

void candidateDiesWithJudge() {}  // it goes at its next read: the request pipe is closed

}  // namespace pathlab::remote

#endif  // _WIN32
