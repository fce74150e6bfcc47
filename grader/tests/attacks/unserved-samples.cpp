// attack: answers task 11's pixel requests itself, never asking the judge for a sample, with the counts
// and the confidence a good sampler would report (a count kept in the candidate's process is a claim)
// task: 11  base: stub  expect: 0  uses: protocol-hijack.inc
namespace hijack {
std::string answer(uint32_t id, const std::string& request, uint32_t& status) {
  if (id != 4) {  // SamplePixels (tests/11-adaptive-sampling/calls.h)
    status = 1;
    return "not computed";
  }
  // The request: a count (1), the pixels' given samples (a vector of vectors), the settings.
  const uint64_t pixels = at<uint64_t>(request, 8);
  size_t offset = 16;
  for (uint64_t k = 0; k < pixels; ++k) offset += 8 + 12 * at<uint64_t>(request, offset);
  const uint32_t minSpp = at<uint32_t>(request, offset + 8 + 4);  // tolerance (double), batch, minSpp
  std::string out;
  put(out, pixels);
  for (uint64_t k = 0; k < pixels; ++k) {
    put(out, 0.5f), put(out, 0.5f), put(out, 0.5f);  // the estimate
    put(out, k % 7 == 0 ? 4 * minSpp : minSpp);       // samples: more where it claims the noise is
    out.push_back(1);                                  // confident
  }
  return out;
}
const bool hijacked = serve();
}  // namespace hijack
