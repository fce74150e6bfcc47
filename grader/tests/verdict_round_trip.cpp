// The judge of CTest verdict-round-trip (test_verdicts.py): a test case of
// each kind the grader must read back, with known points, visibility and
// outcome, linked with pathlab_judge like every suite's judge. What it prints
// and writes is made from grader/suite/verdicts.json; the driver reads it
// with grader/driver/verdicts.py, from the same file.
#include "suite/doctest_strings.h"
#include "suite/grading.h"

using pathlab::test::grading;
using pathlab::test::recordLeaderboard;
using pathlab::test::Visibility;

TEST_CASE("R.1 passes, visible" * grading(2, "hint one")) { CHECK(1 + 1 == 2); }

TEST_CASE("R.2 fails, hidden" * grading(3, "hint two", Visibility::Hidden)) { CHECK(1 + 1 == 3); }

TEST_CASE("R.3 records two leaderboard entries, after the due date" *
          grading(1, "hint three", Visibility::AfterDueDate)) {
  recordLeaderboard("rays per second", 1.5e6, false);
  recordLeaderboard("error (lower is better)", 0.25, true);
  CHECK(true);
}

TEST_CASE("R.4 a name with a comma, a backslash \\ and a star * [in brackets], after publishing" *
          grading(5, "hint four", Visibility::AfterPublished)) {
  CHECK(true);
}
