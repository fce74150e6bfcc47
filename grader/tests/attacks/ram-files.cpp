// attack: 2 GB of files in RAM-backed places (/dev/shm, /run/lock, the sandbox's root and /dev), 64 MB
// each (the file-size limit), where no process's memory limit counts them
// base: stub  expect: 0
#include <fstream>
#include <string>
namespace {
const bool filled = [] {
  const std::string block(1 << 20, 'r');
  int written = 0;
  for (std::string folder : {"/dev/shm", "/run/lock", "", "/dev", "/tmp", "/var/tmp"}) {
    for (int file = 0; file < 32 && written < 2048; ++file) {
      std::ofstream out(folder + "/pathlab-attack-ram-" + std::to_string(file), std::ios::binary);
      for (int i = 0; i < 64 && out; ++i, ++written) out.write(block.data(), std::streamsize(block.size()));
      if (!out) break;
    }
  }
  return true;
}();
}  // namespace
