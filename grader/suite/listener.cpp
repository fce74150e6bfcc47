// Prints a hint under each failing test case and the points scored, parsed
// from the "points=N; hint=..." description that grading() attaches. Under
// a failing test it also shows what the candidate printed (task code's own
// output), line by line behind "candidate| ".
//
// With PATHLAB_VERDICT_FILE set (tools/grade does), each test case's
// verdict is also appended to that file: "PASS|FAIL <points> <name>", then
// "END" when the run finished; and any leaderboard entry a test records,
// "LEADERBOARD asc|desc <value> <name>" (each word and variable defined once,
// in verdicts.json, for this file and the grader's Python). The grader reads only this file, which the
// candidate cannot reach, never the judge's stdout.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <mutex>
#include <string>
#include <vector>

#include "grading.h"
#include "suite/verdicts.h"
#include "wire/call.h"

namespace pathlab::test {

const char* gradingText(int points, const char* hint, Visibility visibility) {
  static std::deque<std::string> texts;  // stable addresses
  static std::mutex mutex;
  std::lock_guard<std::mutex> lock(mutex);
  texts.push_back("points=" + std::to_string(points) + "; visibility=" + verdicts::kVisibilityNames[int(visibility)] +
                  "; hint=" + hint);
  return texts.back().c_str();
}

void appendVerdictLine(const std::string& line) {
  static const char* path = std::getenv(verdicts::kVerdictFileVariable);
  if (!path || !*path) return;
  if (std::FILE* f = std::fopen(path, "a")) {
    std::fprintf(f, "%s\n", line.c_str());
    std::fclose(f);
  }
}

void recordLeaderboard(const std::string& name, double value, bool lowerIsBetter) {
  char number[64];
  std::snprintf(number, sizeof number, "%.6g", value);
  std::printf("leaderboard: %s = %s (%s is better; ungraded)\n", name.c_str(), number,
              lowerIsBetter ? "lower" : "higher");
  appendVerdictLine(std::string(verdicts::kLeaderboard) + " " +
                    (lowerIsBetter ? verdicts::kLowerIsBetter : verdicts::kHigherIsBetter) + " " + number + " " + name);
}

namespace {
const doctest::TestCaseData* g_currentTestCase = nullptr;
int g_checkIndex = 0;
std::vector<std::string> g_failureHints;  // this test case's, from hintForFailure and failed checks under a HINT
std::vector<const char*> g_checkHints;    // the HINTs in scope, innermost last
}  // namespace

CheckHint::CheckHint(const char* hint) { g_checkHints.push_back(hint); }
CheckHint::~CheckHint() { g_checkHints.pop_back(); }

void hintForFailure(const std::string& hint) {
  if (std::find(g_failureHints.begin(), g_failureHints.end(), hint) == g_failureHints.end())
    g_failureHints.push_back(hint);
}

const char* currentTestCaseName() { return g_currentTestCase ? g_currentTestCase->m_name : "(no test case)"; }
int nextCheckIndex() { return g_checkIndex++; }

namespace {

int pointsOf(const char* description) {
  if (!description || std::string(description).rfind("points=", 0) != 0) return 1;
  return std::atoi(description + 7);
}

std::string visibilityOf(const char* description) {
  std::string text = description ? description : "";
  size_t at = text.find("visibility=");
  return at == std::string::npos ? verdicts::kVisibilityNames[0] : text.substr(at + 11, text.find(';', at) - at - 11);
}

std::string hintOf(const char* description) {
  if (!description) return "";
  std::string text = description;
  size_t at = text.find("hint=");
  return at == std::string::npos ? text : text.substr(at + 5);
}

struct GradingListener : doctest::IReporter {
  explicit GradingListener(const doctest::ContextOptions&) {}

  // With --list-test-cases: one "TEST <points> <visibility> <name>" line per case, the
  // manifest tools/grade uses to run each case in its own process.
  void report_query(const doctest::QueryData& query) override {
    for (unsigned i = 0; i < query.num_data; ++i) {
      std::printf("%s %d %s %s\n", verdicts::kListing, pointsOf(query.data[i]->m_description),
                  visibilityOf(query.data[i]->m_description).c_str(), query.data[i]->m_name);
    }
  }
  void test_run_start() override {}
  void test_case_start(const doctest::TestCaseData& data) override {
    current_ = &data;
    g_currentTestCase = &data;
    g_checkIndex = 0;
    g_failureHints.clear();
    remote::newTestCase();  // earlier tests' output and crashes are not this test's
  }
  void test_case_reenter(const doctest::TestCaseData&) override {}
  void test_case_end(const doctest::CurrentTestCaseStats& stats) override {
    const int points = pointsOf(current_->m_description);
    total_ += points;
    ++cases_;
    if (stats.testCaseSuccess) {
      earned_ += points;
      ++passed_;
    } else {
      std::string hint = hintOf(current_->m_description);
      if (!g_failureHints.empty()) {  // the failed checks' own hints, not the test's
        hint.clear();
        for (const std::string& h : g_failureHints) hint += (hint.empty() ? "" : " ALSO: ") + h;
      }
      std::printf("HINT (%s, %d pts): %s\n", current_->m_name, points, hint.c_str());
      printCandidateOutput();
    }
    verdict(std::string(stats.testCaseSuccess ? verdicts::kPass : verdicts::kFail) + " " + std::to_string(points) +
            " " + current_->m_name);
  }

  static void printCandidateOutput() {
    const std::string output = remote::takeCandidateOutput();
    if (output.empty()) return;
    std::printf("The task's code printed:\n");
    size_t start = 0;
    while (start < output.size()) {
      size_t end = output.find('\n', start);
      if (end == std::string::npos) end = output.size();
      std::printf("candidate| %s\n", output.substr(start, end - start).c_str());
      start = end + 1;
    }
  }

  static void verdict(const std::string& line) { appendVerdictLine(line); }
  void test_case_exception(const doctest::TestCaseException&) override {}
  void subcase_start(const doctest::SubcaseSignature&) override {}
  void subcase_end() override {}
  void log_assert(const doctest::AssertData& data) override {
    if (data.m_failed && !g_checkHints.empty()) hintForFailure(g_checkHints.back());
  }
  void log_message(const doctest::MessageData& data) override {  // FAIL_CHECK and FAIL
    if (!(data.m_severity & doctest::assertType::is_warn) && !g_checkHints.empty()) hintForFailure(g_checkHints.back());
  }
  void test_case_skipped(const doctest::TestCaseData&) override {}
  void test_run_end(const doctest::TestRunStats&) override {
    if (cases_ > 0) std::printf("SCORE %d/%d points (%d/%d test cases passed)\n", earned_, total_, passed_, cases_);
    std::fflush(stdout);
    verdict(verdicts::kEnd);
  }

  const doctest::TestCaseData* current_ = nullptr;
  int earned_ = 0, total_ = 0, passed_ = 0, cases_ = 0;
};

}  // namespace
}  // namespace pathlab::test

DOCTEST_REGISTER_LISTENER("grading", 1, pathlab::test::GradingListener);
