#include "figure.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "util/error.h"
#include "util/platform.h"

#ifndef PATHLAB_SOURCE_DIR
#define PATHLAB_SOURCE_DIR "."
#endif

namespace pathlab::demo {
namespace fs = std::filesystem;

namespace {

const char* kindName(Series::Kind kind) {
  switch (kind) {
    case Series::Kind::Line: return "line";
    case Series::Kind::Histogram: return "hist";
    case Series::Kind::Scatter: return "scatter";
    case Series::Kind::Bars: return "bars";
    case Series::Kind::Image: return "image";
  }
  return "?";
}

// Debian's python with matplotlib; the PATH one may be another install.
std::string python() { return fs::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3"; }

}  // namespace

void writeFigure(const Figure& figure, const std::string& path) {
  const fs::path target(path);
  const fs::path work = fs::temp_directory_path() / ("pathlab-demo-" + std::to_string(currentProcessId()));
  fs::create_directories(work);
  nlohmann::json spec = {{"title", figure.title}, {"out", fs::absolute(target).string()}, {"plots", nlohmann::json::array()}};
  int imageCount = 0;
  for (const Plot& plot : figure.plots) {
    nlohmann::json p = {{"title", plot.title},     {"xlabel", plot.xlabel}, {"ylabel", plot.ylabel},
                        {"xlog", plot.logX},       {"ylog", plot.logY},     {"equal", plot.equalAspect},
                        {"categories", plot.categories}, {"series", nlohmann::json::array()}};
    for (const Series& series : plot.series) {
      nlohmann::json s = {{"kind", kindName(series.kind)}, {"label", series.label}, {"x", series.x},
                          {"y", series.y},                 {"dashed", series.dashed}};
      if (series.kind == Series::Kind::Image) {
        const fs::path image = work / ("image" + std::to_string(imageCount++) + ".png");
        writeImage(series.image, image.string());
        s["path"] = image.string();
      }
      p["series"].push_back(s);
    }
    spec["plots"].push_back(p);
  }
  const fs::path specPath = work / "figure.json";
  std::ofstream(specPath) << spec.dump();
  const std::string command = python() + " " PATHLAB_SOURCE_DIR "/tools/plot-demo.py '" + specPath.string() + "'";
  const int status = std::system(command.c_str());
  std::error_code ignored;
  fs::remove_all(work, ignored);
  if (status != 0) {
    throw Error(path + ": matplotlib could not draw the figure (install Debian's python3-matplotlib: "
                "apt-get install python3-matplotlib)");
  }
}

}  // namespace pathlab::demo
