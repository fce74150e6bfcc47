// `pathlab-bench bvh`'s report: the builds, the speeds against Embree and the fast path, and a
// student build's task 3 against the reference's (bvh_run.h).
#include "bvh_run.h"

#include <cstdio>
#include <filesystem>

#include "util/input_file.h"
#include "util/platform.h"

namespace pathlab::bench {
namespace {

using Json = nlohmann::json;

// The reference's task 3 on the same mesh and rays: the reference build
// beside this program (pathlab-bench-reference, made where this build links
// the student's task 3 and the reference is there) run with
// --task3-speed-only. Its JSON, or nothing and `why`.
std::optional<Json> referenceTask3Speed(const BvhBenchOptions& options, int threads, std::string& why) {
  const std::string self = currentExecutablePath();
#if defined(_WIN32)
  const char* kReferenceBench = "pathlab-bench-reference.exe";
#else
  const char* kReferenceBench = "pathlab-bench-reference";
#endif
  const std::filesystem::path reference = std::filesystem::path(self).parent_path() / kReferenceBench;
  if (self.empty() || !fileStatus(reference.string()).found) {
    why = "no reference build beside this program (" + std::string(kReferenceBench) +
          " is built where the reference is there: solutions/, or a student release's reference-objects/ "
          "for this platform)";
    return std::nullopt;
  }
  const std::filesystem::path out = std::filesystem::temp_directory_path() /
                                    ("pathlab-bench-reference-" + std::to_string(currentProcessId()) + ".json");
  std::vector<std::string> arguments;
  if (options.triangles > 0)
    arguments = {"--triangles", std::to_string(options.triangles)};
  else if (!options.mesh.empty())
    arguments = {options.mesh};
  arguments.insert(arguments.begin(), "bvh");
  for (const std::string& a :
       {std::string("--threads"), std::to_string(threads), std::string("--task3-speed-only"), out.string()}) {
    arguments.push_back(a);
  }
  std::string error;
  const int code = runProgram(reference.string(), arguments, error);
  const FileRead read = readRegularFile(out.string(), 1 << 20);
  removeFileQuietly(out.string());
  if (code != 0 || !read.opened) {
    why = reference.string() + " failed (" + (code < 0 ? error : "exit code " + std::to_string(code)) + ")";
    return std::nullopt;
  }
  Json json = Json::parse(read.bytes, nullptr, false);
  if (json.is_discarded() || json.value("task3", "") != "reference") {
    why = reference.string() + " did not report the reference's task 3";
    return std::nullopt;
  }
  return json;
}

// ours / theirs, when theirs was measured and is not 0 (an empty ray set).
std::optional<double> ratioTo(double ours, std::optional<double> theirs) {
  if (!theirs || !(*theirs > 0.0)) return std::nullopt;
  return ours / *theirs;
}

std::string cell(std::optional<double> v) {
  char b[16];
  if (v)
    std::snprintf(b, sizeof b, "%7.2f", *v);
  else
    std::snprintf(b, sizeof b, "%7s", "-");
  return std::string(b);
}

}  // namespace

void printBuilds(const BvhRun& run, const TreeCost& cost) {
  const char* label = run.label.c_str();
  std::printf("code: task 3 (BVH) %s, task 2 (triangle test in the leaves) %s\n", codeName(run.tasks[3]),
              codeName(run.tasks[2]));
  std::printf("mesh: %s, %zu triangles\n", run.description.c_str(), run.scene.triangleCount());
  std::printf("build, 1 thread: %s %.1f ms", label, run.buildTask * 1e3);
  if (run.buildEmbree) {
    std::printf(", Embree %.1f ms (%s/Embree time %.2f)", *run.buildEmbree * 1e3, label,
                run.buildTask / *run.buildEmbree);
  }
  std::printf("\n%s", formatBvhStatistics(bvhStatistics(run.bvh)).c_str());
  // The tree alone, walked by the framework on the primary rays: the score a
  // student can act on (and the grader's leaderboard measure), whatever their traversal does.
  std::printf("score of %s tree on the primary rays (lower is better): %s\n",
              run.label == "reference" ? "the reference's"
              : run.label == "yours"   ? "your"
                                       : "task 3's",
              formatTreeCost(cost).c_str());
  std::printf("fast path layout: +%.1f ms to gather the leaves and collapse (%s + layout", run.buildWide * 1e3, label);
  if (run.buildEmbree) std::printf(" / Embree time %.2f", (run.buildTask + run.buildWide) / *run.buildEmbree);
  std::printf("), %zu %d-wide nodes, %zu triangle packets, %.0f %% of lanes used\n", run.wide.nodeCount(),
              WideBvh::kWidth, run.wide.packetCount(), 100.0 * run.wide.laneOccupancy());
}

void printSpeeds(const BvhRun& run, Json& json) {
  std::printf("%-29s%-26s%s\n", "", "1 thread", std::to_string(run.threads).append(" threads").c_str());
  std::printf("%-8s %8s %8s | %7s %7s %7s | %7s %7s %7s | %s\n", "rays", "count", "", run.shortLabel.c_str(), "Embree",
              "ratio", run.shortLabel.c_str(), "Embree", "ratio", "mismatches");
  for (size_t s = 0; s < run.sets.size(); ++s) {
    const SetResult& r = run.results[s];
    const std::optional<double> ratio1 = ratioTo(r.task1, r.embree1), ratioN = ratioTo(r.taskN, r.embreeN);
    std::printf("%-8s %8zu %8s | %s %s %s | %s %s %s | %s\n", run.sets[s].name, run.sets[s].rays.size(), "Mrays/s",
                cell(r.task1).c_str(), cell(r.embree1).c_str(), cell(ratio1).c_str(), cell(r.taskN).c_str(),
                cell(r.embreeN).c_str(), cell(ratioN).c_str(),
                r.mismatches ? std::to_string(*r.mismatches).c_str() : "-");
    json[run.sets[s].name] = {{"task3_mrays", r.task1},
                              {"embree_mrays", r.embree1 ? Json(*r.embree1) : Json(nullptr)},
                              {"ratio", ratio1 ? Json(*ratio1) : Json(nullptr)},
                              {"mismatches", r.mismatches ? Json(*r.mismatches) : Json(nullptr)},
                              {"embree_misses", r.embreeMisses},
                              {"task3_mrays_threads", r.taskN},
                              {"embree_mrays_threads", r.embreeN ? Json(*r.embreeN) : Json(nullptr)}};
  }
  // The framework's render path walks task 3's tree; its hits must be task 3's, exactly.
  std::printf("fast path (--accel fast: the same tree %d-wide, %s)\n", WideBvh::kWidth,
              run.wide.usesAvx2() ? "eight boxes or triangles per AVX2 test" : "four boxes or triangles per SSE2 test");
  for (size_t s = 0; s < run.sets.size(); ++s) {
    const SetResult& r = run.results[s];
    const std::optional<double> ratio1 = ratioTo(r.fast1, r.embree1), ratioN = ratioTo(r.fastN, r.embreeN);
    std::printf("%-8s %8zu %8s | %s %s %s | %s %s %s | %zu vs task 3\n", run.sets[s].name, run.sets[s].rays.size(),
                "Mrays/s", cell(r.fast1).c_str(), cell(r.embree1).c_str(), cell(ratio1).c_str(), cell(r.fastN).c_str(),
                cell(r.embreeN).c_str(), cell(ratioN).c_str(), r.fastMismatches);
    Json& entry = json[run.sets[s].name];
    entry["fast_mrays"] = r.fast1;
    entry["fast_mrays_threads"] = r.fastN;
    entry["fast_ratio"] = ratio1 ? Json(*ratio1) : Json(nullptr);
    entry["fast_mismatches_vs_task3"] = r.fastMismatches;
  }
}

Json compareWithReferenceTask3(const BvhRun& run) {
  std::string why;
  const std::optional<Json> reference = referenceTask3Speed(run.options, run.threads, why);
  if (!reference) {
    std::printf("the reference's task 3: not measured: %s\n", why.c_str());
    return nullptr;
  }
  std::printf("the reference's task 3 on the same mesh and view (%s):\n", "pathlab-bench-reference");
  Json comparison;
  for (size_t s = 0; s < run.sets.size(); ++s) {
    const RaySet& set = run.sets[s];
    const Json& theirs = (*reference)[set.name];
    const double ref1 = theirs.value("task3_mrays", 0.0), refN = theirs.value("task3_mrays_threads", 0.0);
    const size_t refRays = theirs.value("rays", size_t(0));
    const SetResult& r = run.results[s];
    // Shadow and diffuse rays start at the primary rays' hits: other hits, other rays.
    const bool sameRays = refRays == set.rays.size() && refRays > 0 && ref1 > 0.0 && refN > 0.0;
    const std::optional<double> ratio1 = sameRays ? ratioTo(r.task1, ref1) : std::nullopt;
    const std::optional<double> ratioN = sameRays ? ratioTo(r.taskN, refN) : std::nullopt;
    std::printf("%-8s %8zu %8s | %7.2f %7s %s | %7.2f %7s %s | %s\n", set.name, refRays, "Mrays/s", ref1, "",
                cell(ratio1).c_str(), refN, "", cell(ratioN).c_str(),
                sameRays ? "yours / reference"
                         : ("not the same rays (yours " + std::to_string(set.rays.size()) +
                            "): your hits differ from the reference's")
                               .c_str());
    comparison[set.name] = {{"rays", refRays},
                            {"reference_mrays", ref1},
                            {"reference_mrays_threads", refN},
                            {"ratio", ratio1 ? Json(*ratio1) : Json(nullptr)}};
  }
  return comparison;
}

}  // namespace pathlab::bench
