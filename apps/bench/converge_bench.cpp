#include "converge_bench.h"

#include <algorithm>
#include <cstdlib>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "pathlab/error.h"
#include "pathlab/parallel.h"
#include "pathlab/render.h"
#include "pathlab/scene_io.h"

namespace pathlab::bench {
namespace {

namespace fs = std::filesystem;

struct Strategy {
  std::string name;
  RenderOptions options;
};

// Each strategy changes one thing from the reference's default.
Strategy strategy(const std::string& name) {
  Strategy s{name, {}};
  if (name == "reference" || name == "env-importance" || name == "cosine" || name == "nee" || name == "rr") {
  } else if (name == "env-uniform") {
    s.options.environmentSampling = EnvironmentSampling::Uniform;
  } else if (name == "uniform-hemisphere") {
    s.options.cosineSampling = false;
  } else if (name == "no-nee") {
    s.options.lightSampling = false;
  } else if (name == "no-rr") {
    s.options.russianRoulette = false;
  } else if (name == "mis-balance") {
    s.options.mis = MisHeuristic::Balance;
  } else if (name == "mis-power") {
    s.options.mis = MisHeuristic::Power;
  } else {
    throw Error("--strategies: unknown strategy \"" + name +
                "\" (reference, cosine, uniform-hemisphere, nee, no-nee, rr, no-rr, mis-balance, mis-power, env-importance, "
                "env-uniform)");
  }
  return s;
}

struct Point {
  int spp;
  double seconds, rmse, relMse;
};

}  // namespace

int runConvergeBench(const ConvergeOptions& options) {
  Scene scene = loadScene(options.scene);
  const int threads = options.threads > 0 ? options.threads : defaultThreadCount();
  fs::create_directories(options.outDir);
  const std::string stem = fs::path(options.scene).stem().string();

  // The converged reference: the default (best) strategy, another seed, cached.
  const fs::path referencePath = fs::path(options.outDir) / (stem + "-reference-" + std::to_string(options.referenceSpp) + "spp.exr");
  Image reference;
  if (fs::exists(referencePath)) {
    reference = readImage(referencePath.string());
    std::printf("reference: %s (cached)\n", referencePath.string().c_str());
  } else {
    Scene high = scene;
    high.render.samplesPerPixel = options.referenceSpp;
    high.render.seed = 987654321;
    RenderOptions render;
    render.threads = threads;
    render.progress = false;
    RenderResult result = pathlab::render(high, render);
    writeImage(result.image, referencePath.string());
    reference = result.image;
    std::printf("reference: %s, %d spp in %.1f s\n", referencePath.string().c_str(), options.referenceSpp,
                result.stats.seconds);
  }

  const fs::path csvPath = fs::path(options.outDir) / (stem + "-converge.csv");
  std::ofstream csv(csvPath);
  csv << "strategy,spp,seconds,rmse,relmse,efficiency\n";
  std::vector<std::pair<std::string, std::vector<Point>>> curves;
  std::stringstream list(options.strategies);
  for (std::string name; std::getline(list, name, ',');) {
    Strategy s = strategy(name);
    s.options.threads = threads;
    s.options.progress = false;
    std::vector<Point> points;
    double spent = 0.0;
    for (int spp = 1; spp <= (1 << 16) && spent < options.budgetSeconds; spp *= 2) {
      Scene run = scene;
      run.render.samplesPerPixel = spp;
      run.render.seed = 1;
      RenderResult result = pathlab::render(run, s.options);
      const ImageError error = compareImages(result.image, reference);
      points.push_back({spp, result.stats.seconds, error.rmse, error.relMse});
      spent += result.stats.seconds;
      csv << name << ',' << spp << ',' << result.stats.seconds << ',' << error.rmse << ',' << error.relMse << ','
          << 1.0 / (error.relMse * result.stats.seconds) << '\n';
      std::printf("%-16s %6d spp %8.3f s  RMSE %.5f  relMSE %.6f  efficiency %.4g\n", name.c_str(), spp,
                  result.stats.seconds, error.rmse, error.relMse, 1.0 / (error.relMse * result.stats.seconds));
    }
    curves.push_back({name, points});
  }
  csv.close();
  std::printf("wrote %s\n", csvPath.string().c_str());
  // The plot: matplotlib (Debian's python3-matplotlib), no hand-made charts.
  const fs::path pngPath = fs::path(options.outDir) / (stem + "-converge.png");
  const std::string python = fs::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
  const std::string command = python + " " PATHLAB_SOURCE_DIR "/tools/plot-convergence.py '" + csvPath.string() +
                              "' '" + pngPath.string() + "' '" + stem + ": error against time' > /dev/null";
  if (std::system(command.c_str()) != 0) {
    std::fprintf(stderr, "no plot: install python3-matplotlib, then run tools/plot-convergence.py %s %s\n",
                 csvPath.string().c_str(), pngPath.string().c_str());
  } else {
    std::printf("wrote %s\n", pngPath.string().c_str());
  }

  // Efficiency = 1 / (relMSE x time): for unbiased estimators it settles to a
  // constant, and the ratio of two is the ratio of times to the same error.
  std::vector<double> efficiency;
  for (const auto& [name, points] : curves) {
    std::vector<double> last;
    for (size_t i = points.size() >= 3 ? points.size() - 3 : 0; i < points.size(); ++i) {
      last.push_back(1.0 / (points[i].relMse * points[i].seconds));
    }
    std::sort(last.begin(), last.end());
    efficiency.push_back(last.empty() ? 0.0 : last[last.size() / 2]);
    std::printf("%-16s efficiency (median of the last 3 points) %.4g\n", name.c_str(), efficiency.back());
  }
  if (curves.size() >= 2 && efficiency[1] > 0.0) {
    std::printf("%s needs %.1fx less time than %s for the same relMSE\n", curves[0].first.c_str(),
                efficiency[0] / efficiency[1], curves[1].first.c_str());
  }
  return 0;
}

}  // namespace pathlab::bench
