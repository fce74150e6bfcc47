// attack: answers the judge's first request with an "exception" whose message is 400 MB, to make the
// judge (outside the sandbox) hold it, copy it and print it
// base: stub  expect: 0
#include <unistd.h>
#include <cstdint>
#include <string>
namespace {
const bool flooded = [] {
  struct { uint32_t magic = 0x53455250, status = 1; uint64_t size = uint64_t(400) << 20; } header;
  if (write(4, &header, sizeof header) != ssize_t(sizeof header)) return false;
  const std::string block(1 << 20, 'e');
  for (int i = 0; i < 400; ++i) {
    if (write(4, block.data(), block.size()) < 0) break;
  }
  return true;
}();
}  // namespace
