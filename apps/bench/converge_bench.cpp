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

}  // namespace

int runConvergeBench(const ConvergeOptions& options) {
  // Line by line, so that stdout and the notes and progress on stderr
  // interleave in order when both go to one log.
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  Scene scene = loadScene(options.scene);
  // A changed resolution or depth is part of every file name: a cached
  // reference is only reused for the same picture.
  std::string variant;
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
  const int threads = options.threads > 0 ? options.threads : defaultThreadCount();
  createFolders(options.outDir);
  const std::string stem = fs::path(options.scene).stem().string() + variant;
  const LinkedTasks linked = linkedTasks();
  const std::string code = describeAllTasks(linked);
  std::printf("code: %s\n", code.c_str());

  std::vector<Strategy> strategies;
  std::stringstream list(options.strategies);
  for (std::string name; std::getline(list, name, ',');) strategies.push_back(strategy(name));
  for (const Strategy& s : strategies) checkStrategyFits("--strategies", s, scene, options.scene);
  checkStrategyFits("--reference-strategy", strategy(options.referenceStrategy), scene, options.scene);
  // Every render walks the tree as `pathlab` would with this build (its
  // --accel default), so that the seconds here are a user's seconds.
  RenderOptions defaults;
  defaults.traversal = defaultTraversal(linkedTaskSummary());
  for (Strategy& s : strategies) s.options.traversal = defaults.traversal;

  // Which strategies the linked code implements: probe each change first
  // (cheap), so that nothing unavailable is timed or compared.
  const Scene probe = probeScene(scene);
  std::optional<Image> probeDefault;
  std::vector<Availability> availability(strategies.size());
  for (size_t i = 0; i < strategies.size(); ++i) {
    const Strategy& s = strategies[i];
    if (s.tasks.empty()) continue;  // the default strategy
    if (!probeDefault) probeDefault = probeImage(probe, defaults, threads);
    const bool same = identical(probeImage(probe, s.options, threads), *probeDefault);
    availability[i] = judge(s, scene, linked, same);
    if (availability[i].available) {
      std::printf("probe %-18s available: changes the image (%s%s)\n", s.name.c_str(),
                  s.framework ? "the framework's path tracer with the pieces of " : "",
                  describeTasks(linked, s.tasks).c_str());
      if (!availability[i].note.empty()) std::printf("  note: %s\n", availability[i].note.c_str());
    } else {
      std::printf("probe %-18s unavailable: %s\n", s.name.c_str(), availability[i].reason.c_str());
    }
  }
  if (probeDefault) {
    std::printf("(probe: %dx%d, %d spp, each strategy against the default, same seed, compared pixel for pixel)\n",
                probe.render.width, probe.render.height, kProbeSpp);
  }

  // The converged reference image: the linked code's default (best)
  // strategy, another seed, cached.
  Strategy referenceStrategy = strategy(options.referenceStrategy);
  referenceStrategy.options.traversal = defaults.traversal;
  const std::string referenceStem =
      referenceStrategy.name == "reference" ? stem : stem + "-" + referenceStrategy.name;
  const fs::path referencePath =
      fs::path(options.outDir) / referenceFileName(referenceStem, options.referenceSpp, linked);
  Image reference;
  bool cached = false;
  double referenceSeconds = 0.0;
  std::error_code missing;
  if (fs::exists(referencePath, missing)) {
    reference = readImage(referencePath.string());
    cached = true;
    std::printf("reference image: %s (cached)\n", referencePath.string().c_str());
  } else {
    std::vector<int> tasks = {1, 2, 3, 4, 5, 6, 7};
    tasks.insert(tasks.end(), referenceStrategy.tasks.begin(), referenceStrategy.tasks.end());
    std::sort(tasks.begin(), tasks.end());
    tasks.erase(std::unique(tasks.begin(), tasks.end()), tasks.end());
    const std::string referenceTasks = describeTasks(linked, tasks);
    Scene high = scene;
    high.render.samplesPerPixel = options.referenceSpp;
    high.render.seed = 987654321;
    std::fprintf(stderr,
                 "rendering the reference image once: %dx%d, %d spp, strategy %s (%s); it is cached in %s for "
                 "later runs with the same --out\n",
                 high.render.width, high.render.height, options.referenceSpp, referenceStrategy.name.c_str(),
                 referenceTasks.c_str(),
                 referencePath.string().c_str());
    RenderOptions render = referenceStrategy.options;
    render.threads = threads;
    render.progress = true;  // the bar shows itself only when stderr is a terminal
    RenderResult result = pathlab::render(high, render);
    writeImage(result.image, referencePath.string());
    reference = result.image;
    referenceSeconds = result.stats.seconds;
    std::printf("reference image: %s, %d spp in %.1f s\n", referencePath.string().c_str(), options.referenceSpp,
                result.stats.seconds);
  }

  const fs::path csvPath = fs::path(options.outDir) / (stem + "-converge.csv");
  std::ofstream csv(csvPath);
  csv << "strategy,spp,seconds,rmse,relmse,efficiency,available,reason,samples_per_pixel,block_shift\n";
  auto number = [](std::optional<double> v) {
    std::ostringstream out;
    if (v) out << *v;
    else out << "nan";
    return out.str();
  };
  auto brief = [](std::optional<double> v, const char* none) {
    char text[32];
    if (v) std::snprintf(text, sizeof text, "%.4g", *v);
    else std::snprintf(text, sizeof text, "%s", none);
    return std::string(text);
  };
  std::vector<std::vector<Point>> curves(strategies.size());
  for (size_t i = 0; i < strategies.size(); ++i) {
    Strategy s = strategies[i];
    if (!availability[i].available) {
      csv << s.name << ",0,nan,nan,nan,nan,false," << csvQuote(availability[i].reason) << ",nan,nan\n";
      continue;
    }
    s.options.threads = threads;
    s.options.progress = false;
    double spent = 0.0;
    // Past the budget until the curve passes the last equal-time point.
    const double lastTime =
        options.equalTimes.empty() ? 0.0 : *std::max_element(options.equalTimes.begin(), options.equalTimes.end());
    auto more = [&] { return spent < options.budgetSeconds || curves[i].empty() || curves[i].back().seconds < lastTime; };
    for (int spp = 1; spp <= (1 << 16) && more(); spp *= 2) {
      Scene run = scene;
      run.render.samplesPerPixel = spp;
      run.render.seed = 1;
      if (s.options.adaptive) {  // at most spp: batches of 16 (fewer below), from a sixteenth of it
        AdaptiveSettings& a = *s.options.adaptive;
        a.maxSpp = uint32_t(spp);
        a.batch = uint32_t(std::min(spp, 16));
        a.minSpp = std::max(a.batch, uint32_t(spp / 16) / a.batch * a.batch);
      }
      RenderResult result = pathlab::render(run, s.options);
      const ImageError error = compareImages(result.image, reference);
      const double taken = double(result.stats.samples) / (double(run.render.width) * double(run.render.height));
      const Point point{spp, taken, result.stats.seconds, error.rmse, error.relMse,
                        efficiencyOf(error.relMse, result.stats.seconds), meanBlockShift(result.image, reference)};
      curves[i].push_back(point);
      spent += result.stats.seconds;
      csv << s.name << ',' << spp << ',' << point.seconds << ',' << point.rmse << ',' << point.relMse << ','
          << number(point.efficiency) << ",true," << csvQuote(availability[i].note) << ',' << taken << ','
          << point.shift << '\n';
      char took[48] = "";  // an adaptive render takes fewer
      if (s.options.adaptive) std::snprintf(took, sizeof took, " (took %.1f)", taken);
      std::printf("%-18s %6d spp%s %8.3f s  RMSE %.5f  relMSE %.6f  shift %+.2f %%  efficiency %s\n", s.name.c_str(),
                  spp, took, point.seconds, point.rmse, point.relMse, 100.0 * point.shift,
                  brief(point.efficiency, "- (zero error)").c_str());
    }
  }
  csv.close();
  std::printf("wrote %s\n", csvPath.string().c_str());
  // The plot: matplotlib (Debian's python3-matplotlib), no hand-made charts;
  // it gets the measured rows only (an unavailable strategy has no curve).
  const fs::path pngPath = fs::path(options.outDir) / (stem + "-converge.png");
  const fs::path plotCsvPath = fs::path(options.outDir) / (stem + "-converge.plot.csv");
  size_t measured = 0;
  {
    std::ofstream plotCsv(plotCsvPath);
    plotCsv << "strategy,spp,seconds,rmse,relmse,efficiency\n";
    for (size_t i = 0; i < strategies.size(); ++i) {
      for (const Point& p : curves[i]) {
        if (!p.efficiency) continue;  // zero error: nothing to draw on log axes
        plotCsv << strategies[i].name << ',' << p.samples << ',' << p.seconds << ',' << p.rmse << ',' << p.relMse << ','
                << *p.efficiency << '\n';
        ++measured;
      }
    }
  }
  const std::string python = fs::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
  const std::string command = python + " " PATHLAB_SOURCE_DIR "/tools/plot-convergence.py '" + plotCsvPath.string() +
                              "' '" + pngPath.string() + "' '" + stem + ": error against time' > /dev/null";
  if (measured == 0) {
    std::fprintf(stderr, "no plot: no strategy ran with an error above zero\n");
  } else if (std::system(command.c_str()) != 0) {
    std::fprintf(stderr, "no plot: install python3-matplotlib, then run tools/plot-convergence.py %s %s\n",
                 csvPath.string().c_str(), pngPath.string().c_str());
  } else {
    std::printf("wrote %s\n", pngPath.string().c_str());
  }
  fs::remove(plotCsvPath);

  // Efficiency = 1 / (relMSE x time): for unbiased estimators it settles to a
  // constant, and the ratio of two is the ratio of times to the same error.
  // relMSE x spp is the error per sample (time-free: comparable across machines), samples/s the speed:
  // efficiency is their ratio, so a peer comparison can be redone on any machine from these two.
  const double pixels = double(scene.render.width) * double(scene.render.height);
  std::vector<std::optional<double>> efficiency(strategies.size()), slope(strategies.size()),
      errorPerSample(strategies.size()), samplesPerSecond(strategies.size());
  std::printf("%-18s %12s %7s %12s %11s  %s\n", "strategy", "efficiency", "slope", "relMSE*spp", "samples/s",
              "(medians of the last 3 points; slope of log relMSE against log spp, -1 for plain Monte Carlo; whose "
              "code ran)");
  for (size_t i = 0; i < strategies.size(); ++i) {
    const Strategy& s = strategies[i];
    if (!availability[i].available) {
      std::printf("%-18s %12s %7s %12s %11s  %s\n", s.name.c_str(), "unavailable", "", "", "",
                  availability[i].reason.c_str());
      continue;
    }
    std::vector<double> last;
    for (size_t p = curves[i].size() >= 3 ? curves[i].size() - 3 : 0; p < curves[i].size(); ++p) {
      if (curves[i][p].efficiency) last.push_back(*curves[i][p].efficiency);
    }
    std::sort(last.begin(), last.end());
    if (!last.empty()) efficiency[i] = last[last.size() / 2];
    std::vector<double> perSample, rate;
    for (size_t p = curves[i].size() >= 3 ? curves[i].size() - 3 : 0; p < curves[i].size(); ++p) {
      const Point& point = curves[i][p];
      if (point.relMse > 0.0 && std::isfinite(point.relMse)) perSample.push_back(point.relMse * point.samples);
      if (point.seconds > 0.0) rate.push_back(point.samples * pixels / point.seconds);
    }
    std::sort(perSample.begin(), perSample.end()), std::sort(rate.begin(), rate.end());
    if (!perSample.empty()) errorPerSample[i] = perSample[perSample.size() / 2];
    if (!rate.empty()) samplesPerSecond[i] = rate[rate.size() / 2];
    slope[i] = convergenceSlope(curves[i]);
    char slopeText[32] = "-";
    if (slope[i]) std::snprintf(slopeText, sizeof slopeText, "%.2f", *slope[i]);
    const std::string who = s.tasks.empty() ? "default strategy: " + describeTasks(linked, {4, 5, 7})
                            : s.framework     ? "framework tracer, pieces of " + describeTasks(linked, s.tasks)
                                              : describeTasks(linked, s.tasks);
    char perSampleText[32] = "-", rateText[32] = "-";
    if (errorPerSample[i]) std::snprintf(perSampleText, sizeof perSampleText, "%.4g", *errorPerSample[i]);
    if (samplesPerSecond[i]) std::snprintf(rateText, sizeof rateText, "%.3gM", *samplesPerSecond[i] / 1e6);
    std::printf("%-18s %12s %7s %12s %11s  %s\n", s.name.c_str(), brief(efficiency[i], "-").c_str(), slopeText,
                perSampleText, rateText, who.c_str());
  }
  std::string comparison;
  if (strategies.size() >= 2) {
    const std::string &first = strategies[0].name, &second = strategies[1].name;
    if (!availability[0].available || !availability[1].available) {
      comparison = "no comparison of " + first + " with " + second + ": " +
                   (availability[0].available ? second : first) + " is unavailable";
    } else if (!efficiency[0] || !efficiency[1]) {
      comparison = "no comparison of " + first + " with " + second + ": zero error (is the image black?)";
    } else {
      char line[256];
      const double ratio = *efficiency[0] / *efficiency[1];
      std::snprintf(line, sizeof line, "%s needs %.1fx less time than %s for the same relMSE",
                    (ratio >= 1.0 ? first : second).c_str(), ratio >= 1.0 ? ratio : 1.0 / ratio,
                    (ratio >= 1.0 ? second : first).c_str());
      comparison = line;
    }
    std::printf("%s\n", comparison.c_str());
  }
  // Equal time: each strategy's relMSE at the same render time; the ratio of
  // the first's to another's is that one's efficiency over the first's there.
  // The shift beside it says how much of that error is bias.
  Json equalTime = Json::array();
  for (double seconds : options.equalTimes) {
    std::printf("at %g s:", seconds);
    Json entry = {{"seconds", seconds}};
    Json errors = Json::object(), shifts = Json::object();
    std::optional<AtTime> first;
    for (size_t i = 0; i < strategies.size(); ++i) {
      std::optional<AtTime> at;
      if (availability[i].available) at = curveAtTime(curves[i], seconds);
      if (i == 0) first = at;
      errors[strategies[i].name] = at ? Json(at->relMse) : Json(nullptr);
      shifts[strategies[i].name] = at ? Json(at->shift) : Json(nullptr);
      if (!at) {
        std::printf("  %s relMSE (not reached)", strategies[i].name.c_str());
        continue;
      }
      std::printf("  %s relMSE %.4g", strategies[i].name.c_str(), at->relMse);
      if (i > 0 && first) std::printf(" (efficiency %.2fx %s's)", first->relMse / at->relMse, strategies[0].name.c_str());
      std::printf(" shift %+.2f %%", 100.0 * at->shift);
    }
    std::printf("\n");
    entry["relmse"] = errors;
    entry["block_shift"] = shifts;
    equalTime.push_back(entry);
  }

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

  if (options.json) {
    Json json;
    json["scene"] = options.scene;
    json["tasks"] = allTasksJson(linked);
    json["tasks_recorded"] = linked.recorded;
    json["reference_image"] = {{"path", referencePath.string()},
                               {"spp", options.referenceSpp},
                               {"strategy", referenceStrategy.name},
                               {"cached", cached},
                               {"seconds", cached ? Json(nullptr) : Json(referenceSeconds)}};
    json["probe"] = {{"width", probe.render.width}, {"height", probe.render.height}, {"spp", kProbeSpp}};
    Json todos = Json::array();
    for (const TodoReached& todo : todosReached()) todos.push_back(todo.tag);
    json["todos_reached"] = todos;
    Json entries = Json::array();
    for (size_t i = 0; i < strategies.size(); ++i) {
      const Strategy& s = strategies[i];
      Json tasks = Json::object();
      for (int n : s.tasks) tasks[std::to_string(n)] = codeName(linked[n]);
      Json points = Json::array();
      for (const Point& p : curves[i]) {
        points.push_back({{"spp", p.spp}, {"samples_per_pixel", p.samples}, {"seconds", p.seconds}, {"rmse", p.rmse}, {"relmse", p.relMse},
                          {"efficiency", p.efficiency ? Json(*p.efficiency) : Json(nullptr)}, {"block_shift", p.shift}});
      }
      Json entry = {{"name", s.name},
                    {"default", s.tasks.empty()},
                    {"relies_on", tasks},
                    {"available", availability[i].available},
                    {"points", points},
                    {"efficiency", efficiency[i] ? Json(*efficiency[i]) : Json(nullptr)},
                    {"slope", slope[i] ? Json(*slope[i]) : Json(nullptr)},
                    {"relmse_times_spp", errorPerSample[i] ? Json(*errorPerSample[i]) : Json(nullptr)},
                    {"samples_per_second", samplesPerSecond[i] ? Json(*samplesPerSecond[i]) : Json(nullptr)}};
      if (!availability[i].available) entry["reason"] = availability[i].reason;
      if (!availability[i].note.empty()) entry["note"] = availability[i].note;
      entries.push_back(entry);
    }
    json["strategies"] = entries;
    json["equal_time"] = equalTime;
    json["comparison"] = comparison.empty() ? Json(nullptr) : Json(comparison);
    std::printf("%s\n", json.dump().c_str());
  }
  return 0;
}

}  // namespace pathlab::bench
