// attack: every call sleeps just under the per-test time limit, to make a grade take hours
// base: stub  expect: 0
#include <unistd.h>
namespace {
const bool slow = [] {
  usleep(2900000);  // the test runs the grader with --timeout 3
  return true;
}();
}  // namespace
