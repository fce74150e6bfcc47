// attack: prints the environment it runs in (the grader's variables, if it inherited them)
// base: stub  expect: 0
#include <cstdio>
extern char** environ;
static int print_environment = [] {
  for (char** e = environ; *e; ++e) std::printf("%s\n", *e);
  return 0;
}();
