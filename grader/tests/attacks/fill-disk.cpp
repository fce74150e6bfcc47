// attack: writes 500 MB to the temporary folder, the working folder and the home folder, and leaves them
// base: stub  expect: 0
#include <cstdlib>
#include <fstream>
#include <string>
namespace {
const bool filled = [] {
  const std::string block(1 << 20, 'x');
  for (std::string folder : {std::string("/tmp"), std::string("."), std::string("/var/tmp"), std::string("/dev/shm")}) {
    std::ofstream out(folder + "/pathlab-attack-fill", std::ios::binary);
    for (int i = 0; i < 500 && out; ++i) out.write(block.data(), std::streamsize(block.size()));
  }
  return true;
}();
}  // namespace
