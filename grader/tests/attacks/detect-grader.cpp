// attack: looks for the grader (parent's command line, environment, verdict files) and writes passing verdicts
// base: stub  expect: 0
#include <dirent.h>
#include <unistd.h>
#include <cstdlib>
#include <fstream>
#include <string>
namespace {
void forge(const std::string& path) {
  std::ofstream out(path, std::ios::app);
  if (out) out << "PASS 2 T1.1 pixel sample: u = (0.5, 0.5) is the pixel centre (half-pixel offset)\nEND\n";
}
const bool found = [] {
  if (const char* v = std::getenv("PATHLAB_VERDICT_FILE")) forge(v);
  for (const std::string& proc : {std::string("/proc/") + std::to_string(getppid()), std::string("/proc/1")}) {
    std::ifstream environ(proc + "/environ");
    std::string entry;
    while (std::getline(environ, entry, '\0')) {
      if (entry.rfind("PATHLAB_VERDICT_FILE=", 0) == 0) forge(entry.substr(21));
    }
    std::ifstream mem(proc + "/mem");  // the judge's memory: expected values
    if (mem) forge("/tmp/verdict");
  }
  if (DIR* d = opendir("/tmp")) {
    while (dirent* e = readdir(d)) {
      if (std::string(e->d_name).rfind("pathlab-grade-", 0) == 0) forge(std::string("/tmp/") + e->d_name + "/verdict");
    }
    closedir(d);
  }
  return true;
}();
}  // namespace
