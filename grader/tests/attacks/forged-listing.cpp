// attack: prints a fake --list-test-cases manifest worth 3,000,000 points, then exits 0
// base: stub  expect: 0
#include <cstdio>
#include <cstdlib>
namespace {
const bool forged = [] {
  for (int i = 0; i < 3; ++i) std::printf("TEST 1000000 visible forged test %d\n", i);
  std::fflush(stdout);
  std::_Exit(0);
  return true;
}();
}  // namespace
