// The judge's side of remote calls: starts the candidate process, sends it
// requests, and turns a crash, an exception or a malformed answer into a
// CandidateError for the test that made the call.
//
// The candidate is $PATHLAB_CANDIDATE (the grader points it at a launcher
// that runs the candidate in a sandbox), else candidate-NN-name beside this
// test-NN-name (the build's own, as ctest runs it).
#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <mutex>
#include <string>
#include <thread>

#include "call.h"
#include "protocol.h"
#include "util/platform.h"

#if defined(__GLIBC__)
#include <malloc.h>
#endif

extern char** environ;

namespace pathlab::remote {
namespace {

constexpr size_t kOutputKept = 8192;  // bytes of the candidate's output shown under a failing test

std::string candidatePath() {
  if (const char* path = std::getenv("PATHLAB_CANDIDATE"); path && *path) return path;
  const std::string exe = currentExecutablePath();
  if (exe.empty()) throw CandidateError("cannot find this executable's folder: set PATHLAB_CANDIDATE");
  // test-NN-name's candidate is candidate-NN-name in the same folder.
  const size_t slash = exe.rfind('/');
  std::string name = exe.substr(slash + 1);
  if (name.rfind("test-", 0) == 0) name = name.substr(5);
  return exe.substr(0, slash) + "/candidate-" + name;
}

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

// Batches of megabytes are encoded, sent and decoded over and over: keep
// freed memory in the heap instead of returning it to the kernel, or every
// batch pays a page fault per 4 KB again (half the time of a big batch).
// (glibc's malloc; macOS's keeps freed memory anyway.)
void keepLargeBuffers() {
#if defined(__GLIBC__)
  mallopt(M_MMAP_THRESHOLD, 1 << 30);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
#endif
}

class Candidate {
 public:
  ~Candidate() { stop(); }

  std::string exchange(uint32_t id, const char* name, const std::string& request) {
    if (pid_ < 0) start();
    uint32_t status = 0;
    std::string answer;
    bool answered = false;
    try {
      writeMessage(toCandidate_, kRequestMagic, id, request);
      answered = readMessage(fromCandidate_, kResponseMagic, status, answer);
    } catch (const std::exception& e) {
      const std::string how = died(name);
      throw CandidateError(how.empty() ? std::string("the candidate broke the protocol during ") + name + ": " + e.what()
                                       : how);
    }
    if (!answered) throw CandidateError(died(name));
    switch (Status(status)) {
      case Status::Ok:
        return answer;
      case Status::Threw:
        throw CandidateError(std::string("the task's code threw an exception in ") + name + ": " + printable(answer));
      case Status::UnknownCall:
        throw CandidateError(std::string("the candidate does not serve ") + name + " (built for another suite?)");
      default:
        throw CandidateError(std::string("the candidate could not read the request for ") + name + ": " +
                             printable(answer));
    }
  }

  std::string takeOutput() {
    std::lock_guard<std::mutex> lock(outputMutex_);
    std::string text = printable(output_);
    if (dropped_ > 0) text += "\n[... " + std::to_string(dropped_) + " more bytes of output not shown ...]";
    output_.clear();
    dropped_ = 0;
    return text;
  }

 private:
  void start() {
    std::signal(SIGPIPE, SIG_IGN);  // a dead candidate is an error on write, not a signal
    keepLargeBuffers();
    int requests[2], answers[2], output[2];
    if (::pipe(requests) != 0 || ::pipe(answers) != 0 || ::pipe(output) != 0) {
      throw CandidateError(std::string("pipe failed: ") + std::strerror(errno));
    }
    for (int* fds : {requests, answers, output}) {
      fds[0] = high(fds[0]), fds[1] = high(fds[1]);
#if defined(F_SETPIPE_SZ)  // Linux only
      ::fcntl(fds[0], F_SETPIPE_SZ, 1 << 20);  // batches of megabytes in few round trips
#endif
    }
    const std::string path = candidatePath();
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_adddup2(&actions, output[1], 1);
    posix_spawn_file_actions_adddup2(&actions, output[1], 2);
    posix_spawn_file_actions_adddup2(&actions, requests[0], kRequestFd);
    posix_spawn_file_actions_adddup2(&actions, answers[1], kResponseFd);
    char* argv[] = {const_cast<char*>(path.c_str()), nullptr};
    const int error = posix_spawn(&pid_, path.c_str(), &actions, nullptr, argv, environ);
    posix_spawn_file_actions_destroy(&actions);
    ::close(requests[0]);
    ::close(answers[1]);
    ::close(output[1]);
    if (error != 0) {
      pid_ = -1;
      ::close(requests[1]);
      ::close(answers[0]);
      ::close(output[0]);
      throw CandidateError("cannot start the candidate " + path + ": " + std::strerror(error));
    }
    toCandidate_ = requests[1];
    fromCandidate_ = answers[0];
    drain_ = std::thread([this, fd = output[0]] { drainOutput(fd); });
  }

  // Keeps what the candidate prints. A process it left behind may hold the
  // pipe open forever: once the candidate is gone, drain what is there and stop.
  void drainOutput(int fd) {
    char buffer[4096];
    for (;;) {
      pollfd p{fd, POLLIN, 0};
      const int ready = ::poll(&p, 1, 50);
      if (ready < 0 && errno == EINTR) continue;
      if (ready <= 0) {
        if (candidateGone_) break;
        continue;
      }
      const ssize_t n = ::read(fd, buffer, sizeof buffer);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) break;
      std::lock_guard<std::mutex> lock(outputMutex_);
      const size_t keep = std::min(size_t(n), kOutputKept - std::min(kOutputKept, output_.size()));
      output_.append(buffer, keep);
      dropped_ += size_t(n) - keep;
    }
    ::close(fd);
  }

  void joinDrain() {
    candidateGone_ = true;
    if (drain_.joinable()) drain_.join();
    candidateGone_ = false;
  }

  // Reaps a candidate that stopped answering; describes how it ended.
  std::string died(const char* name) {
    ::close(toCandidate_);
    ::close(fromCandidate_);
    toCandidate_ = fromCandidate_ = -1;
    int status = 0;
    // Let a crashing candidate (or the sandbox reporting its crash) finish
    // exiting before the kill, so its own end is the one reported.
    pid_t done = 0;
    for (int i = 0; i < 100 && (done = ::waitpid(pid_, &status, WNOHANG)) == 0; ++i) ::usleep(10000);
    if (done == 0) {
      ::kill(pid_, SIGKILL);  // still alive with its pipes closed
      while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
      }
    }
    pid_ = -1;
    joinDrain();
    std::string how;
    if (WIFSIGNALED(status) && WTERMSIG(status) != SIGKILL) {
      how = "the task's code crashed (" + signalName(WTERMSIG(status)) + ")";
    } else if (WIFEXITED(status) && WEXITSTATUS(status) > 128 && WEXITSTATUS(status) < 128 + 32) {
      // The sandbox reports its child's death by signal k as exit code 128 + k.
      how = "the task's code crashed (" + signalName(WEXITSTATUS(status) - 128) + ")";
    } else if (WIFEXITED(status)) {
      how = "the candidate exited (exit code " + std::to_string(WEXITSTATUS(status)) + ")";
    } else {
      how = "the candidate stopped";
    }
    return how + " while computing " + name;
  }

  void stop() {
    if (pid_ < 0) return;
    ::close(toCandidate_);  // end of requests: a well-behaved candidate exits
    ::close(fromCandidate_);
    ::kill(pid_, SIGKILL);  // one stuck in the task's code does not
    int status = 0;
    while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
    }
    pid_ = -1;
    joinDrain();
  }

  static std::string printable(const std::string& text) {
    std::string out;
    out.reserve(text.size());
    for (unsigned char c : text) out += (c == '\n' || c == '\t' || (c >= 32 && c < 127)) ? char(c) : '?';
    return out;
  }

  pid_t pid_ = -1;
  int toCandidate_ = -1, fromCandidate_ = -1;
  std::thread drain_;
  std::atomic<bool> candidateGone_{false};
  std::mutex outputMutex_;
  std::string output_;
  size_t dropped_ = 0;
};

Candidate& candidate() {
  static Candidate instance;
  return instance;
}

std::mutex callMutex;  // tests may call from several threads; one request at a time

}  // namespace

std::string exchange(uint32_t id, const char* name, const std::string& request) {
  std::lock_guard<std::mutex> lock(callMutex);
  return candidate().exchange(id, name, request);
}

std::string takeCandidateOutput() { return candidate().takeOutput(); }

}  // namespace pathlab::remote
