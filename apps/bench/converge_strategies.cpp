#include "converge_strategies.h"

#include <algorithm>
#include <cmath>

#include "util/error.h"
#include "util/todo.h"

namespace pathlab::bench {

// Each strategy changes one thing from the default (the course's recipe).
// The sampling strategies are the framework's path tracer, assembled from
// the tasks' pieces (BRDF, ray offset, light directions, diffuse sampling,
// lobes): the student's tracePath follows the recipe only.
Strategy strategy(const std::string& name) {
  Strategy s{name, {}, {}, {}, false};
  auto frameworkStrategy = [&](SamplingStrategy change, const std::string& what) {
    s.options.strategy = change;
    s.tasks = {4, 5};
    s.change = what + " (the framework's path tracer, with task 4 and 5's pieces)";
    s.framework = true;
  };
  if (name == "reference" || name == "env-importance" || name == "cosine" || name == "nee" || name == "rr") {
  } else if (name == "env-uniform") {
    s.options.environmentSampling = EnvironmentSampling::Uniform;
    s.tasks = {7};
    s.change = "uniform environment sampling (sampleUniformSphere instead of sampleEnvironment)";
  } else if (name == "uniform-hemisphere") {
    frameworkStrategy({.cosineSampling = false}, "uniform hemisphere sampling of diffuse bounces");
  } else if (name == "no-nee") {
    frameworkStrategy({.lightSampling = false}, "BSDF sampling only, no next-event estimation");
  } else if (name == "no-rr") {
    frameworkStrategy({.russianRoulette = false}, "no Russian roulette");
  } else if (name == "independent") {
    s.options.sampler = SampleSequence::Independent;
    s.tasks = {4, 5};
    s.change = "independent samples instead of Owen-scrambled Sobol ones (the framework's sampler, --sampler independent)";
  } else if (name == "stratified") {
    s.options.sampler = SampleSequence::Stratified;
    s.tasks = {4, 5};
    s.change = "jittered strata instead of Owen-scrambled Sobol points (the framework's sampler, --sampler stratified)";
  } else if (const std::optional<Integrator> mis = integratorFromName(name == "mis-power" ? "mis" : name);
             mis && misEstimatorOf(*mis)) {
    // Task 9's tracePathMis, by the integrator's name (render.h's kIntegrators; "mis-power" is "mis"):
    // one light sample per vertex, the BSDF sample, or both weighted.
    s.options.integrator = *mis;
    s.tasks = {9};
    s.change = *mis == Integrator::LightSampling   ? "task 9's path tracer, one light sample per vertex alone"
               : *mis == Integrator::BsdfSampling ? "task 9's path tracer, the BSDF sample alone"
               : *mis == Integrator::MisBalance   ? "task 9's path tracer, MIS of light and BSDF samples, balance heuristic"
                                                  : "task 9's path tracer, MIS of light and BSDF samples, power heuristic";
  } else if (name == "adaptive" || name.rfind("adaptive-", 0) == 0) {
    // Task 11: each pixel stops once its 95 % interval is within the
    // tolerance (adaptive-TOL; 0.2 by default: on CBspheres.dae it pays at
    // 30 s and at 120 s, docs/performance-convergence.md); the curve's spp is each
    // render's maximum, a sixteenth of it the minimum.
    AdaptiveSettings adaptive;
    adaptive.tolerance = 0.2;
    if (name != "adaptive") {
      const std::string text = name.substr(9);
      char* end = nullptr;
      adaptive.tolerance = std::strtod(text.c_str(), &end);
      if (text.empty() || *end != '\0' || !(adaptive.tolerance > 0.0 && adaptive.tolerance <= 10.0)) {
        throw Error("--strategies: \"" + name + "\": expected adaptive-TOLERANCE with a tolerance in (0, 10]");
      }
    }
    s.options.adaptive = adaptive;
    s.tasks = {11};
    char what[160];
    std::snprintf(what, sizeof what, "task 11's adaptive sampling, tolerance %g (spp: the maximum; the minimum "
                  "a sixteenth of it, batches of 16)", adaptive.tolerance);
    s.change = what;
  } else {
    std::string names;
    for (const char* known : kStrategyNames) names += std::string(known) + ", ";
    throw Error("--strategies: unknown strategy \"" + name + "\" (" + names + "adaptive-TOL)");
  }
  return s;
}

void checkStrategyFits(const char* flag, const Strategy& s, const Scene& scene, const std::string& sceneName) {
  if (mediaProblem(scene, s.options).empty()) return;
  std::string fitting;
  for (const char* name : kStrategyNames) {
    if (mediaProblem(scene, strategy(name).options).empty()) fitting += std::string(fitting.empty() ? "" : ", ") + name;
  }
  throw Error(std::string(flag) + " " + s.name + ": " + sceneName + " has media, which only task 12's path tracer "
              "renders, with its own sampling (the strategies that take it: " + fitting + ")");
}

Scene probeScene(const Scene& scene) {
  Scene probe = scene;
  const int width = std::min(scene.render.width, kProbeWidth);
  probe.render.height = std::max(1, int(std::lround(double(scene.render.height) * width / scene.render.width)));
  probe.render.width = width;
  probe.render.samplesPerPixel = kProbeSpp;
  probe.render.seed = 1;
  return probe;
}

Image probeImage(const Scene& probe, RenderOptions options, int threads) {
  options.threads = threads;
  options.progress = false;
  if (options.adaptive) {  // adaptive: batches of 2 from 2 samples, so that pixels can stop before kProbeSpp
    options.adaptive->maxSpp = kProbeSpp;
    options.adaptive->batch = options.adaptive->minSpp = 2;
  }
  return pathlab::render(probe, options).image;
}

bool identical(const Image& a, const Image& b) {
  if (a.width != b.width || a.height != b.height) return false;
  for (size_t i = 0; i < a.pixels.size(); ++i) {
    if (a.pixels[i] != b.pixels[i]) return false;
  }
  return true;
}

namespace {

// "T5.2, T5.1": the TODOs of task n reached so far (its code is a stub there).
std::string todosOfTask(int task) {
  std::string out;
  const std::string prefix = std::string("T").append(std::to_string(task)).append(".");  // not "T" + ...: GCC 12's -Wrestrict misfires
  for (const TodoReached& todo : todosReached()) {
    if (todo.tag.rfind(prefix, 0) != 0 || out.find(todo.tag) != std::string::npos) continue;
    if (!out.empty()) out += ", ";
    out += todo.tag;
  }
  return out;
}

std::string joinTasks(const std::vector<int>& tasks) {
  std::string out;
  for (int n : tasks) out += (out.empty() ? "" : " and ") + std::to_string(n);
  return out;
}

}  // namespace

Availability judge(const Strategy& s, const Scene& scene, const LinkedTasks& linked, bool identicalToDefault) {
  Availability a;
  std::vector<int> yours, reference, unknown;
  for (int n : s.tasks) {
    (linked[n] == Code::Yours ? yours : linked[n] == Code::Reference ? reference : unknown).push_back(n);
  }
  if (!identicalToDefault) {
    if (!s.framework && !yours.empty() && !reference.empty()) {
      a.note = "combines your task " + joinTasks(yours) + " with the reference's task " + joinTasks(reference) +
               ": unbiased only if both apply " + s.change;
    }
    return a;
  }
  a.available = false;
  const std::string probe = "a probe render with it is identical to the default";
  // Causes in the scene first: there the reference would not do more.
  std::string sceneCause;
  if (s.name == "env-uniform" && (!scene.environment || scene.environment->image.pixels.empty())) {
    sceneCause = "it has no environment map";
  } else if (s.name == "no-rr" && scene.render.maxDepth < 3) {
    sceneCause = "max_depth " + std::to_string(scene.render.maxDepth) + " ends paths before Russian roulette starts";
  }
  if (!sceneCause.empty()) {
    a.reason = "no effect on this scene (" + sceneCause + "; " + probe + ")";
  } else if (!yours.empty()) {
    a.reason = (s.framework ? s.change + " changes nothing with your task " + joinTasks(yours)
                            : "your task " + joinTasks(yours) + " ignores " + s.change) +
               " (" + probe;
    for (int n : yours) {
      const std::string todos = todosOfTask(n);
      if (!todos.empty()) a.reason += "; your task " + std::to_string(n) + " reached TODO " + todos;
    }
    a.reason += ")";
  } else if (!unknown.empty()) {
    a.reason = "with the linked task " + joinTasks(unknown) + " (whose code this binary does not record), " +
               s.change + " changes nothing (" + probe + ")";
  } else {
    a.reason = "no effect on this scene (" + probe + ")";
  }
  return a;
}

}  // namespace pathlab::bench
