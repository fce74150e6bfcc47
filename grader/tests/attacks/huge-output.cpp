// attack: a correct solution that prints 100 MB (honest work: full marks, output clipped)
// base: reference  expect: full
#include <cstdio>
#include <string>
namespace {
const bool flood = [] {
  const std::string line(1000, 'y');
  for (int i = 0; i < 100000; ++i) std::puts(line.c_str());
  return true;
}();
}  // namespace
