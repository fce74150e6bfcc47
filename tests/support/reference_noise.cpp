#include "reference_noise.h"

#include "suite/doctest_strings.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>

#include "suite/grading.h"

namespace pathlab::test {
namespace {

using Variances = std::map<std::string, double>;  // "<test case> #<k>" -> variance per sample

std::string variancesPath(const std::string& suite) {
  return std::string(PATHLAB_TESTS_DIR) + "/" + suite + "/reference-variances.txt";
}

// One "<variance> <key>" line per estimate (the key may hold spaces).
Variances load(const std::string& path) {
  Variances table;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    double variance = 0;
    std::string key;
    if (fields >> variance && std::getline(fields >> std::ws, key)) table[key] = variance;
  }
  return table;
}

void save(const std::string& path, const Variances& table) {
  std::ofstream out(path);
  char number[32];
  for (const auto& [key, variance] : table) {
    std::snprintf(number, sizeof number, "%.9g", variance);
    out << number << " " << key << "\n";
  }
}

}  // namespace

void noteNoiseCeiling(const char* why) {
  const char* path = std::getenv("PATHLAB_NOISE_CATALOG");
  if (!path || !*path) return;
  if (std::FILE* f = std::fopen(path, "a")) {
    std::fprintf(f, "%s\t%s\n", currentTestCaseName(), why);
    std::fclose(f);
  }
}

void limitNoise(MeanEstimate& m, const std::string& suite) {
  const std::string key = std::string(currentTestCaseName()) + " #" + std::to_string(nextCheckIndex());
  const std::string path = variancesPath(suite);
  if (const char* write = std::getenv("PATHLAB_WRITE_REFERENCE_VARIANCES"); write && *write) {
    Variances table = load(path);
    const auto stored = table.find(key);
    table[key] = stored == table.end() ? m.variance() : std::max(stored->second, m.variance());
    save(path, table);
    // Writing the ceilings, not judging by them: this run's verdicts are judged by its own noise.
    m.setVarianceCeiling(std::max(m.variance(), 0.0), "writing reference-variances.txt: its own variance");
    return;
  }
  static std::map<std::string, Variances> tables;  // per suite, read once
  auto loaded = tables.find(suite);
  if (loaded == tables.end()) loaded = tables.emplace(suite, load(path)).first;
  const auto found = loaded->second.find(key);
  if (found == loaded->second.end()) {
    FAIL_CHECK("no reference variance for '" << key << "' in " << path
                                             << " (tools/make-reference-images writes it)");
    m.setVarianceCeiling(0.0, "none stored: the test fails");
    return;
  }
  // A deterministic reference (variance 0) allows a correct estimator's rounding noise only.
  m.setVarianceCeiling(kNoiseFactor * found->second + 1e-12,
                       "8 x the largest of the reference's and the alternates' (reference-variances.txt)");
  if (const char* stats = std::getenv("PATHLAB_NOISE_STATS"); stats && *stats) {
    // The variance ratio per estimate, to measure kNoiseFactor's margin.
    if (std::FILE* f = std::fopen(stats, "a")) {
      std::fprintf(f, "%.4g %s/%s\n", found->second > 0 ? m.variance() / found->second : 0.0, suite.c_str(),
                   key.c_str());
      std::fclose(f);
    }
  }
}

}  // namespace pathlab::test
