#include "converge_bench.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>
#include <utility>
#include <vector>

#include "converge_curves.h"
#include "converge_strategies.h"
#include "linked_tasks.h"
#include "util/input_file.h"
#include "util/error.h"
#include "util/parallel.h"
#include "render/render.h"
#include "scene/scene_io.h"
#include "util/todo.h"

namespace pathlab::bench {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

std::string csvQuote(const std::string& text) {
  std::string out = "\"";
  for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

// The reference image's file name: the linked code's default strategy made
// it, so an image made by other code is never reused. All-reference builds
// keep the plain name.
std::string referenceFileName(const std::string& stem, int spp, const LinkedTasks& linked) {
  std::string name = stem + "-reference-" + std::to_string(spp) + "spp";
  std::string yours, unknown;
  for (int n = 1; n <= kTaskCount; ++n) {
    if (linked[n] == Code::Yours) yours += std::to_string(n);
    if (linked[n] == Code::Unknown) unknown += std::to_string(n);
  }
  if (!yours.empty()) name += "-yours" + yours;
  if (!unknown.empty()) name += "-unknown" + unknown;
  return name + ".exr";
}

// The converged reference image every curve is measured against.
struct Reference {
  Image image;
  fs::path path;
  std::string strategy;
  bool cached = false;
  double seconds = 0.0;  // to render it (0 when cached)
};

// Each strategy's numbers over its last points (medians of the last 3).
struct Summary {
  std::optional<double> efficiency, slope, errorPerSample, samplesPerSecond;
};

// One run of the bench: the scene, the strategies and what each step found.
struct ConvergeRun {
  ConvergeRun(const ConvergeOptions& given, Scene loaded) : options(given), scene(std::move(loaded)) {}
  const ConvergeOptions& options;
  Scene scene;
  std::string stem;  // the scene file's name, with any -r and -m: every output file's prefix
  LinkedTasks linked;
  int threads = 1;
  RenderOptions defaults;
  std::vector<Strategy> strategies;
  Scene probe;
  std::vector<Availability> availability;
  std::vector<std::vector<Point>> curves;
};

std::string number(std::optional<double> v) {
  std::ostringstream out;
  if (v)
    out << *v;
  else
    out << "nan";
  return out.str();
}

std::string brief(std::optional<double> v, const char* none) {
  char text[32];
  if (v)
    std::snprintf(text, sizeof text, "%.4g", *v);
  else
    std::snprintf(text, sizeof text, "%s", none);
  return std::string(text);
}

// The scene as the options change it. A changed resolution or depth is part
// of every file name (`variant`): a cached reference is only reused for the
// same picture.
Scene sceneOf(const ConvergeOptions& options, std::string& variant) {
  Scene scene = loadScene(options.scene);
  if (!options.resolution.empty()) {
    checkResolution(options.resolution[0], options.resolution[1], "-r");
    scene.render.width = options.resolution[0], scene.render.height = options.resolution[1];
    variant += "-" + std::to_string(scene.render.width) + "x" + std::to_string(scene.render.height);
  }
  if (options.maxDepth >= 0) {
    if (options.maxDepth > 1024) throw Error("-m: at most 1024, as in a scene file");
    scene.render.maxDepth = options.maxDepth;
    variant += "-m" + std::to_string(options.maxDepth);
  }
  return scene;
}

// The --strategies, each checked against the scene. Every render walks the
// tree as `pathlab` would with this build (its --accel default), so that the
// seconds here are a user's seconds.
void chooseStrategies(ConvergeRun& run) {
  std::stringstream list(run.options.strategies);
  for (std::string name; std::getline(list, name, ',');) run.strategies.push_back(strategy(name));
  for (const Strategy& s : run.strategies) checkStrategyFits("--strategies", s, run.scene, run.options.scene);
  checkStrategyFits("--reference-strategy", strategy(run.options.referenceStrategy), run.scene, run.options.scene);
  run.defaults.traversal = defaultTraversal(linkedTaskSummary());
  for (Strategy& s : run.strategies) s.options.traversal = run.defaults.traversal;
}

// Which strategies the linked code implements: probe each change first
// (cheap), so that nothing unavailable is timed or compared.
void probeStrategies(ConvergeRun& run) {
  run.probe = probeScene(run.scene);
  std::optional<Image> probeDefault;
  run.availability.assign(run.strategies.size(), Availability{});
  for (size_t i = 0; i < run.strategies.size(); ++i) {
    const Strategy& s = run.strategies[i];
    if (s.tasks.empty()) continue;  // the default strategy
    if (!probeDefault) probeDefault = probeImage(run.probe, run.defaults, run.threads);
    const bool same = identical(probeImage(run.probe, s.options, run.threads), *probeDefault);
    run.availability[i] = judge(s, run.scene, run.linked, same);
    if (run.availability[i].available) {
      std::printf("probe %-18s available: changes the image (%s%s)\n", s.name.c_str(),
                  s.framework ? "the framework's path tracer with the pieces of " : "",
                  describeTasks(run.linked, s.tasks).c_str());
      if (!run.availability[i].note.empty()) std::printf("  note: %s\n", run.availability[i].note.c_str());
    } else {
      std::printf("probe %-18s unavailable: %s\n", s.name.c_str(), run.availability[i].reason.c_str());
    }
  }
  if (probeDefault) {
    std::printf("(probe: %dx%d, %d spp, each strategy against the default, same seed, compared pixel for pixel)\n",
                run.probe.render.width, run.probe.render.height, kProbeSpp);
  }
}

// The converged reference image: the linked code's default (best) strategy,
// or --reference-strategy, another seed, cached in --out.
Reference referenceImage(const ConvergeRun& run) {
  const ConvergeOptions& options = run.options;
  Strategy referenceStrategy = strategy(options.referenceStrategy);
  referenceStrategy.options.traversal = run.defaults.traversal;
  Reference reference;
  reference.strategy = referenceStrategy.name;
  const std::string referenceStem =
      referenceStrategy.name == "reference" ? run.stem : run.stem + "-" + referenceStrategy.name;
  reference.path = fs::path(options.outDir) / referenceFileName(referenceStem, options.referenceSpp, run.linked);
  std::error_code missing;
  if (fs::exists(reference.path, missing)) {
    reference.image = readImage(reference.path.string());
    reference.cached = true;
    std::printf("reference image: %s (cached)\n", reference.path.string().c_str());
    return reference;
  }
  std::vector<int> tasks = {1, 2, 3, 4, 5, 6, 7};
  tasks.insert(tasks.end(), referenceStrategy.tasks.begin(), referenceStrategy.tasks.end());
  std::sort(tasks.begin(), tasks.end());
  tasks.erase(std::unique(tasks.begin(), tasks.end()), tasks.end());
  const std::string referenceTasks = describeTasks(run.linked, tasks);
  Scene high = run.scene;
  high.render.samplesPerPixel = options.referenceSpp;
  high.render.seed = 987654321;
  std::fprintf(stderr,
               "rendering the reference image once: %dx%d, %d spp, strategy %s (%s); it is cached in %s for "
               "later runs with the same --out\n",
               high.render.width, high.render.height, options.referenceSpp, referenceStrategy.name.c_str(),
               referenceTasks.c_str(), reference.path.string().c_str());
  RenderOptions render = referenceStrategy.options;
  render.threads = run.threads;
  render.progress = true;  // the bar shows itself only when stderr is a terminal
  RenderResult result = pathlab::render(high, render);
  writeImage(result.image, reference.path.string());
  reference.image = result.image;
  reference.seconds = result.stats.seconds;
  std::printf("reference image: %s, %d spp in %.1f s\n", reference.path.string().c_str(), options.referenceSpp,
              result.stats.seconds);
  return reference;
}

// Each available strategy at 1, 2, 4, ... spp until its budget is spent (and
// past it until the curve passes the last equal-time point): error against
// the reference and time, printed and written to STEM-converge.csv.
fs::path measureCurves(ConvergeRun& run, const Image& reference) {
  const ConvergeOptions& options = run.options;
  const fs::path csvPath = fs::path(options.outDir) / (run.stem + "-converge.csv");
  std::ofstream csv(csvPath);
  csv << "strategy,spp,seconds,rmse,relmse,efficiency,available,reason,samples_per_pixel,block_shift\n";
  run.curves.assign(run.strategies.size(), {});
  const double lastTime =
      options.equalTimes.empty() ? 0.0 : *std::max_element(options.equalTimes.begin(), options.equalTimes.end());
  for (size_t i = 0; i < run.strategies.size(); ++i) {
    Strategy s = run.strategies[i];
    const Availability& availability = run.availability[i];
    if (!availability.available) {
      csv << s.name << ",0,nan,nan,nan,nan,false," << csvQuote(availability.reason) << ",nan,nan\n";
      continue;
    }
    s.options.threads = run.threads;
    s.options.progress = false;
    std::vector<Point>& curve = run.curves[i];
    double spent = 0.0;
    auto more = [&] { return spent < options.budgetSeconds || curve.empty() || curve.back().seconds < lastTime; };
    for (int spp = 1; spp <= (1 << 16) && more(); spp *= 2) {
      Scene scene = run.scene;
      scene.render.samplesPerPixel = spp;
      scene.render.seed = 1;
      if (s.options.adaptive) {  // at most spp: batches of 16 (fewer below), from a sixteenth of it
        AdaptiveSettings& a = *s.options.adaptive;
        a.maxSpp = uint32_t(spp);
        a.batch = uint32_t(std::min(spp, 16));
        a.minSpp = std::max(a.batch, uint32_t(spp / 16) / a.batch * a.batch);
      }
      RenderResult result = pathlab::render(scene, s.options);
      const ImageError error = compareImages(result.image, reference);
      const double taken = double(result.stats.samples) / (double(scene.render.width) * double(scene.render.height));
      const Point point{spp, taken, result.stats.seconds, error.rmse, error.relMse,
                        efficiencyOf(error.relMse, result.stats.seconds), meanBlockShift(result.image, reference)};
      curve.push_back(point);
      spent += result.stats.seconds;
      csv << s.name << ',' << spp << ',' << point.seconds << ',' << point.rmse << ',' << point.relMse << ','
          << number(point.efficiency) << ",true," << csvQuote(availability.note) << ',' << taken << ',' << point.shift
          << '\n';
      char took[48] = "";  // an adaptive render takes fewer
      if (s.options.adaptive) std::snprintf(took, sizeof took, " (took %.1f)", taken);
      std::printf("%-18s %6d spp%s %8.3f s  RMSE %.5f  relMSE %.6f  shift %+.2f %%  efficiency %s\n", s.name.c_str(),
                  spp, took, point.seconds, point.rmse, point.relMse, 100.0 * point.shift,
                  brief(point.efficiency, "- (zero error)").c_str());
    }
  }
  csv.close();
  std::printf("wrote %s\n", csvPath.string().c_str());
  return csvPath;
}

// The plot: matplotlib (Debian's python3-matplotlib), no hand-made charts;
// it gets the measured rows only (an unavailable strategy has no curve).
void plotCurves(const ConvergeRun& run, const fs::path& csvPath) {
  const fs::path pngPath = fs::path(run.options.outDir) / (run.stem + "-converge.png");
  const fs::path plotCsvPath = fs::path(run.options.outDir) / (run.stem + "-converge.plot.csv");
  size_t measured = 0;
  {
    std::ofstream plotCsv(plotCsvPath);
    plotCsv << "strategy,spp,seconds,rmse,relmse,efficiency\n";
    for (size_t i = 0; i < run.strategies.size(); ++i) {
      for (const Point& p : run.curves[i]) {
        if (!p.efficiency) continue;  // zero error: nothing to draw on log axes
        plotCsv << run.strategies[i].name << ',' << p.samples << ',' << p.seconds << ',' << p.rmse << ',' << p.relMse
                << ',' << *p.efficiency << '\n';
        ++measured;
      }
    }
  }
  const std::string python = fs::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
  const std::string command = python + " " PATHLAB_SOURCE_DIR "/tools/plot-convergence.py '" + plotCsvPath.string() +
                              "' '" + pngPath.string() + "' '" + run.stem + ": error against time' > /dev/null";
  if (measured == 0) {
    std::fprintf(stderr, "no plot: no strategy ran with an error above zero\n");
  } else if (std::system(command.c_str()) != 0) {
    std::fprintf(stderr, "no plot: install python3-matplotlib, then run tools/plot-convergence.py %s %s\n",
                 csvPath.string().c_str(), pngPath.string().c_str());
  } else {
    std::printf("wrote %s\n", pngPath.string().c_str());
  }
  fs::remove(plotCsvPath);
}

// The median of the values `of` gives for a curve's last 3 points (none: nothing).
template <typename Of>
std::optional<double> medianOfLast3(const std::vector<Point>& curve, Of of) {
  std::vector<double> values;
  for (size_t p = curve.size() >= 3 ? curve.size() - 3 : 0; p < curve.size(); ++p) {
    if (const std::optional<double> v = of(curve[p])) values.push_back(*v);
  }
  std::sort(values.begin(), values.end());
  if (values.empty()) return std::nullopt;
  return values[values.size() / 2];
}

// Efficiency = 1 / (relMSE x time): for unbiased estimators it settles to a
// constant, and the ratio of two is the ratio of times to the same error.
// relMSE x spp is the error per sample (time-free: comparable across
// machines), samples/s the speed: efficiency is their ratio, so a peer
// comparison can be redone on any machine from these two. Printed as a table.
std::vector<Summary> summarise(const ConvergeRun& run) {
  const double pixels = double(run.scene.render.width) * double(run.scene.render.height);
  std::vector<Summary> summaries(run.strategies.size());
  std::printf("%-18s %12s %7s %12s %11s  %s\n", "strategy", "efficiency", "slope", "relMSE*spp", "samples/s",
              "(medians of the last 3 points; slope of log relMSE against log spp, -1 for plain Monte Carlo; whose "
              "code ran)");
  for (size_t i = 0; i < run.strategies.size(); ++i) {
    const Strategy& s = run.strategies[i];
    if (!run.availability[i].available) {
      std::printf("%-18s %12s %7s %12s %11s  %s\n", s.name.c_str(), "unavailable", "", "", "",
                  run.availability[i].reason.c_str());
      continue;
    }
    const std::vector<Point>& curve = run.curves[i];
    Summary& summary = summaries[i];
    summary.efficiency = medianOfLast3(curve, [](const Point& p) { return p.efficiency; });
    summary.errorPerSample = medianOfLast3(curve, [](const Point& p) -> std::optional<double> {
      if (p.relMse > 0.0 && std::isfinite(p.relMse)) return p.relMse * p.samples;
      return std::nullopt;
    });
    summary.samplesPerSecond = medianOfLast3(curve, [&](const Point& p) -> std::optional<double> {
      if (p.seconds > 0.0) return p.samples * pixels / p.seconds;
      return std::nullopt;
    });
    summary.slope = convergenceSlope(curve);
    char slopeText[32] = "-";
    if (summary.slope) std::snprintf(slopeText, sizeof slopeText, "%.2f", *summary.slope);
    const std::string who = s.tasks.empty() ? "default strategy: " + describeTasks(run.linked, {4, 5, 7})
                            : s.framework   ? "framework tracer, pieces of " + describeTasks(run.linked, s.tasks)
                                            : describeTasks(run.linked, s.tasks);
    char perSampleText[32] = "-", rateText[32] = "-";
    if (summary.errorPerSample) std::snprintf(perSampleText, sizeof perSampleText, "%.4g", *summary.errorPerSample);
    if (summary.samplesPerSecond) std::snprintf(rateText, sizeof rateText, "%.3gM", *summary.samplesPerSecond / 1e6);
    std::printf("%-18s %12s %7s %12s %11s  %s\n", s.name.c_str(), brief(summary.efficiency, "-").c_str(), slopeText,
                perSampleText, rateText, who.c_str());
  }
  return summaries;
}

// The first strategy against the second, in time to the same relMSE ("" with
// fewer than two), printed.
std::string compareFirstTwo(const ConvergeRun& run, const std::vector<Summary>& summaries) {
  if (run.strategies.size() < 2) return "";
  const std::string &first = run.strategies[0].name, &second = run.strategies[1].name;
  std::string comparison;
  if (!run.availability[0].available || !run.availability[1].available) {
    comparison = "no comparison of " + first + " with " + second + ": " +
                 (run.availability[0].available ? second : first) + " is unavailable";
  } else if (!summaries[0].efficiency || !summaries[1].efficiency) {
    comparison = "no comparison of " + first + " with " + second + ": zero error (is the image black?)";
  } else {
    char line[256];
    const double ratio = *summaries[0].efficiency / *summaries[1].efficiency;
    std::snprintf(line, sizeof line, "%s needs %.1fx less time than %s for the same relMSE",
                  (ratio >= 1.0 ? first : second).c_str(), ratio >= 1.0 ? ratio : 1.0 / ratio,
                  (ratio >= 1.0 ? second : first).c_str());
    comparison = line;
  }
  std::printf("%s\n", comparison.c_str());
  return comparison;
}

// Equal time: each strategy's relMSE at the same render time; the ratio of
// the first's to another's is that one's efficiency over the first's there.
// The shift beside it says how much of that error is bias. Printed, and
// returned for the JSON.
Json compareAtEqualTimes(const ConvergeRun& run) {
  Json equalTime = Json::array();
  for (double seconds : run.options.equalTimes) {
    std::printf("at %g s:", seconds);
    Json entry = {{"seconds", seconds}};
    Json errors = Json::object(), shifts = Json::object();
    std::optional<AtTime> first;
    for (size_t i = 0; i < run.strategies.size(); ++i) {
      const std::string& name = run.strategies[i].name;
      std::optional<AtTime> at;
      if (run.availability[i].available) at = curveAtTime(run.curves[i], seconds);
      if (i == 0) first = at;
      errors[name] = at ? Json(at->relMse) : Json(nullptr);
      shifts[name] = at ? Json(at->shift) : Json(nullptr);
      if (!at) {
        std::printf("  %s relMSE (not reached)", name.c_str());
        continue;
      }
      std::printf("  %s relMSE %.4g", name.c_str(), at->relMse);
      if (i > 0 && first) {
        std::printf(" (efficiency %.2fx %s's)", first->relMse / at->relMse, run.strategies[0].name.c_str());
      }
      std::printf(" shift %+.2f %%", 100.0 * at->shift);
    }
    std::printf("\n");
    entry["relmse"] = errors;
    entry["block_shift"] = shifts;
    equalTime.push_back(entry);
  }
  return equalTime;
}

// A note when the linked code reached a TODO: its numbers say nothing yet.
void noteTodosReached() {
  std::string reached;
  std::vector<std::string> tags;  // each TODO once (a tag may mark several sites)
  for (const TodoReached& todo : todosReached()) {
    if (std::find(tags.begin(), tags.end(), todo.tag) == tags.end()) tags.push_back(todo.tag);
  }
  for (const std::string& tag : tags) reached += (reached.empty() ? "" : ", ") + tag;
  if (!reached.empty()) {
    std::printf("note: the linked code reached TODO %s: unfinished task code renders neutral values there "
                "(black), so its errors and efficiencies say nothing yet\n", reached.c_str());
  }
}

Json strategyJson(const ConvergeRun& run, size_t i, const Summary& summary) {
  const Strategy& s = run.strategies[i];
  Json tasks = Json::object();
  for (int n : s.tasks) tasks[std::to_string(n)] = codeName(run.linked[n]);
  Json points = Json::array();
  for (const Point& p : run.curves[i]) {
    points.push_back({{"spp", p.spp},
                      {"samples_per_pixel", p.samples},
                      {"seconds", p.seconds},
                      {"rmse", p.rmse},
                      {"relmse", p.relMse},
                      {"efficiency", p.efficiency ? Json(*p.efficiency) : Json(nullptr)},
                      {"block_shift", p.shift}});
  }
  auto value = [](const std::optional<double>& v) { return v ? Json(*v) : Json(nullptr); };
  Json entry = {{"name", s.name},
                {"default", s.tasks.empty()},
                {"relies_on", tasks},
                {"available", run.availability[i].available},
                {"points", points},
                {"efficiency", value(summary.efficiency)},
                {"slope", value(summary.slope)},
                {"relmse_times_spp", value(summary.errorPerSample)},
                {"samples_per_second", value(summary.samplesPerSecond)}};
  if (!run.availability[i].available) entry["reason"] = run.availability[i].reason;
  if (!run.availability[i].note.empty()) entry["note"] = run.availability[i].note;
  return entry;
}

// --json: everything above as one object, the last line of the output.
void printJson(const ConvergeRun& run, const Reference& reference, const std::vector<Summary>& summaries,
               const std::string& comparison, const Json& equalTime) {
  Json json;
  json["scene"] = run.options.scene;
  json["tasks"] = allTasksJson(run.linked);
  json["tasks_recorded"] = run.linked.recorded;
  json["reference_image"] = {{"path", reference.path.string()},
                             {"spp", run.options.referenceSpp},
                             {"strategy", reference.strategy},
                             {"cached", reference.cached},
                             {"seconds", reference.cached ? Json(nullptr) : Json(reference.seconds)}};
  json["probe"] = {{"width", run.probe.render.width}, {"height", run.probe.render.height}, {"spp", kProbeSpp}};
  Json todos = Json::array();
  for (const TodoReached& todo : todosReached()) todos.push_back(todo.tag);
  json["todos_reached"] = todos;
  Json entries = Json::array();
  for (size_t i = 0; i < run.strategies.size(); ++i) entries.push_back(strategyJson(run, i, summaries[i]));
  json["strategies"] = entries;
  json["equal_time"] = equalTime;
  json["comparison"] = comparison.empty() ? Json(nullptr) : Json(comparison);
  std::printf("%s\n", json.dump().c_str());
}

}  // namespace

int runConvergeBench(const ConvergeOptions& options) {
  // Line by line, so that stdout and the notes and progress on stderr
  // interleave in order when both go to one log.
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  std::string variant;
  ConvergeRun run(options, sceneOf(options, variant));
  run.threads = options.threads > 0 ? options.threads : defaultThreadCount();
  createFolders(options.outDir);
  run.stem = fs::path(options.scene).stem().string() + variant;
  run.linked = linkedTasks();
  std::printf("code: %s\n", describeAllTasks(run.linked).c_str());

  chooseStrategies(run);
  probeStrategies(run);
  const Reference reference = referenceImage(run);
  const fs::path csvPath = measureCurves(run, reference.image);
  plotCurves(run, csvPath);
  const std::vector<Summary> summaries = summarise(run);
  const std::string comparison = compareFirstTwo(run, summaries);
  const Json equalTime = compareAtEqualTimes(run);
  noteTodosReached();
  if (options.json) printJson(run, reference, summaries, comparison, equalTime);
  return 0;
}

}  // namespace pathlab::bench
