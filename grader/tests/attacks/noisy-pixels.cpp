// attack: answers every image request itself, rendering nothing: the size asked for, a flat grey, and an
// enormous variance in one pixel of every 4 x 4 block, which widened the block's tolerance (and the whole
// image's) until any mean passed (the judge caps the candidate's variance per pixel and per block)
// base: stub  expect: 0  uses: protocol-hijack.inc
namespace hijack {
std::string answer(uint32_t id, const std::string& request, uint32_t& status) {
  if (id != 110) {  // RenderMoments (tests/support/image_calls.h)
    status = 1;
    return "not computed";
  }
  // The request: a count, then the Scene: its source (a string), its camera (48 bytes), its render settings.
  const size_t render = 8 + 8 + at<uint64_t>(request, 8) + 48;
  const int width = at<int>(request, render), height = at<int>(request, render + 4);
  const uint64_t pixels = uint64_t(width) * uint64_t(height);
  std::string out;
  put(out, width), put(out, height), put(out, at<int>(request, render + 8));  // the asked size and samples
  put(out, pixels);
  for (uint64_t i = 0; i < 3 * pixels; ++i) put(out, 0.3f);
  put(out, pixels);
  for (uint64_t i = 0; i < pixels; ++i) {
    const bool noisy = (i % uint64_t(width)) % 4 == 0 && (i / uint64_t(width)) % 4 == 0;
    for (int c = 0; c < 3; ++c) put(out, noisy ? 1e30f : 0.0f);
  }
  put(out, uint64_t(0)), out.push_back(1);  // no NaN, the BVH used
  return out;
}
const bool hijacked = serve();
}  // namespace hijack
