// The candidate process on this system (candidate_process.h), driven
// through the judge's own exchange(): answers, an exception, the output
// shown under a failing test, a crash, an exit code, a fresh candidate
// after each death, and none after the third death in one test. This
// program is both sides: started with PATHLAB_TEST_CANDIDATE set, it is the
// candidate.
//   CTest candidate-process runs the POSIX half; tools/windows-check runs the
//   Windows half under Wine.
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>

#include "call.h"
#include "candidate_process.h"
#include "protocol.h"
#include "util/platform.h"

namespace remote = pathlab::remote;

namespace {

int failures = 0;
void expect(bool ok, const std::string& what) {
  std::printf("%s %s\n", ok ? "ok  " : "FAIL", what.c_str());
  failures += ok ? 0 : 1;
}

void setEnvironment(const char* name, const std::string& value) {
#if defined(_WIN32)
  _putenv_s(name, value.c_str());
#else
  setenv(name, value.c_str(), 1);
#endif
}

// The candidate: call 1 answers, 2 crashes, 3 exits with code 7, 4 throws.
int runCandidate() {
  const int requests = remote::candidateRequestFd(), answers = remote::candidateResponseFd();
  if (requests < 0 || answers < 0) return 2;
  std::printf("candidate says hello on stdout\n");
  std::fflush(stdout);
  std::fprintf(stderr, "and on stderr\n");
  uint32_t id = 0;
  std::string payload;
  while (remote::readMessage(requests, remote::kRequestMagic, id, payload)) {
    if (id == 2) {
      // A store to an address no system maps (not null: UBSan would stop at
      // that first); volatile, so the store is real, not a compiler's trap.
      int* volatile nowhere = reinterpret_cast<int*>(std::uintptr_t(64));
      *nowhere = 1;
    }
    if (id == 3) std::exit(7);
    const auto status = id == 4 ? remote::Status::Threw : remote::Status::Ok;
    remote::writeMessage(answers, remote::kResponseMagic, uint32_t(status), payload + " back");
  }
  return 0;
}

// The CandidateError's message of a call, or "" when it answered.
std::string failureOf(uint32_t id, const char* name) {
  try {
    remote::exchange(id, name, "x", remote::kMaxAnswerBytes);
  } catch (const remote::CandidateError& e) {
    return e.what();
  }
  return "";
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

int main() {
  if (std::getenv("PATHLAB_TEST_CANDIDATE")) return runCandidate();
  setEnvironment("PATHLAB_TEST_CANDIDATE", "1");
  // Under AddressSanitizer (the asan preset) the candidate's crash must stay
  // a crash: its SEGV handler would report and exit with code 1.
  const char* asan = std::getenv("ASAN_OPTIONS");
  setEnvironment("ASAN_OPTIONS", std::string(asan ? asan : "") + ":handle_segv=0");
  setEnvironment("PATHLAB_CANDIDATE", pathlab::currentExecutablePath());

  expect(remote::exchange(1, "answer", "ping", remote::kMaxAnswerBytes) == "ping back", "a call answered");
  expect(remote::exchange(1, "answer", "pong", remote::kMaxAnswerBytes) == "pong back",
         "a second call on the same candidate");
  const std::string threw = failureOf(4, "throw");
  expect(contains(threw, "threw an exception in throw: x back"), "an exception reported (" + threw + ")");
  std::string output;
  for (int i = 0; i < 100 && !(contains(output, "hello on stdout") && contains(output, "on stderr")); ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    output += remote::takeCandidateOutput();
  }
  expect(contains(output, "candidate says hello on stdout") && contains(output, "and on stderr"),
         "its stdout and stderr kept");

  const std::string crash = failureOf(2, "crash");
#if defined(_WIN32)
  const char* crashName = "access violation";
#else
  const char* crashName = "SIGSEGV";
#endif
  expect(contains(crash, "the task's code crashed (") && contains(crash, crashName) &&
             contains(crash, "while computing crash"),
         "a crash reported (" + crash + ")");
  expect(remote::exchange(1, "answer", "again", remote::kMaxAnswerBytes) == "again back",
         "a fresh candidate after the crash");
  const std::string exited = failureOf(3, "exit");
  expect(contains(exited, "the candidate exited (exit code 7) while computing exit"),
         "an exit code reported (" + exited + ")");
  expect(remote::exchange(1, "answer", "last", remote::kMaxAnswerBytes) == "last back",
         "a fresh candidate after the exit");
  // An answer longer than its request allows is refused from its header, unread.
  std::string tooLong;
  try {
    remote::exchange(1, "answer", "long", 8);
  } catch (const remote::CandidateError& e) {
    tooLong = e.what();
  }
  expect(contains(tooLong, "a message of 9 bytes is over the limit of 8 bytes"),
         "an answer too long refused (" + tooLong + ")");
  // Three deaths in one test: the next call fails at once, naming the last;
  // a new test case starts a fresh candidate again.
  const std::string spent = failureOf(1, "answer");
  expect(contains(spent, "over the limit of 8 bytes") && contains(spent, "not started again in this test after 3"),
         "no fourth start in the same test (" + spent + ")");
  remote::newTestCase();
  expect(remote::exchange(1, "answer", "after", remote::kMaxAnswerBytes) == "after back",
         "a fresh candidate in the next test");

  std::printf("%d passed, %d failed\n", 11 - failures, failures);
  return failures == 0 ? 0 : 1;
}
