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
#include "util/random.h"
#ifdef PATHLAB_HAVE_EMBREE
#include "embree_scene.h"
#endif
#include "bvh_run.h"
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

// Task 3's tree, built (median of three, one thread) and validated.
void buildTask3(BvhRun& run) {
  const std::vector<Aabb> bounds = primitiveBounds(run.scene);
  run.buildTask = medianBuildSeconds([&] { run.bvh = Bvh{}; }, [&] { run.bvh = buildBvh(bounds); });
  const std::string problem = validateBvh(run.bvh, run.scene.primitives.size(), &bounds);
  if (!problem.empty()) throw Error("the task-3 BVH (" + describeTasks(run.tasks, {3}) + ") is not valid: " + problem);
}

// Asked by a student build (referenceTask3Speed): task 3's speed alone, as JSON.
void writeTask3Speed(const BvhRun& run) {
  const LeafGeometry leaves(run.scene, run.bvh.primitives, kLinkedTasks.primitives);
  Json json = {{"task3", codeName(run.tasks[3])}};
  for (const RaySet& set : makeRaySets(run.scene, run.bvh, leaves)) {
    const Task3Run task3 = runTask3(set, run.bvh, leaves, run.threads);
    json[set.name] = {{"rays", set.rays.size()}, {"task3_mrays", task3.mrays1}, {"task3_mrays_threads", task3.mraysN}};
  }
  writeFileAtomically(run.options.task3SpeedOut, json.dump());
}

// The fast path's layout: the leaves' geometry gathered in leaf order, then
// task 3's tree collapsed to eight children per node (the task-3 walk reads
// the same gathered geometry; its build time leaves it out); and Embree's.
void buildOthers(BvhRun& run) {
  run.buildWide = medianBuildSeconds(
      [&] {
        run.wide = WideBvh();
        run.geometry = LeafGeometry();
      },
      [&] {
        run.geometry = LeafGeometry(run.scene, run.bvh.primitives, kLinkedTasks.primitives);
        run.wide = WideBvh(run.bvh, run.geometry, kLinkedTasks.primitives);
      });
#ifdef PATHLAB_HAVE_EMBREE
  std::vector<double> buildTimes;
  for (int r = 0; r < kRepeats; ++r) {
    run.embree = std::make_unique<EmbreeScene>(run.scene.meshes[0], 1);
    buildTimes.push_back(run.embree->buildSeconds());
  }
  run.buildEmbree = median(buildTimes);
#else
  std::fprintf(stderr, "Embree was not found when PathLab was built (install libembree-dev): skipping the comparison\n");
#endif
}

// The fast path's speed on a set, and the rays where it differs from task 3 at all.
void measureFastPath(const BvhRun& run, const RaySet& set, const Task3Run& task3, SetResult& result) {
  std::vector<std::optional<PrimitiveHit>> fastHits(set.rays.size());
  std::vector<uint8_t> fastBlocked(set.rays.size());
  auto withFast = [&](size_t i) {
    if (set.occlusion)
      fastBlocked[i] = run.wide.intersectAny(set.rays[i], set.ranges[i]);
    else
      fastHits[i] = run.wide.intersectClosest(set.rays[i], set.ranges[i]);
  };
  result.fast1 = mraysPerSecond(set.rays.size(), 1, withFast);
  result.fastN = mraysPerSecond(set.rays.size(), run.threads, withFast);
  for (size_t i = 0; i < set.rays.size(); ++i) {
    if (set.occlusion) {
      result.fastMismatches += task3.blocked[i] != fastBlocked[i];
    } else {
      const auto &a = task3.hits[i], &b = fastHits[i];
      result.fastMismatches += a.has_value() != b.has_value() || (a && (a->primitive != b->primitive || a->t != b->t));
    }
  }
}

// Embree's speed on a set, and where task 3 disagrees with it. Agreement: the
// same hit or miss; hits on different triangles count only when their
// distances differ too (ties on shared edges are fine). Where they disagree,
// double precision decides who is right: a hit Embree's default
// (non-watertight) mode misses is Embree's, not a mismatch.
void measureEmbree([[maybe_unused]] const BvhRun& run, [[maybe_unused]] const RaySet& set,
                   [[maybe_unused]] const Task3Run& task3, [[maybe_unused]] SetResult& result) {
#ifdef PATHLAB_HAVE_EMBREE
  std::vector<std::optional<PrimitiveHit>> embreeHits(set.rays.size());
  std::vector<uint8_t> embreeBlocked(set.rays.size());
  auto withEmbree = [&](size_t i) {
    if (set.occlusion)
      embreeBlocked[i] = run.embree->occluded(set.rays[i], set.ranges[i]);
    else
      embreeHits[i] = run.embree->intersect(set.rays[i], set.ranges[i]);
  };
  result.embree1 = mraysPerSecond(set.rays.size(), 1, withEmbree);
  result.embreeN = mraysPerSecond(set.rays.size(), run.threads, withEmbree);
  size_t mismatches = 0, embreeMisses = 0;
  auto confirmed = [&](size_t i, const std::optional<PrimitiveHit>& hit) {
    return hit && hitsInDouble(run.scene, set.rays[i], hit->primitive, hit->t);
  };
  for (size_t i = 0; i < set.rays.size(); ++i) {
    if (set.occlusion) {
      mismatches += task3.blocked[i] != embreeBlocked[i];
      continue;
    }
    const auto &ours = task3.hits[i], &theirs = embreeHits[i];
    const bool agree = ours.has_value() == theirs.has_value() && (!ours || ours->primitive == theirs->primitive ||
                                                                  std::abs(ours->t - theirs->t) <= 1e-4f * ours->t);
    if (agree) continue;
    const bool oursNearer = ours && (!theirs || ours->t < theirs->t);
    if (oursNearer && confirmed(i, ours))
      ++embreeMisses;
    else
      ++mismatches;
  }
  result.mismatches = mismatches;
  result.embreeMisses = embreeMisses;
#endif
}

}  // namespace

int runBvhBench(const BvhBenchOptions& options) {
  BvhRun run(options);
  // Whose BVH this is: task 3 as linked (and task 2's triangle test in the leaves).
  run.tasks = linkedTasks();
  run.label = run.tasks[3] == Code::Yours ? "yours" : run.tasks[3] == Code::Reference ? "reference" : "task 3";
  run.shortLabel = run.tasks[3] == Code::Reference ? "ref" : run.label;
  run.threads = options.threads > 0 ? options.threads : defaultThreadCount();
  run.scene = loadMesh(options.mesh, options.triangles, run.description);
  if (run.scene.meshes.size() != 1 || !run.scene.spheres.empty()) {
    throw Error("pathlab-bench bvh: expected one triangle mesh");
  }
  buildTask3(run);
  if (!options.task3SpeedOut.empty()) {
    writeTask3Speed(run);
    return 0;
  }
  buildOthers(run);
  run.sets = makeRaySets(run.scene, run.bvh, run.geometry);
  run.results.resize(run.sets.size());
  for (size_t s = 0; s < run.sets.size(); ++s) {
    const Task3Run task3 = runTask3(run.sets[s], run.bvh, run.geometry, run.threads);
    run.results[s].task1 = task3.mrays1;
    run.results[s].taskN = task3.mraysN;
    measureFastPath(run, run.sets[s], task3, run.results[s]);
    measureEmbree(run, run.sets[s], task3, run.results[s]);
  }

  // Report. Every "ref"/"yours" names task 3 as linked, whose code it is.
  const TreeCost cost = treeCost(run.bvh, run.geometry, run.sets[0].rays);
  printBuilds(run, cost);
  Json json;
  printSpeeds(run, json);
  if (run.tasks[3] == Code::Yours) json["reference_task3"] = compareWithReferenceTask3(run);
  for (size_t s = 0; s < run.sets.size(); ++s) {
    if (run.results[s].embreeMisses == 0) continue;
    std::printf("%s: Embree missed %zu hits that task 3 (%s) found and double precision confirms "
                "(Embree's default mode is not watertight)\n",
                run.sets[s].name, run.results[s].embreeMisses, run.label.c_str());
  }
  // Whose code ran: "yours" (the student's file), "reference" (solutions/)
  // or "unknown" (a binary built without the record); ratios are task 3 / Embree.
  json["task3"] = codeName(run.tasks[3]);
  json["tree_cost"] = {{"nodes_per_ray", cost.nodesPerRay},
                       {"primitive_tests_per_ray", cost.primitiveTestsPerRay},
                       {"score", cost.score()},
                       {"sah_cost", sahCost(run.bvh)}};
  json["tasks"] = tasksJson(run.tasks, {2, 3});
  json["build_ms_task3"] = run.buildTask * 1e3;
  json["build_ms_embree"] = run.buildEmbree ? Json(*run.buildEmbree * 1e3) : Json(nullptr);
  json["build_ms_fast_collapse"] = run.buildWide * 1e3;
  json["fast_lane_occupancy"] = run.wide.laneOccupancy();
  json["fast_box_test"] = run.wide.usesAvx2() ? "avx2" : "baseline";
  json["triangles"] = run.scene.triangleCount();
  json["threads"] = run.threads;
  if (options.json) std::printf("%s\n", json.dump().c_str());
  return 0;
}

}  // namespace pathlab::bench
