// attack: answers every image request itself, rendering nothing: a picture whose stated size (1 x 1)
// disagrees with the request, flat grey, with an enormous variance on its first pixel
// base: stub  expect: 0  uses: protocol-hijack.inc
namespace hijack {
std::string answer(uint32_t id, const std::string& request, uint32_t& status) {
  if (id != 110) {  // RenderMoments (tests/support/image_calls.h)
    status = 1;
    return "not computed";
  }
  // The request: a count, then the Scene: its source (a string), its camera (48 bytes), its render settings.
  const size_t render = 8 + 8 + at<uint64_t>(request, 8) + 48;
  const uint64_t pixels = uint64_t(at<int>(request, render)) * uint64_t(at<int>(request, render + 4));
  std::string out;
  put(out, 1), put(out, 1), put(out, at<int>(request, render + 8));  // 1 x 1, at the asked samples per pixel
  put(out, pixels);
  for (uint64_t i = 0; i < 3 * pixels; ++i) put(out, 0.3f);
  put(out, pixels);
  for (uint64_t i = 0; i < 3 * pixels; ++i) put(out, i < 3 ? 1e30f : 0.0f);
  put(out, uint64_t(0)), out.push_back(1);  // no NaN, the BVH used
  return out;
}
const bool hijacked = serve();
}  // namespace hijack
