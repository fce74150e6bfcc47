// candidate_process.h on Linux and macOS.
#if !defined(_WIN32)

#include "candidate_process.h"

#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>
#if defined(__linux__)
#include <sys/prctl.h>
#endif

#include <cerrno>
#include <csignal>
#include <cstring>

#include "call.h"
#include "protocol.h"

extern char** environ;

namespace pathlab::remote {
namespace {

std::string signalName(int signal) {
#if defined(__GLIBC__) && (__GLIBC__ > 2 || __GLIBC_MINOR__ >= 32)
  const char* name = sigabbrev_np(signal);
#else
  const char* name = nullptr;  // macOS and older C libraries: the number and the text
#endif
  const char* text = strsignal(signal);
  return std::string(name ? "SIG" + std::string(name) : "signal " + std::to_string(signal)) +
         (text ? std::string(", ") + text : "");
}

// A descriptor number >= 10, close-on-exec, so the child's 0-4 never collide with it.
int high(int fd) {
  const int moved = ::fcntl(fd, F_DUPFD_CLOEXEC, 10);
  ::close(fd);
  if (moved < 0) throw CandidateError(std::string("fcntl failed: ") + std::strerror(errno));
  return moved;
}

}  // namespace

CandidatePipes CandidateProcess::start(const std::string& path) {
  std::signal(SIGPIPE, SIG_IGN);  // a dead candidate is an error on write, not a signal
  int requests[2], answers[2], output[2];
  if (::pipe(requests) != 0 || ::pipe(answers) != 0 || ::pipe(output) != 0) {
    throw CandidateError(std::string("pipe failed: ") + std::strerror(errno));
  }
  for (int* fds : {requests, answers, output}) {
    fds[0] = high(fds[0]), fds[1] = high(fds[1]);
#if defined(F_SETPIPE_SZ)                    // Linux only
    ::fcntl(fds[0], F_SETPIPE_SZ, 1 << 20);  // batches of megabytes in few round trips
#endif
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_adddup2(&actions, output[1], 1);
  posix_spawn_file_actions_adddup2(&actions, output[1], 2);
  posix_spawn_file_actions_adddup2(&actions, requests[0], kRequestFd);
  posix_spawn_file_actions_adddup2(&actions, answers[1], kResponseFd);
  char* argv[] = {const_cast<char*>(path.c_str()), nullptr};
  pid_t pid = -1;
  const int error = posix_spawn(&pid, path.c_str(), &actions, nullptr, argv, environ);
  posix_spawn_file_actions_destroy(&actions);
  ::close(requests[0]);
  ::close(answers[1]);
  ::close(output[1]);
  if (error != 0) {
    ::close(requests[1]);
    ::close(answers[0]);
    ::close(output[0]);
    throw CandidateError("cannot start the candidate " + path + ": " + std::strerror(error));
  }
  handle_ = pid;
  return {requests[1], answers[0], output[0]};
}

std::string CandidateProcess::reap(int graceMs) {
  const pid_t pid = pid_t(handle_);
  int status = 0;
  pid_t done = 0;
  for (int waited = 0; waited < graceMs && (done = ::waitpid(pid, &status, WNOHANG)) == 0; waited += 10) {
    ::usleep(10000);
  }
  if (done == 0) {
    ::kill(pid, SIGKILL);  // still alive with its pipes closed
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
  }
  handle_ = 0;
  if (WIFSIGNALED(status) && WTERMSIG(status) != SIGKILL) {
    return "the task's code crashed (" + signalName(WTERMSIG(status)) + ")";
  }
  if (WIFEXITED(status) && WEXITSTATUS(status) > 128 && WEXITSTATUS(status) < 128 + 32) {
    // The grader's sandbox reports its child's death by signal k as exit code 128 + k.
    return "the task's code crashed (" + signalName(WEXITSTATUS(status) - 128) + ")";
  }
  if (WIFEXITED(status)) return "the candidate exited (exit code " + std::to_string(WEXITSTATUS(status)) + ")";
  return "the candidate stopped";
}

void CandidateProcess::kill() {
  if (handle_ == 0) return;
  const pid_t pid = pid_t(handle_);
  ::kill(pid, SIGKILL);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  handle_ = 0;
}

int CandidateProcess::waitReadable(int fd, int ms) {
  pollfd p{fd, POLLIN, 0};
  const int ready = ::poll(&p, 1, ms);
  if (ready < 0) return errno == EINTR ? 0 : -1;
  return ready > 0 ? 1 : 0;
}

int candidateRequestFd() { return ::fcntl(kRequestFd, F_GETFD) == -1 ? -1 : kRequestFd; }
int candidateResponseFd() { return ::fcntl(kResponseFd, F_GETFD) == -1 ? -1 : kResponseFd; }

void candidateDiesWithJudge() {
#if defined(__linux__)
  // Outside a sandbox (ctest), a candidate whose judge died goes with it
  // (elsewhere it goes at its next read: the request pipe is closed).
  prctl(PR_SET_PDEATHSIG, SIGKILL);
#endif
}

}  // namespace pathlab::remote

#endif  // !_WIN32
