// The judge's side of remote calls: starts the candidate process, sends it
// requests, and turns a crash, an exception or a malformed answer into a
// CandidateError for the test that made the call.
//
// The candidate is $PATHLAB_CANDIDATE (the grader points it at a launcher
// that runs the candidate in a sandbox), else candidate-NN-name beside this
// test-NN-name (the build's own, as ctest runs it). Starting, watching and
// ending the process is candidate_process.h's, one half per system.
#include <atomic>
#include <cstdlib>
#include <mutex>
#include <string>
#include <thread>

#include "call.h"
#include "candidate_process.h"
#include "protocol.h"
#include "suite/verdicts.h"
#include "util/platform.h"

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace pathlab::remote {
namespace {

constexpr size_t kOutputKept = 8192;  // bytes of the candidate's output shown under a failing test
// A candidate that died this often in one test is not started again in it:
// its later calls fail at once. (Each start of a sandboxed candidate takes
// tens of milliseconds: a crash in a loop of 400 calls would spend the
// test's time limit on restarts, and the crash would read as a timeout.)
constexpr int kDeathsPerTest = 3;

std::string candidatePath() {
  if (const char* path = std::getenv(verdicts::kCandidateVariable); path && *path) return path;
  const std::string exe = currentExecutablePath();
  if (exe.empty()) throw CandidateError("cannot find this executable's folder: set PATHLAB_CANDIDATE");
  // test-NN-name's candidate is candidate-NN-name in the same folder.
  // (Windows: backslashes, and both end in .exe.)
  const size_t slash = exe.find_last_of("/\\");
  std::string name = exe.substr(slash + 1);
  if (name.rfind("test-", 0) == 0) name = name.substr(5);
  return exe.substr(0, slash + 1) + "candidate-" + name;
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

  std::string exchange(uint32_t id, const char* name, const std::string& request, uint64_t maxAnswerBytes,
                       const AskHandler* asks) {
    if (deaths_ >= kDeathsPerTest) {
      throw CandidateError(lastDeath_ + "; not started again in this test after " + std::to_string(deaths_) +
                           " such ends (while computing " + name + ")");
    }
    if (!process_.running()) start();
    uint32_t status = 0;
    std::string answer;
    bool answered = false;
    try {
      writeMessage(toCandidate_, kRequestMagic, id, request);
      // Asks first, each answered, until the answer comes.
      while ((answered = readMessage(fromCandidate_, kResponseMagic, status, answer, maxAnswerBytes)) &&
             Status(status) == Status::Asks) {
        if (!asks)
          throw CandidateError(std::string("the candidate asked the judge for data during ") + name +
                               ", which serves none");
        writeMessage(toCandidate_, kRequestMagic, kReplyId, (*asks)(answer));
      }
    } catch (const CandidateError&) {
      stop();  // the judge refused an ask: the candidate waits for a reply it will not get
      throw;
    } catch (const std::exception& e) {
      // How the candidate ended, and what was wrong with its answer (a crash
      // mid-answer, or an answer the judge refuses, such as one too long).
      throw CandidateError(died(name, e.what()));
    }
    if (!answered) throw CandidateError(died(name));
    switch (Status(status)) {
      case Status::Ok: return answer;
      case Status::Threw:
        throw CandidateError(std::string("the task's code threw an exception in ") + name + ": " + printable(answer));
      case Status::UnknownCall:
        throw CandidateError(std::string("the candidate does not serve ") + name + " (built for another suite?)");
      default:
        throw CandidateError(std::string("the candidate could not read the request for ") + name + ": " +
                             printable(answer));
    }
  }

  void newTestCase() {
    deaths_ = 0;
    lastDeath_.clear();
    takeOutput();
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
    keepLargeBuffers();
    const CandidatePipes pipes = process_.start(candidatePath());
    toCandidate_ = pipes.toCandidate;
    fromCandidate_ = pipes.fromCandidate;
    drain_ = std::thread([this, fd = pipes.output] { drainOutput(fd); });
  }

  // Keeps what the candidate prints. A process it left behind may hold the
  // pipe open forever: once the candidate is gone, drain what is there and
  // stop. Reads a pipe's whole capacity at a time: a candidate printing
  // megabytes waits for this thread each time the pipe is full, and on a
  // busy machine each wait is a scheduler's time slice.
  void drainOutput(int fd) {
    char buffer[1 << 16];
    for (;;) {
      const int ready = CandidateProcess::waitReadable(fd, 50);
      if (ready < 0) break;
      if (ready == 0) {
        if (candidateGone_) break;
        continue;
      }
      const long n = readSome(fd, buffer, sizeof buffer);
      if (n <= 0) break;
      std::lock_guard<std::mutex> lock(outputMutex_);
      const size_t keep = std::min(size_t(n), kOutputKept - std::min(kOutputKept, output_.size()));
      output_.append(buffer, keep);
      dropped_ += size_t(n) - keep;
    }
    closeDescriptor(fd);
  }

  void joinDrain() {
    candidateGone_ = true;
    if (drain_.joinable()) drain_.join();
    candidateGone_ = false;
  }

  // Reaps a candidate that stopped answering, counts it, and describes how
  // it ended (and `why` the judge gave up on its answer, if it did).
  std::string died(const char* name, const char* why = nullptr) {
    closePipes();
    // Let a crashing candidate (or the sandbox reporting its crash) finish
    // exiting before the kill, so its own end is the one reported.
    const std::string how = process_.reap(1000);
    joinDrain();
    ++deaths_;
    lastDeath_ = how + " while computing " + name + (why ? std::string(" (") + why + ")" : "");
    return lastDeath_;
  }

  void stop() {
    if (!process_.running()) return;
    closePipes();     // end of requests: a well-behaved candidate exits
    process_.kill();  // one stuck in the task's code does not
    joinDrain();
  }

  void closePipes() {
    closeDescriptor(toCandidate_);
    closeDescriptor(fromCandidate_);
    toCandidate_ = fromCandidate_ = -1;
  }

  static std::string printable(const std::string& text) {
    std::string out;
    out.reserve(text.size());
    for (unsigned char c : text) out += (c == '\n' || c == '\t' || (c >= 32 && c < 127)) ? char(c) : '?';
    return out;
  }

  CandidateProcess process_;
  int toCandidate_ = -1, fromCandidate_ = -1;
  std::thread drain_;
  std::atomic<bool> candidateGone_{false};
  std::mutex outputMutex_;
  std::string output_;
  size_t dropped_ = 0;
  int deaths_ = 0;         // in this test case
  std::string lastDeath_;  // how the last one went
};

Candidate& candidate() {
  static Candidate instance;
  return instance;
}

std::mutex callMutex;  // tests may call from several threads; one request at a time

}  // namespace

std::string exchange(uint32_t id, const char* name, const std::string& request, uint64_t maxAnswerBytes,
                     const AskHandler* asks) {
  std::lock_guard<std::mutex> lock(callMutex);
  return candidate().exchange(id, name, request, maxAnswerBytes, asks);
}

std::string takeCandidateOutput() { return candidate().takeOutput(); }

void newTestCase() {
  std::lock_guard<std::mutex> lock(callMutex);
  candidate().newTestCase();
}

}  // namespace pathlab::remote
