// What one run of `pathlab-bench bvh` measured (bvh_bench.cpp), and its
// report (bvh_report.cpp).
#pragma once

#include <nlohmann/json.hpp>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bvh_bench.h"
#include "core/scene.h"
#include "linked_tasks.h"
#include "render/accelerator.h"
#include "render/wide_bvh.h"
#include "tasks/bvh.h"
#include "util/ray.h"
#ifdef PATHLAB_HAVE_EMBREE
#include "embree_scene.h"
#endif

namespace pathlab::bench {

struct RaySet {
  const char* name;
  std::vector<Ray> rays;
  std::vector<Interval> ranges;
  bool occlusion = false;
};

struct SetResult {
  double task1 = 0.0, taskN = 0.0;  // task 3's BVH (with task 2's triangle test in its leaves)
  std::optional<double> embree1, embreeN;
  std::optional<size_t> mismatches;  // rays where task 3 is wrong
  size_t embreeMisses = 0;           // true hits that Embree missed
  double fast1 = 0.0, fastN = 0.0;   // the framework's render path (--accel fast) over the same tree
  size_t fastMismatches = 0;         // rays where it differs from task 3 at all (primitive, t, or blocked)
};

// One run: the mesh, its trees (task 3's, the fast path's, Embree's) and
// what each ray set measured.
struct BvhRun {
  explicit BvhRun(const BvhBenchOptions& given) : options(given) {}
  const BvhBenchOptions& options;
  LinkedTasks tasks;
  std::string label, shortLabel;  // whose task 3: "yours", "reference"; "ref" in the table
  int threads = 1;
  std::string description;  // the mesh
  Scene scene;
  Bvh bvh;
  double buildTask = 0.0;
  LeafGeometry geometry;  // the leaves' geometry in leaf order, read by task 3's walk and the fast path
  WideBvh wide;
  double buildWide = 0.0;
  std::optional<double> buildEmbree;
#ifdef PATHLAB_HAVE_EMBREE
  std::unique_ptr<EmbreeScene> embree;
#endif
  std::vector<RaySet> sets;
  std::vector<SetResult> results;
};

// The report's head: whose code, the mesh, the builds, the tree and its score.
void printBuilds(const BvhRun& run, const TreeCost& cost);
// Task 3's and the fast path's speeds per ray set against Embree's, printed
// as two tables and added to `json`.
void printSpeeds(const BvhRun& run, nlohmann::json& json);
// The student's task 3 against the reference's: same mesh, same machine, one
// run (null when the reference build beside this program could not say).
nlohmann::json compareWithReferenceTask3(const BvhRun& run);

}  // namespace pathlab::bench
