#include "bvh_bench.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <thread>
#include <vector>

#include "render/accelerator.h"
#include "render/task_wiring.h"
#include "render/wide_bvh.h"
#include "scene/procedural.h"
#include "scene/scene_io.h"
#include "tasks/bvh.h"
#include "util/error.h"
#include "util/input_file.h"
#include "util/parallel.h"
#include "util/platform.h"
#include "util/random.h"
#ifdef PATHLAB_HAVE_EMBREE
#include "embree_scene.h"
#endif
#include "linked_tasks.h"

namespace pathlab::bench {
namespace {

using Json = nlohmann::json;
constexpr int kImageSize = 512;  // primary rays: one per pixel of a 512 x 512 view
constexpr int kRepeats = 3;      // timings are the median of three runs

Scene loadMesh(const std::string& requested, int triangles, std::string& description) {
  if (triangles > 0) {
    // rings bands of 2 rings segments: about 4 rings^2 triangles.
    const int rings = std::max(4, int(std::lround(std::sqrt(double(triangles) / 4.0))));
    Scene scene;
    scene.materials.push_back(Material{.name = "default"});
    scene.meshes.push_back(bumpySphere(rings, 2 * rings));
    scene.indexPrimitives();
    description = scene.meshes[0].name;
    return scene;
  }
  std::string path = requested;
  if (path.empty()) {
    // The scanned bunny from the optional data folder, else its stand-in.
    const char* data = std::getenv("PATHLAB_DATA_DIR");
    if (data && *data) path = std::string(data) + "/models/stanford-bunny.obj";
    std::error_code missing;
    if (path.empty() || !std::filesystem::exists(path, missing)) {
      Scene scene = scanLikeScene();
      description = scene.meshes[0].name;
      return scene;
    }
  }
  std::error_code unresolved;  // then the path as given: the loader names what is wrong with it
  std::string absolute = std::filesystem::absolute(path, unresolved).string();
  if (unresolved) absolute = path;
  Json scene = {{"meshes", Json::array({Json{{"obj", absolute}}})}};
  description = path;
  return loadSceneFromJson(scene.dump(), path, "");
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

// Runs body(i) for i in [0, n) on `threads` threads; returns seconds.
double timeParallel(size_t n, int threads, const std::function<void(size_t)>& body) {
  const auto start = std::chrono::steady_clock::now();
  std::atomic<size_t> next{0};
  constexpr size_t kChunk = 1024;
  auto worker = [&] {
    for (size_t begin = next.fetch_add(kChunk); begin < n; begin = next.fetch_add(kChunk)) {
      for (size_t i = begin; i < std::min(n, begin + kChunk); ++i) body(i);
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();
  for (std::thread& thread : pool) thread.join();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Median seconds of kRepeats runs of `build`; `freeLast` runs first, off the
// clock, so freeing the previous run's structures is not timed (as Embree's
// timing leaves its own out).
double medianBuildSeconds(const std::function<void()>& freeLast, const std::function<void()>& build) {
  std::vector<double> seconds;
  for (int r = 0; r < kRepeats; ++r) {
    freeLast();
    const auto start = std::chrono::steady_clock::now();
    build();
    seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  return median(seconds);
}

double mraysPerSecond(size_t n, int threads, const std::function<void(size_t)>& body) {
  std::vector<double> seconds;
  for (int r = 0; r < kRepeats; ++r) seconds.push_back(timeParallel(n, threads, body));
  return double(n) / median(seconds) / 1e6;
}

struct RaySet {
  const char* name;
  std::vector<Ray> rays;
  std::vector<Interval> ranges;
  bool occlusion = false;
};

// Primary rays of a view that frames the mesh; shadow rays from their hits
// towards a point light; diffuse rays from their hits in cosine-distributed
// directions (incoherent).
std::vector<RaySet> makeRaySets(const Scene& scene, const Bvh& bvh, const LeafGeometry& geometry) {
  Aabb bounds;
  for (const Point3& p : scene.meshes[0].positions) bounds.grow(p);
  const Point3 center = bounds.centroid();
  const float radius = 0.5f * glm::length(bounds.extent());
  Camera camera;
  camera.lookAt = center;
  camera.position = center + glm::normalize(Vec3(0.3f, 0.4f, 1.0f)) * (2.4f * radius);
  camera.vfovDegrees = 45.0f;
  const Vec3 forward = glm::normalize(camera.lookAt - camera.position);
  const Vec3 right = glm::normalize(glm::cross(forward, camera.up));
  const Vec3 up = glm::cross(right, forward);
  const float half = std::tan(glm::radians(camera.vfovDegrees) * 0.5f);
  const Point3 light = center + Vec3(0.5f, 2.0f, 0.8f) * (2.0f * radius);

  RaySet primary{"primary", {}, {}, false}, shadow{"shadow", {}, {}, true}, diffuse{"diffuse", {}, {}, false};
  for (int y = 0; y < kImageSize; ++y) {
    for (int x = 0; x < kImageSize; ++x) {
      const float sx = (2.0f * (float(x) + 0.5f) / kImageSize - 1.0f) * half;
      const float sy = (1.0f - 2.0f * (float(y) + 0.5f) / kImageSize) * half;
      Ray ray{camera.position, glm::normalize(forward + sx * right + sy * up)};
      primary.rays.push_back(ray);
      primary.ranges.push_back({0.0f, kInfinity});
      std::optional<PrimitiveHit> hit = intersectClosest(bvh, geometry, ray, {0.0f, kInfinity});
      if (!hit) continue;
      const glm::uvec3& t = scene.meshes[0].triangles[scene.primitives[hit->primitive].index];
      const auto& p = scene.meshes[0].positions;
      Vec3 normal = glm::normalize(glm::cross(p[t.y] - p[t.x], p[t.z] - p[t.x]));
      if (glm::dot(normal, ray.direction) > 0.0f) normal = -normal;
      const Point3 origin = ray.at(hit->t) + normal * (1e-4f * radius);
      const Vec3 toLight = light - origin;
      shadow.rays.push_back(Ray{origin, glm::normalize(toLight)});
      shadow.ranges.push_back({0.0f, glm::length(toLight) * (1.0f - 1e-4f)});
      // Cosine-weighted direction about the normal.
      Sampler sampler(uint32_t(y * kImageSize + x), 0, 1);
      const Vec2 u = sampler.next2D();
      const float r = std::sqrt(u.x), phi = 2.0f * kPi * u.y;
      const Vec3 a = std::abs(normal.x) > 0.9f ? Vec3(0, 1, 0) : Vec3(1, 0, 0);
      const Vec3 tangent = glm::normalize(glm::cross(normal, a)), bitangent = glm::cross(normal, tangent);
      const Vec3 direction = r * std::cos(phi) * tangent + r * std::sin(phi) * bitangent +
                             std::sqrt(std::max(0.0f, 1.0f - u.x)) * normal;
      diffuse.rays.push_back(Ray{origin, glm::normalize(direction)});
      diffuse.ranges.push_back({0.0f, kInfinity});
    }
  }
  return {primary, shadow, diffuse};
}

// Task 3's own traversal on one set of rays: Mrays/s on one thread and on
// `threads`, and its answers (hits, or blocked for shadow rays).
struct Task3Run {
  double mrays1 = 0.0, mraysN = 0.0;
  std::vector<std::optional<PrimitiveHit>> hits;
  std::vector<uint8_t> blocked;
};

Task3Run runTask3(const RaySet& set, const Bvh& bvh, const LeafGeometry& geometry, int threads) {
  Task3Run run;
  run.hits.resize(set.rays.size());
  run.blocked.resize(set.rays.size());
  auto withTask = [&](size_t i) {
    if (set.occlusion) run.blocked[i] = intersectAny(bvh, geometry, set.rays[i], set.ranges[i]);
    else run.hits[i] = intersectClosest(bvh, geometry, set.rays[i], set.ranges[i]);
  };
  run.mrays1 = mraysPerSecond(set.rays.size(), 1, withTask);
  run.mraysN = mraysPerSecond(set.rays.size(), threads, withTask);
  return run;
}

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
  const std::filesystem::path out =
      std::filesystem::temp_directory_path() / ("pathlab-bench-reference-" + std::to_string(currentProcessId()) + ".json");
  std::vector<std::string> arguments;
  if (options.triangles > 0) arguments = {"--triangles", std::to_string(options.triangles)};
  else if (!options.mesh.empty()) arguments = {options.mesh};
  arguments.insert(arguments.begin(), "bvh");
  for (const std::string& a : {std::string("--threads"), std::to_string(threads), std::string("--task3-speed-only"),
                               out.string()}) {
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

struct SetResult {
  double task1 = 0.0, taskN = 0.0;  // task 3's BVH (with task 2's triangle test in its leaves)
  std::optional<double> embree1, embreeN;
  std::optional<size_t> mismatches;  // rays where task 3 is wrong
  size_t embreeMisses = 0;           // true hits that Embree missed
  double fast1 = 0.0, fastN = 0.0;   // the framework's render path (--accel fast) over the same tree
  size_t fastMismatches = 0;         // rays where it differs from task 3 at all (primitive, t, or blocked)
};

#ifdef PATHLAB_HAVE_EMBREE  // only the Embree comparison asks
// Does the ray hit triangle `primitive` at about distance t, by a
// double-precision Moller-Trumbore with edges counted as inside?
bool hitsInDouble(const Scene& scene, const Ray& ray, uint32_t primitive, float t) {
  const PrimitiveRef& ref = scene.primitives[primitive];
  if (ref.isSphere()) return false;
  const TriangleMesh& mesh = scene.meshes[ref.mesh];
  const glm::uvec3& tri = mesh.triangles[ref.index];
  using D = glm::dvec3;
  const D p0(mesh.positions[tri.x]), e1 = D(mesh.positions[tri.y]) - p0, e2 = D(mesh.positions[tri.z]) - p0;
  const D o(ray.origin), d(ray.direction), pv = glm::cross(d, e2);
  const double det = glm::dot(e1, pv);
  if (det == 0.0) return false;
  const D s = o - p0, qv = glm::cross(s, e1);
  const double b1 = glm::dot(s, pv) / det, b2 = glm::dot(d, qv) / det, exact = glm::dot(e2, qv) / det;
  constexpr double kEdge = 1e-9;
  return b1 >= -kEdge && b2 >= -kEdge && b1 + b2 <= 1.0 + kEdge && std::abs(exact - t) <= 1e-4 * exact;
}
#endif

}  // namespace

int runBvhBench(const BvhBenchOptions& options) {
  // Whose BVH this is: task 3 as linked (and task 2's triangle test in the leaves).
  const LinkedTasks tasks = linkedTasks();
  const std::string label = tasks[3] == Code::Yours ? "yours" : tasks[3] == Code::Reference ? "reference" : "task 3";
  const std::string shortLabel = tasks[3] == Code::Reference ? "ref" : label;
  const int threads = options.threads > 0 ? options.threads : defaultThreadCount();
  std::string description;
  Scene scene = loadMesh(options.mesh, options.triangles, description);
  const size_t triangles = scene.triangleCount();
  if (scene.meshes.size() != 1 || !scene.spheres.empty()) throw Error("pathlab-bench bvh: expected one triangle mesh");

  // Builds: median of three, one thread each.
  const std::vector<Aabb> bounds = primitiveBounds(scene);
  Bvh bvh;
  const double buildTask = medianBuildSeconds([&] { bvh = Bvh{}; }, [&] { bvh = buildBvh(bounds); });
  const std::string problem = validateBvh(bvh, scene.primitives.size(), &bounds);
  if (!problem.empty()) throw Error("the task-3 BVH (" + describeTasks(tasks, {3}) + ") is not valid: " + problem);
  if (!options.task3SpeedOut.empty()) {
    // Asked by a student build (referenceTask3Speed): task 3's speed alone, as JSON.
    const LeafGeometry leaves(scene, bvh.primitives, kLinkedTasks.primitives);
    Json json = {{"task3", codeName(tasks[3])}};
    for (const RaySet& set : makeRaySets(scene, bvh, leaves)) {
      const Task3Run run = runTask3(set, bvh, leaves, threads);
      json[set.name] = {{"rays", set.rays.size()}, {"task3_mrays", run.mrays1}, {"task3_mrays_threads", run.mraysN}};
    }
    writeFileAtomically(options.task3SpeedOut, json.dump());
    return 0;
  }
  // The fast path's layout: the leaves' geometry gathered in leaf order, then
  // task 3's tree collapsed to eight children per node. (The task-3 walk reads
  // the same gathered geometry; its build time above leaves it out.)
  LeafGeometry geometry;
  WideBvh wide;
  const double buildWide = medianBuildSeconds(
      [&] {
        wide = WideBvh();
        geometry = LeafGeometry();
      },
      [&] {
        geometry = LeafGeometry(scene, bvh.primitives, kLinkedTasks.primitives);
        wide = WideBvh(bvh, geometry, kLinkedTasks.primitives);
      });

  std::optional<double> buildEmbree;
#ifdef PATHLAB_HAVE_EMBREE
  std::unique_ptr<EmbreeScene> embree;
  std::vector<double> buildTimes;
  for (int r = 0; r < kRepeats; ++r) {
    embree = std::make_unique<EmbreeScene>(scene.meshes[0], 1);
    buildTimes.push_back(embree->buildSeconds());
  }
  buildEmbree = median(buildTimes);
#else
  std::fprintf(stderr, "Embree was not found when PathLab was built (install libembree-dev): skipping the comparison\n");
#endif

  std::vector<RaySet> sets = makeRaySets(scene, bvh, geometry);
  std::vector<SetResult> results(sets.size());
  for (size_t s = 0; s < sets.size(); ++s) {
    const RaySet& set = sets[s];
    SetResult& result = results[s];
    Task3Run task3 = runTask3(set, bvh, geometry, threads);
    const std::vector<std::optional<PrimitiveHit>>& hits = task3.hits;
    const std::vector<uint8_t>& blocked = task3.blocked;
    result.task1 = task3.mrays1;
    result.taskN = task3.mraysN;
    std::vector<std::optional<PrimitiveHit>> fastHits(set.rays.size());
    std::vector<uint8_t> fastBlocked(set.rays.size());
    auto withFast = [&](size_t i) {
      if (set.occlusion) fastBlocked[i] = wide.intersectAny(set.rays[i], set.ranges[i]);
      else fastHits[i] = wide.intersectClosest(set.rays[i], set.ranges[i]);
    };
    result.fast1 = mraysPerSecond(set.rays.size(), 1, withFast);
    result.fastN = mraysPerSecond(set.rays.size(), threads, withFast);
    for (size_t i = 0; i < set.rays.size(); ++i) {
      if (set.occlusion) {
        result.fastMismatches += blocked[i] != fastBlocked[i];
      } else {
        const auto &a = hits[i], &b = fastHits[i];
        result.fastMismatches += a.has_value() != b.has_value() || (a && (a->primitive != b->primitive || a->t != b->t));
      }
    }
#ifdef PATHLAB_HAVE_EMBREE
    std::vector<std::optional<PrimitiveHit>> embreeHits(set.rays.size());
    std::vector<uint8_t> embreeBlocked(set.rays.size());
    auto withEmbree = [&](size_t i) {
      if (set.occlusion) embreeBlocked[i] = embree->occluded(set.rays[i], set.ranges[i]);
      else embreeHits[i] = embree->intersect(set.rays[i], set.ranges[i]);
    };
    result.embree1 = mraysPerSecond(set.rays.size(), 1, withEmbree);
    result.embreeN = mraysPerSecond(set.rays.size(), threads, withEmbree);
    // Agreement: same hit or miss; hits on different triangles count only
    // when their distances differ too (ties on shared edges are fine). Where
    // they disagree, double precision decides who is right: a hit Embree's
    // default (non-watertight) mode misses is Embree's, not a mismatch.
    size_t mismatches = 0, embreeMisses = 0;
    auto confirmed = [&](size_t i, const std::optional<PrimitiveHit>& hit) {
      return hit && hitsInDouble(scene, set.rays[i], hit->primitive, hit->t);
    };
    for (size_t i = 0; i < set.rays.size(); ++i) {
      if (set.occlusion) {
        mismatches += blocked[i] != embreeBlocked[i];
        continue;
      }
      const auto &ours = hits[i], &theirs = embreeHits[i];
      const bool agree = ours.has_value() == theirs.has_value() &&
                         (!ours || ours->primitive == theirs->primitive || std::abs(ours->t - theirs->t) <= 1e-4f * ours->t);
      if (agree) continue;
      const bool oursNearer = ours && (!theirs || ours->t < theirs->t);
      if (oursNearer && confirmed(i, ours)) ++embreeMisses;
      else ++mismatches;
    }
    result.mismatches = mismatches;
    result.embreeMisses = embreeMisses;
#endif
  }

  // Report. Every "ref"/"yours" names task 3 as linked, whose code it is.
  std::printf("code: task 3 (BVH) %s, task 2 (triangle test in the leaves) %s\n", codeName(tasks[3]),
              codeName(tasks[2]));
  std::printf("mesh: %s, %zu triangles\n", description.c_str(), triangles);
  std::printf("build, 1 thread: %s %.1f ms", label.c_str(), buildTask * 1e3);
  if (buildEmbree) {
    std::printf(", Embree %.1f ms (%s/Embree time %.2f)", *buildEmbree * 1e3, label.c_str(), buildTask / *buildEmbree);
  }
  std::printf("\n%s", formatBvhStatistics(bvhStatistics(bvh)).c_str());
  // The tree alone, walked by the framework on the primary rays: the score a student can act on (and
  // the grader's leaderboard measure), whatever their traversal does.
  const TreeCost cost = treeCost(bvh, geometry, sets[0].rays);
  std::printf("score of %s tree on the primary rays (lower is better): %s\n", label == "reference" ? "the reference's" : label == "yours" ? "your" : "task 3's",
              formatTreeCost(cost).c_str());
  std::printf("fast path layout: +%.1f ms to gather the leaves and collapse (%s + layout", buildWide * 1e3,
              label.c_str());
  if (buildEmbree) std::printf(" / Embree time %.2f", (buildTask + buildWide) / *buildEmbree);
  std::printf("), %zu %d-wide nodes, %zu triangle packets, %.0f %% of lanes used\n", wide.nodeCount(),
              WideBvh::kWidth, wide.packetCount(), 100.0 * wide.laneOccupancy());
  std::printf("%-29s%-26s%s\n", "", "1 thread", std::to_string(threads).append(" threads").c_str());
  std::printf("%-8s %8s %8s | %7s %7s %7s | %7s %7s %7s | %s\n", "rays", "count", "", shortLabel.c_str(), "Embree",
              "ratio", shortLabel.c_str(), "Embree", "ratio", "mismatches");
  auto cell = [](std::optional<double> v) {
    char b[16];
    if (v) std::snprintf(b, sizeof b, "%7.2f", *v);
    else std::snprintf(b, sizeof b, "%7s", "-");
    return std::string(b);
  };
  Json json;
  for (size_t s = 0; s < sets.size(); ++s) {
    const SetResult& r = results[s];
    const std::optional<double> ratio1 = ratioTo(r.task1, r.embree1), ratioN = ratioTo(r.taskN, r.embreeN);
    std::printf("%-8s %8zu %8s | %s %s %s | %s %s %s | %s\n", sets[s].name, sets[s].rays.size(), "Mrays/s",
                cell(r.task1).c_str(), cell(r.embree1).c_str(), cell(ratio1).c_str(), cell(r.taskN).c_str(),
                cell(r.embreeN).c_str(), cell(ratioN).c_str(),
                r.mismatches ? std::to_string(*r.mismatches).c_str() : "-");
    json[sets[s].name] = {{"task3_mrays", r.task1},
                          {"embree_mrays", r.embree1 ? Json(*r.embree1) : Json(nullptr)},
                          {"ratio", ratio1 ? Json(*ratio1) : Json(nullptr)},
                          {"mismatches", r.mismatches ? Json(*r.mismatches) : Json(nullptr)},
                          {"embree_misses", r.embreeMisses},
                          {"task3_mrays_threads", r.taskN},
                          {"embree_mrays_threads", r.embreeN ? Json(*r.embreeN) : Json(nullptr)}};
  }
  // The framework's render path walks task 3's tree; its hits must be task 3's, exactly.
  std::printf("fast path (--accel fast: the same tree %d-wide, %s)\n", WideBvh::kWidth,
              wide.usesAvx2() ? "eight boxes or triangles per AVX2 test" : "four boxes or triangles per SSE2 test");
  for (size_t s = 0; s < sets.size(); ++s) {
    const SetResult& r = results[s];
    const std::optional<double> ratio1 = ratioTo(r.fast1, r.embree1), ratioN = ratioTo(r.fastN, r.embreeN);
    std::printf("%-8s %8zu %8s | %s %s %s | %s %s %s | %zu vs task 3\n", sets[s].name, sets[s].rays.size(), "Mrays/s",
                cell(r.fast1).c_str(), cell(r.embree1).c_str(), cell(ratio1).c_str(), cell(r.fastN).c_str(),
                cell(r.embreeN).c_str(), cell(ratioN).c_str(), r.fastMismatches);
    json[sets[s].name]["fast_mrays"] = r.fast1;
    json[sets[s].name]["fast_mrays_threads"] = r.fastN;
    json[sets[s].name]["fast_ratio"] = ratio1 ? Json(*ratio1) : Json(nullptr);
    json[sets[s].name]["fast_mismatches_vs_task3"] = r.fastMismatches;
  }
  // The student's task 3 against the reference's, same mesh, same machine, one run.
  if (tasks[3] == Code::Yours) {
    std::string why;
    if (const std::optional<Json> reference = referenceTask3Speed(options, threads, why)) {
      std::printf("the reference's task 3 on the same mesh and view (%s):\n", "pathlab-bench-reference");
      Json comparison;
      for (size_t s = 0; s < sets.size(); ++s) {
        const Json& theirs = (*reference)[sets[s].name];
        const double ref1 = theirs.value("task3_mrays", 0.0), refN = theirs.value("task3_mrays_threads", 0.0);
        const size_t refRays = theirs.value("rays", size_t(0));
        const SetResult& r = results[s];
        // Shadow and diffuse rays start at the primary rays' hits: other hits, other rays.
        const bool sameRays = refRays == sets[s].rays.size() && refRays > 0 && ref1 > 0.0 && refN > 0.0;
        const std::optional<double> ratio1 = sameRays ? ratioTo(r.task1, ref1) : std::nullopt;
        const std::optional<double> ratioN = sameRays ? ratioTo(r.taskN, refN) : std::nullopt;
        std::printf("%-8s %8zu %8s | %7.2f %7s %s | %7.2f %7s %s | %s\n", sets[s].name, refRays, "Mrays/s", ref1, "",
                    cell(ratio1).c_str(), refN, "", cell(ratioN).c_str(),
                    sameRays ? "yours / reference"
                             : ("not the same rays (yours " + std::to_string(sets[s].rays.size()) +
                                "): your hits differ from the reference's").c_str());
        comparison[sets[s].name] = {{"rays", refRays}, {"reference_mrays", ref1}, {"reference_mrays_threads", refN},
                                    {"ratio", ratio1 ? Json(*ratio1) : Json(nullptr)}};
      }
      json["reference_task3"] = comparison;
    } else {
      std::printf("the reference's task 3: not measured: %s\n", why.c_str());
      json["reference_task3"] = nullptr;
    }
  }
  for (size_t s = 0; s < sets.size(); ++s) {
    if (results[s].embreeMisses == 0) continue;
    std::printf("%s: Embree missed %zu hits that task 3 (%s) found and double precision confirms "
                "(Embree's default mode is not watertight)\n", sets[s].name, results[s].embreeMisses, label.c_str());
  }
  // Whose code ran: "yours" (the student's file), "reference" (solutions/)
  // or "unknown" (a binary built without the record); ratios are task 3 / Embree.
  json["task3"] = codeName(tasks[3]);
  json["tree_cost"] = {{"nodes_per_ray", cost.nodesPerRay}, {"primitive_tests_per_ray", cost.primitiveTestsPerRay},
                       {"score", cost.score()}, {"sah_cost", sahCost(bvh)}};
  json["tasks"] = tasksJson(tasks, {2, 3});
  json["build_ms_task3"] = buildTask * 1e3;
  json["build_ms_embree"] = buildEmbree ? Json(*buildEmbree * 1e3) : Json(nullptr);
  json["build_ms_fast_collapse"] = buildWide * 1e3;
  json["fast_lane_occupancy"] = wide.laneOccupancy();
  json["fast_box_test"] = wide.usesAvx2() ? "avx2" : "baseline";
  json["triangles"] = triangles;
  json["threads"] = threads;
  if (options.json) std::printf("%s\n", json.dump().c_str());
  return 0;
}

}  // namespace pathlab::bench
