// Autograder conventions shared by every suite.
//
// Each TEST_CASE carries its points and a one-line hint naming the likely
// mistake:
//
//   TEST_CASE("T2.1 triangle: ..." * pathlab::test::grading(3, "hint ..."))
//   TEST_CASE("..." * grading(2, "hint ...", Visibility::AfterDueDate))   // hidden until the due date
//
// The listener in listener.cpp prints the hint under a failing test and a
// score line at the end ("SCORE 17/20 points").
#pragma once

#include "doctest_strings.h"

#include <string>

namespace pathlab::test {

// Who sees a test's result on Gradescope (its "visibility").
enum class Visibility { Visible, Hidden, AfterDueDate, AfterPublished };

// doctest keeps the description string by pointer, so grading() stores the
// text for the life of the program.
const char* gradingText(int points, const char* hint, Visibility visibility);

inline doctest::description grading(int points, const char* hint, Visibility visibility = Visibility::Visible) {
  return doctest::description(gradingText(points, hint, visibility));
}

// An ungraded number for the course's leaderboard (Gradescope's
// results.json "leaderboard"), measured by the judge itself, never reported
// by the candidate: tools/grade collects it, a course publishes or ignores it.
void recordLeaderboard(const std::string& name, double value, bool lowerIsBetter);
// One line into PATHLAB_VERDICT_FILE (nothing when it is not set).
void appendVerdictLine(const std::string& line);

// What a failed check points to, for a test with several checks: printed
// under the failing test instead of the test's own hint (each such hint
// once, in order, joined by " ALSO: "). Two ways to give one:
//
//   HINT("t is the distance along the unit direction ...");  // the checks after it,
//   CHECK(...);                                               // to the end of the block
//
// names what the checks that follow measure (as doctest's INFO, it lasts to
// the end of the enclosing block; a later HINT in the same block takes
// over). hintForFailure(text), called where a check failed, gives a hint
// chosen by what failed together (which estimators, which floor).
// tools/hint-catalogue lists every test's hints (docs/hints.md) and fails
// a test with several checks that leaves one to the test's fixed hint.
void hintForFailure(const std::string& hint);

class CheckHint {
 public:
  explicit CheckHint(const char* hint);
  ~CheckHint();
  CheckHint(const CheckHint&) = delete;
  CheckHint& operator=(const CheckHint&) = delete;
};
#define HINT(text) const ::pathlab::test::CheckHint DOCTEST_ANONYMOUS(pathlabCheckHint_)(text)

// The test case running now, and 0, 1, 2, ... on successive calls within it:
// the key of data a suite stores per check (reference_noise.h).
const char* currentTestCaseName();
int nextCheckIndex();

}  // namespace pathlab::test
