// attack: a file that takes minutes to compile (64 constant expressions, each evaluated until the
// compiler's step limit, about 5 s apiece), to use time no test budget counts
// base: stub  expect: 0
namespace {
template <int K>
constexpr long long pathlabSlowSum() {
  long long sum = 0;
  for (long long i = 0; i < 200000 + K; ++i)  // K: no two evaluations are the same
    for (long long j = 0; j < 200000; ++j) sum += (i ^ j) % 7;
  return sum;
}
#define PATHLAB_SLOW static_assert(pathlabSlowSum<__COUNTER__>() >= 0);
#define PATHLAB_X4(x) x x x x
PATHLAB_X4(PATHLAB_X4(PATHLAB_X4(PATHLAB_SLOW)))
}  // namespace
