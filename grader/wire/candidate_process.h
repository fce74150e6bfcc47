// The candidate as an operating-system process (judge.cpp decides what to
// send it; this file only starts, watches and ends it). Two halves:
// candidate_process_posix.cpp (Linux, macOS: posix_spawn, pipes, signals)
// and candidate_process_windows.cpp (CreateProcess, anonymous pipes, exit
// codes); each compiles to nothing on the other's systems.
//
// Every descriptor here is a C runtime file descriptor, so protocol.cpp's
// reads and writes are the same code on both.
#pragma once

#include <string>

namespace pathlab::remote {

// The judge's ends of the three pipes.
struct CandidatePipes {
  int toCandidate = -1;    // requests
  int fromCandidate = -1;  // answers
  int output = -1;         // the candidate's stdout and stderr together
};

class CandidateProcess {
 public:
  CandidateProcess() = default;
  CandidateProcess(const CandidateProcess&) = delete;
  CandidateProcess& operator=(const CandidateProcess&) = delete;
  ~CandidateProcess() { kill(); }

  // Starts the program at `path`; throws CandidateError when it cannot.
  CandidatePipes start(const std::string& path);
  bool running() const { return handle_ != 0; }

  // After the judge closed its pipe ends: gives the candidate up to
  // `graceMs` to end by itself (a crash finishes being reported), kills it
  // if it has not, and describes its end ("the task's code crashed
  // (SIGSEGV, ...)", "the candidate exited (exit code 3)"); "the candidate
  // stopped" when it had to be killed.
  std::string reap(int graceMs);
  // Ends it now, if it runs, and waits for it.
  void kill();

  // Waits up to `ms` for `fd` (an output pipe) to have bytes or reach its
  // end: 1 ready, 0 not yet, -1 error.
  static int waitReadable(int fd, int ms);

 private:
  long long handle_ = 0;  // POSIX: the pid; Windows: the process HANDLE
};

// The candidate's side: its request and answer descriptors (POSIX: 3 and 4,
// set up by the judge or the grader's sandbox; Windows: the inherited pipe
// handles the judge names in PATHLAB_CANDIDATE_PIPES). -1 when absent.
int candidateRequestFd();
int candidateResponseFd();

// Ends the candidate when its judge dies, where the system can (Linux).
void candidateDiesWithJudge();

}  // namespace pathlab::remote
