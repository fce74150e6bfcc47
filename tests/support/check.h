// Helpers for precise comparisons in the suites: double-precision oracles,
// vector closeness with the values printed on failure, seeded randomness.
#pragma once

#include "suite/doctest_strings.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "util/math.h"
#include "util/random.h"

namespace pathlab::test {

using DVec3 = glm::dvec3;

// Irradiance at x (normal n) from a uniform, fully visible polygon of
// radiance 1 (Lambert): E = 1/2 sum_i angle(v_i, v_i+1) n . normalize(v_i x v_i+1).
inline double polygonIrradiance(const DVec3& x, const DVec3& n, const std::vector<DVec3>& polygon) {
  double sum = 0.0;
  for (size_t i = 0; i < polygon.size(); ++i) {
    DVec3 a = glm::normalize(polygon[i] - x), b = glm::normalize(polygon[(i + 1) % polygon.size()] - x);
    double angle = std::acos(std::clamp(glm::dot(a, b), -1.0, 1.0));
    sum += angle * glm::dot(n, glm::normalize(glm::cross(a, b)));
  }
  return 0.5 * std::abs(sum);
}

inline std::string str(const Vec3& v) {
  std::ostringstream s;
  s.precision(9);
  s << "(" << v.x << ", " << v.y << ", " << v.z << ")";
  return s.str();
}

inline bool near(const Vec3& a, const Vec3& b, float tolerance) {
  return std::abs(a.x - b.x) <= tolerance && std::abs(a.y - b.y) <= tolerance && std::abs(a.z - b.z) <= tolerance;
}

inline bool finite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Every seed in the suites passes through here. PATHLAB_TEST_SEED=k (k > 0)
// runs the same tests on independent random inputs: tools/run-seeds.sh runs
// a suite under many seeds to check its false-failure rate.
inline uint64_t testSeed(uint64_t base) {
  static const uint64_t offset = [] {
    const char* text = std::getenv("PATHLAB_TEST_SEED");
    return text ? std::strtoull(text, nullptr, 10) : 0ull;
  }();
  return base + offset * 0x9e3779b97f4a7c15ull;
}

// A seeded generator: every suite is deterministic, run after run.
class Random {
 public:
  explicit Random(uint32_t seed) : engine_(testSeed(seed)) {}
  // Inputs that must not vary with PATHLAB_TEST_SEED (e.g. a scene whose
  // reference cost is a constant in the test).
  static Random fixed(uint32_t seed) {
    Random r(0);
    r.engine_.seed(seed);
    return r;
  }
  double uniform(double a = 0.0, double b = 1.0) { return std::uniform_real_distribution<double>(a, b)(engine_); }
  DVec3 unitVector() {
    double z = uniform(-1.0, 1.0), phi = uniform(0.0, 2.0 * std::numbers::pi), r = std::sqrt(std::max(0.0, 1.0 - z * z));
    return {r * std::cos(phi), r * std::sin(phi), z};
  }
  DVec3 inCube(double half) { return {uniform(-half, half), uniform(-half, half), uniform(-half, half)}; }

 private:
  std::mt19937_64 engine_;
};

// n uniform points of [0,1)^2, one framework Sampler stream per point: the
// inputs a warp's chi-square test maps.
inline std::vector<Vec2> uniformPoints(int n, uint64_t seed) {
  std::vector<Vec2> us;
  us.reserve(size_t(n));
  for (int i = 0; i < n; ++i) us.push_back(Sampler(uint32_t(i), 0, testSeed(seed)).next2D());
  return us;
}

// The optional folder of data users bring (the course's .dae files, scanned
// models): $PATHLAB_DATA_DIR, or "" when unset. Tests that read it skip with
// one line without it; no graded test reads it.
inline std::string dataDir() {
  const char* dir = std::getenv("PATHLAB_DATA_DIR");
  return dir && *dir ? std::string(dir) : std::string();
}

}  // namespace pathlab::test
