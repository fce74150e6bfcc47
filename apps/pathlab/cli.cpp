#include "cli.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <thread>

#include "debug/debug_views.h"
#include "debug/draw.h"
#include "lab_cli.h"
#include "render/render.h"
#include "scene/scene_io.h"
#include "task_summary.h"
#include "util/error.h"
#include "util/output_file.h"
#include "util/platform.h"
#include "util/progress.h"

namespace pathlab {
namespace {

struct RenderArgs {
  std::string scene;
  std::optional<int> threads;  // absent: all cores
  std::optional<int> spp, lightSamples, maxDepth;
  std::optional<double> aperture, focalDistance;  // task 10's lens, over the scene's
  std::optional<double> adaptive;                 // task 11: the tolerance; -s is then the maximum
  std::optional<int> minSpp, batch;
  std::optional<std::string> sppMap;  // absent: beside the output, NAME.spp.png (given but empty is an error)
  std::optional<std::string> resolution;  // -d WxH (given but empty is an error)
  std::vector<int> widthHeight;    // -r W H
  std::string output = "render.png";
  std::string seed;  // parsed by parseSeed: CLI11 would wrap "-1" to 2^64 - 1
  std::optional<std::string> reference;
  std::optional<std::string> stats;  // --stats FILE.json: the summary's numbers for scripts (tools/writeup)
  std::string integrator = "path";
  std::string accel;  // empty: defaultTraversal
  std::string sampler = "sobol";
  bool quiet = false;
};

struct DebugArgs {
  int task = 0;
  std::string view;
  std::string scene;
  std::optional<std::string> resolution;
  std::string output;
  std::vector<int> pixel;
  std::optional<int> depth;
  std::optional<int> threads;
  bool list = false;
};

Scene loadSceneArg(const std::string& path) { return path.empty() ? defaultScene() : loadScene(path); }

// -d WxH or -r W H into the scene's resolution (-r wins if both are given).
void applyResolution(RenderSettings& settings, const std::optional<std::string>& wxh, const std::vector<int>& pair) {
  if (wxh && pair.empty()) {
    std::smatch m;
    if (!std::regex_match(*wxh, m, std::regex(R"((\d{1,9})[xX](\d{1,9}))"))) {
      throw Error("-d: expected WIDTHxHEIGHT such as 800x600, got " + inQuotes(*wxh));
    }
    settings.width = std::stoi(m[1]);
    settings.height = std::stoi(m[2]);
  } else if (!pair.empty()) {
    if (pair.size() != 2) throw Error("-r: expected two numbers, -r WIDTH HEIGHT");
    settings.width = pair[0];
    settings.height = pair[1];
  } else {
    return;
  }
  checkResolution(settings.width, settings.height, wxh && pair.empty() ? "-d" : "-r");
}

uint64_t parseSeed(const std::string& text) {
  uint64_t seed = 0;
  auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), seed);
  if (text.empty() || error != std::errc() || end != text.data() + text.size()) {
    throw Error("--seed: expected an integer in [0, 2^64 - 1], got " + inQuotes(text));
  }
  return seed;
}

int checkedCount(const char* flag, int value, int min, int max) {
  if (value < min || value > max) {
    throw Error(std::string(flag) + ": expected a value in [" + std::to_string(min) + ", " +
                std::to_string(max) + "], got " + std::to_string(value));
  }
  return value;
}

// NAME.png -> NAME.spp.png, in the same folder.
std::string sppMapBeside(const std::string& output) {
  std::filesystem::path path(output);
  return (path.parent_path() / (path.stem().string() + ".spp.png")).string();
}

// A length in world units for the camera: in [min, 1e12] (the scene's coordinate limit), finite.
float checkedLength(const char* flag, double value, double min) {
  if (!(value >= min && value <= 1e12)) {
    throw Error(std::string(flag) + ": expected a length in [" + (min > 0.0 ? "1e-06" : "0") + ", 1e12], got " +
                std::to_string(value));
  }
  return float(value);
}

// The scene with the command line's changes to its settings and camera.
Scene sceneFor(const RenderArgs& args) {
  Scene scene = loadSceneArg(args.scene);
  RenderSettings& settings = scene.render;
  if (args.spp) settings.samplesPerPixel = checkedCount("-s", *args.spp, 1, 1 << 20);
  if (args.lightSamples) settings.lightSamples = checkedCount("-l", *args.lightSamples, 1, 4096);
  if (args.maxDepth) settings.maxDepth = checkedCount("-m", *args.maxDepth, 0, 1024);
  if (!args.seed.empty()) settings.seed = parseSeed(args.seed);
  applyResolution(settings, args.resolution, args.widthHeight);
  if (args.aperture) scene.camera.apertureRadius = checkedLength("--aperture", *args.aperture, 0.0);
  if (args.focalDistance) scene.camera.focalDistance = checkedLength("--focal-distance", *args.focalDistance, 1e-6);
  return scene;
}

// The integrator, the tree's walk and the sampler, each checked.
RenderOptions optionsFor(const RenderArgs& args, const Scene& scene, const std::atomic<bool>& cancel) {
  RenderOptions options;
  if (args.threads) options.threads = checkedCount("-t", *args.threads, 1, 1024);
  options.progress = !args.quiet;
  options.cancel = &cancel;
  auto integrator = integratorFromName(args.integrator);
  if (!integrator) {
    throw Error("--integrator: unknown integrator " + inQuotes(args.integrator) + " (" + integratorNames() + ")");
  }
  options.integrator = *integrator;
  if (const std::string problem = mediaProblem(scene, options); !problem.empty()) {
    throw Error("--integrator " + args.integrator + ": " + scene.source + " has media, which only task 12's path "
                "tracer renders (--integrator path; preview and normals look without them)");
  }
  options.traversal = defaultTraversal(linkedTaskSummary());
  if (!args.accel.empty()) {
    auto traversal = traversalFromName(args.accel);
    if (!traversal) throw Error("--accel: unknown traversal " + inQuotes(args.accel) + " (task3, fast)");
    options.traversal = *traversal;
  }
  const std::optional<SampleSequence> sampler = sampleSequenceFromName(args.sampler);
  if (!sampler) throw Error("--sampler: unknown sampler " + inQuotes(args.sampler) + " (sobol, stratified, independent)");
  options.sampler = *sampler;
  return options;
}

// --adaptive's settings (task 11): -s the most a pixel may take, --min-spp
// and --batch as given or task 11's defaults within it; nothing without it.
std::optional<AdaptiveSettings> adaptiveFor(const RenderArgs& args, int most) {
  if (!args.adaptive && (args.minSpp || args.batch || args.sppMap)) {
    throw Error("--min-spp, --batch and --spp-map go with --adaptive TOLERANCE");
  }
  if (!args.adaptive) return std::nullopt;
  AdaptiveSettings adaptive;
  adaptive.tolerance = *args.adaptive;
  if (!(adaptive.tolerance > 0.0 && adaptive.tolerance <= 1e6)) {
    throw Error("--adaptive: expected a tolerance in (0, 1e6], got " + std::to_string(*args.adaptive));
  }
  adaptive.maxSpp = uint32_t(most);
  const AdaptiveSettings defaults;  // task 11's one set (adaptive_sampling.h)
  adaptive.batch =
      uint32_t(args.batch ? checkedCount("--batch", *args.batch, 1, most) : std::min(int(defaults.batch), most));
  adaptive.minSpp =
      uint32_t(args.minSpp ? checkedCount("--min-spp", *args.minSpp, 1, most)
                           : std::max(int(adaptive.batch), std::min(int(defaults.minSpp), most) / int(adaptive.batch) *
                                                               int(adaptive.batch)));
  if (const std::string problem = adaptiveSettingsProblem(adaptive); !problem.empty()) {
    char given[128];
    std::snprintf(given, sizeof given, " (-s %u, --min-spp %u, --batch %u)", adaptive.maxSpp, adaptive.minSpp,
                  adaptive.batch);
    throw Error("--adaptive: " + problem + given);
  }
  return adaptive;
}

// --ref's image, read and checked before an hour of rendering, not after.
std::optional<Image> referenceFor(const RenderArgs& args, const RenderSettings& settings) {
  if (!args.reference) return std::nullopt;
  Image reference = readImage(*args.reference);
  if (reference.width != settings.width || reference.height != settings.height) {
    throw Error("--ref: " + shown(*args.reference, 200) + " is " + std::to_string(reference.width) + "x" +
                std::to_string(reference.height) + " but the render is " + std::to_string(settings.width) + "x" +
                std::to_string(settings.height));
  }
  return reference;
}

// What a render says when it ends: its settings, its speed, whose tasks lit
// it and, adaptive, how many samples the pixels took.
void printRenderSummary(const RenderArgs& args, const Scene& scene, const RenderOptions& options,
                        const RenderResult& result, const std::string& sppMapPath) {
  const RenderSettings& settings = scene.render;
  const RenderStats& stats = result.stats;
  std::printf("%s: %dx%d, %d spp, %s integrator, %s traversal, %s samples, tasks %s\n", args.output.c_str(),
              settings.width, settings.height, settings.samplesPerPixel, integratorName(options.integrator),
              traversalName(options.traversal), sampleSequenceName(options.sampler), linkedTaskSummary());
  std::printf("time %.3f s (BVH build %.1f ms), %s samples/s, %s rays/s\n", stats.seconds, stats.buildSeconds * 1e3,
              formatRate(double(stats.samples) / stats.seconds).c_str(),
              formatRate(double(stats.rays) / stats.seconds).c_str());
  std::printf("lit by tasks %s\n", tasksLightingRender(scene, options.integrator).c_str());
  if (options.adaptive) {
    const SampleMap& map = result.sampleMap;
    const size_t confident = size_t(std::count(map.confident.begin(), map.confident.end(), uint8_t(1)));
    std::printf("adaptive (task 11, tolerance %g, batches of %u, %u to %u spp): mean %.1f spp, %.1f %% of pixels "
                "confident, the rest at the maximum; spp map %s\n",
                options.adaptive->tolerance, options.adaptive->batch, options.adaptive->minSpp,
                options.adaptive->maxSpp, double(stats.samples) / double(map.samples.size()),
                100.0 * double(confident) / double(map.samples.size()), sppMapPath.c_str());
  }
}

// --stats: the render's numbers as JSON.
nlohmann::json statsJson(const RenderArgs& args, const Scene& scene, const RenderOptions& options,
                         const RenderStats& stats, const std::optional<ImageError>& error) {
  const RenderSettings& settings = scene.render;
  nlohmann::json j = {{"output", args.output},
                      {"scene", scene.source},
                      {"width", settings.width},
                      {"height", settings.height},
                      {"spp", stats.completedSpp},
                      {"max_depth", settings.maxDepth},
                      {"light_samples", settings.lightSamples},
                      {"integrator", integratorName(options.integrator)},
                      {"traversal", traversalName(options.traversal)},
                      {"sampler", sampleSequenceName(options.sampler)},
                      {"tasks", linkedTaskSummary()},
                      {"threads", options.threads > 0 ? options.threads : int(std::thread::hardware_concurrency())},
                      {"seconds", stats.seconds},
                      {"build_seconds", stats.buildSeconds},
                      {"samples", stats.samples},
                      {"rays", stats.rays},
                      {"samples_per_second", double(stats.samples) / stats.seconds},
                      {"rays_per_second", double(stats.rays) / stats.seconds},
                      {"non_finite_samples", stats.nonFiniteSamples}};
  if (error) j["vs_reference"] = {{"rmse", error->rmse}, {"rel_mse", error->relMse}};
  return j;
}

int runRender(const RenderArgs& args, const std::atomic<bool>& cancel, std::atomic<bool>& rendering) {
  const Scene scene = sceneFor(args);
  const RenderSettings& settings = scene.render;
  RenderOptions options = optionsFor(args, scene, cancel);
  checkOutputFile("-o", args.output, OutputKind::Image);
  options.adaptive = adaptiveFor(args, settings.samplesPerPixel);
  std::string sppMapPath;
  if (options.adaptive) {
    sppMapPath = args.sppMap ? *args.sppMap : sppMapBeside(args.output);
    checkOutputFile("--spp-map", sppMapPath, OutputKind::Image);
  }
  if (args.stats) checkOutputFile("--stats", *args.stats, OutputKind::Text);
  if (args.reference && args.reference->empty()) throw Error("--ref: expected an image file name");
  checkDistinctFiles({{"-o", args.output}, {"--spp-map", sppMapPath}, {"--stats", args.stats.value_or("")},
                      {"--ref", args.reference.value_or("")}});
  const std::optional<Image> reference = referenceFor(args, settings);
  std::ofstream statsFile;  // opened before an hour of rendering, not after
  if (args.stats) {
    statsFile.open(*args.stats);
    if (!statsFile) throw Error("--stats " + shown(*args.stats, 200) + ": cannot write it");
  }

  rendering.store(true);
  RenderResult result = render(scene, options);
  const RenderStats& stats = result.stats;
  writeImage(result.image, args.output,
             {{"pathlab:spp", std::to_string(stats.completedSpp)}, {"pathlab:scene", scene.source}});
  if (options.adaptive) {
    writeImage(sampleMapImage(result.sampleMap, options.adaptive->minSpp, options.adaptive->maxSpp), sppMapPath);
  }
  if (stats.nonFiniteSamples > 0) {
    printWarning(std::to_string(stats.nonFiniteSamples) + " samples were NaN or Inf (first at pixel " +
                 std::to_string(stats.firstNonFinitePixel->x) + "," + std::to_string(stats.firstNonFinitePixel->y) +
                 "); they count as black");
  }
  if (stats.interrupted) {
    std::fprintf(stderr, "interrupted: wrote %s with %d of %d samples per pixel\n", args.output.c_str(),
                 stats.completedSpp, settings.samplesPerPixel);
    return 130;
  }
  if (!args.quiet) printRenderSummary(args, scene, options, result, sppMapPath);
  std::optional<ImageError> error;
  if (reference) {
    error = compareImages(result.image, *reference);
    std::printf("vs %s: RMSE %.6g, relMSE %.6g\n", args.reference->c_str(), error->rmse, error->relMse);
  }
  if (args.stats) {
    statsFile << statsJson(args, scene, options, stats, error).dump(2) << "\n";
    if (!statsFile.flush()) throw Error("--stats " + shown(*args.stats, 200) + ": cannot write it");
  }
  return 0;
}

int runDebug(const DebugArgs& args) {
  std::vector<DebugView> views = allDebugViews();
  if (args.list) {
    for (const DebugView& view : views) {
      std::printf("--task %d --view %-14s %s\n", view.task, view.name.c_str(), view.description.c_str());
    }
    return 0;
  }
  if (args.task == 0 || args.view.empty()) throw Error("debug: give --task N and --view VIEW (see --list)");
  const DebugView* chosen = nullptr;
  std::string available;
  for (const DebugView& view : views) {
    if (view.task != args.task) continue;
    available += (available.empty() ? "" : ", ") + view.name;
    if (view.name == args.view) chosen = &view;
  }
  if (!chosen) {
    throw Error("debug: task " + std::to_string(args.task) + " has no view " + inQuotes(args.view) +
                (available.empty() ? " (it has no views yet)" : " (views: " + available + ")"));
  }
  Scene scene = loadSceneArg(args.scene);
  applyResolution(scene.render, args.resolution, {});
  std::string output = args.output.empty()
                           ? "debug-task" + std::to_string(args.task) + "-" + args.view + ".png"
                           : args.output;
  checkOutputFile("-o", output, OutputKind::Image);
  DebugViewRequest request(scene, scene.render.width, scene.render.height);
  if (args.threads) request.threads = checkedCount("-t", *args.threads, 1, 1024);
  if (args.depth) request.depth = checkedCount("--depth", *args.depth, 0, 64);
  if (!args.pixel.empty()) {
    if (args.pixel.size() != 2) throw Error("--pixel: expected two numbers, --pixel X Y");
    request.pixel = {args.pixel[0], args.pixel[1]};
    if (request.pixel.x < 0 || request.pixel.y < 0 || request.pixel.x >= scene.render.width ||
        request.pixel.y >= scene.render.height) {
      throw Error("--pixel: " + std::to_string(request.pixel.x) + "," + std::to_string(request.pixel.y) +
                  " is outside the " + std::to_string(scene.render.width) + "x" +
                  std::to_string(scene.render.height) + " image");
    }
  }
  DebugOutput result = chosen->render(request);
  writeImage(result.image, output);
  std::printf("%s: task %d view %s\n%s", output.c_str(), args.task, args.view.c_str(), result.report.c_str());
  return 0;
}

}  // namespace

int runCli(int argc, char** argv, const std::atomic<bool>& cancel, std::atomic<bool>& rendering) {
  CLI::App app{"PathLab: a Monte Carlo path tracer to learn from.\n"
               "Renders SCENE (a .json file; none = the embedded Cornell box) to an image."};
  app.set_version_flag("--version", std::string("pathlab 0.1 (tasks ") + linkedTaskSummary() + ")");
  app.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);  // a repeated flag: last wins
  RenderArgs render;
  app.add_option("scene", render.scene, "Scene file (.json); omit for the built-in Cornell box");
  app.add_option("-t,--threads", render.threads, "Threads (default: all cores)");
  app.add_option("-s,--spp", render.spp, "Samples per pixel");
  app.add_option("-l,--light-samples", render.lightSamples, "Samples per area light");
  app.add_option("-m,--max-depth", render.maxDepth, "Maximum ray depth");
  app.add_option("-d", render.resolution, "Resolution WIDTHxHEIGHT, e.g. 800x600");
  app.add_option("-r", render.widthHeight, "Resolution as two numbers: -r WIDTH HEIGHT")
      ->expected(2)
      ->allow_extra_args(false);  // exactly two values, then the scene
  app.add_option("--aperture", render.aperture,
                 "Task 10: the lens's radius in scene units (0: a pinhole), over the scene's aperture_radius");
  app.add_option("--focal-distance", render.focalDistance,
                 "Task 10: the distance in focus, along the view (default: the scene's focal_distance, else the "
                 "distance to look_at)");
  app.add_option("--adaptive", render.adaptive,
                 "Task 11: sample each pixel until 1.96 sigma / sqrt(n) <= TOLERANCE x mean (e.g. 0.05), in "
                 "batches, at most -s samples; writes the samples-per-pixel map beside the image (NAME.spp.png)");
  app.add_option("--min-spp", render.minSpp, "Task 11: the fewest samples a pixel takes (default 64, or -s)");
  app.add_option("--batch", render.batch, "Task 11: samples between checks of the rule (default 32, or -s)");
  app.add_option("--spp-map", render.sppMap, "Task 11: where the samples-per-pixel map goes (default NAME.spp.png)");
  app.add_option("-o,-w,--output", render.output, "Output image: .png (display) or .exr (linear)");
  app.add_option("--seed", render.seed, "Random seed");
  app.add_option("--ref", render.reference, "Reference image: print RMSE and relMSE after the render");
  app.add_option("--stats", render.stats, "Also write the render's numbers (time, samples/s, rays/s, NaN or Inf "
                                          "samples, settings, tasks) as JSON to this file");
  app.add_option("--integrator", render.integrator,
                 "path (default), direct (task 4 only), preview (eye light, tasks 1-3), normals; task 9: mis (power "
                 "heuristic), mis-balance, light (one light sample per vertex alone), bsdf (BSDF sampling alone)");
  app.add_option("--accel", render.accel,
                 "How rays walk task 3's tree: task3 (your intersectClosest/intersectAny) or fast (the framework's "
                 "8-wide SIMD copy, the reference task 2's triangle and sphere tests and hit records; same hits); "
                 "default fast where tasks 2 and 3 are the reference");
  app.add_option("--sampler", render.sampler,
                 "Random numbers: sobol (default: Owen-scrambled Sobol points per pixel, less error for the same "
                 "samples), stratified (one jittered sample per cell, per dimension) or independent (plain Monte "
                 "Carlo)");
  app.add_flag("-q,--quiet", render.quiet, "No progress bar or summary");

  DebugArgs debug;
  CLI::App* debugCommand = app.add_subcommand("debug", "Write a task's debugger view to a PNG");
  debugCommand->add_option("--task", debug.task, "Task number (see --list)");
  debugCommand->add_option("--view", debug.view, "View name (see --list)");
  debugCommand->add_option("scene", debug.scene, "Scene file; omit for the built-in Cornell box");
  debugCommand->add_option("-d", debug.resolution, "Resolution WIDTHxHEIGHT");
  debugCommand->add_option("-o,--output", debug.output, "Output PNG");
  debugCommand->add_option("--pixel", debug.pixel, "Inspected pixel: --pixel X Y")
      ->expected(2)
      ->allow_extra_args(false);
  debugCommand->add_option("--depth", debug.depth, "Tree depth for hierarchy views (default 3)");
  debugCommand->add_option("-t,--threads", debug.threads, "Threads (default: all cores)");
  debugCommand->add_flag("--list", debug.list, "List every task's views");

  lab::LabArgs labArgs;
  CLI::App* labCommand = app.add_subcommand("lab", "The sampling lab: a warp's samples against its pdf, chi-square, figure");
  lab::addLabOptions(*labCommand, labArgs);

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    printError("pathlab", std::string(e.what()) + " (see pathlab --help)");
    return 1;
  }
  try {
    if (debugCommand->parsed()) return runDebug(debug);
    if (labCommand->parsed()) return lab::runLab(labArgs);
    return runRender(render, cancel, rendering);
  } catch (const Error& e) {
    printError("pathlab", e.what());
    return 1;
  }
}

}  // namespace pathlab
