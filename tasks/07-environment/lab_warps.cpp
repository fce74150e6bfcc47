// Task 7's warps in the sampling lab (lab/lab.h): its sampling
// routines, called as this build links them (the student's file or the
// reference), each against its own pdf. lab/CMakeLists.txt compiles this
// file into the lab; addEnvironmentWarps is listed with the other tasks'.
#include <cmath>

#include "lab_support.h"
#include "tasks/environment.h"
#include "util/distribution.h"
#include "util/error.h"
#include "util/image.h"

namespace pathlab::lab {
namespace {

// The maps the lab offers: a sky with a sun (a hot spot), bright poles, a
// constant map, a single lit pixel.
Image labMap(int which) {
  constexpr int kWidth = 64, kHeight = 32;
  Image map(kWidth, kHeight, Color(which == 3 ? 0.0f : 1.0f));
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      Color& c = map.at(x, y);
      if (which == 0) c = Color(0.3f + 0.7f * float(y) / kHeight) + (x == 40 && y == 10 ? Color(2000.0f) : Color(0.0f));
      if (which == 1) c = Color(y == 0 || y == kHeight - 1 ? 50.0f : 0.5f);
    }
  if (which == 3) map.at(17, 9) = Color(1.0f);
  return map;
}

// The widest user map the lab tests as it is; a wider one is averaged down,
// so that the expected counts' 48 midpoints per cell side (2,400 around phi)
// see every pixel about ten times: with 8 (a whole number) per pixel, a hot
// pixel's share came out 0.5 % off; with 12, 0.02 %. A figure still redraws
// in about a second.
constexpr int kWidestLabMap = 256;
constexpr int kUserMapMidpoints = 48;

// A user's map, read as a scene reads one (invalid texels black), averaged
// down by a whole factor when it is wider than the lab resolves.
Image userMap(const std::string& path, std::string* note) {
  Image map;
  try {
    map = readImage(path);
  } catch (const Error& e) {
    throw Error(std::string("lab: --map: ") + e.what());
  }
  const size_t invalid = zeroInvalidRadiance(map);
  float brightest = 0.0f;
  for (const Color& c : map.pixels) brightest = std::max(brightest, maxComponent(c));
  if (!(brightest > 0.0f)) throw Error("lab: --map " + path + ": the map is black everywhere: there is no light to sample");
  *note = format("map: %s (%d x %d", path.c_str(), map.width, map.height);
  if (invalid > 0) *note += format("; %zu NaN, infinite or negative texels count as black", invalid);
  if (map.width > kWidestLabMap) {
    const int f = (map.width + kWidestLabMap - 1) / kWidestLabMap;
    Image small((map.width + f - 1) / f, (map.height + f - 1) / f);
    for (int y = 0; y < small.height; ++y)
      for (int x = 0; x < small.width; ++x) {
        Color sum(0.0f);
        int n = 0;
        for (int yy = y * f; yy < std::min(map.height, (y + 1) * f); ++yy)
          for (int xx = x * f; xx < std::min(map.width, (x + 1) * f); ++xx) sum += map.at(xx, yy), ++n;
        small.at(x, y) = sum / float(n);
      }
    *note += format(", averaged %d x %d into each pixel: %d x %d for the test's bins", f, f, small.width,
                    small.height);
    map = std::move(small);
  }
  *note += ")";
  return map;
}

// Whether w's (u, v), by the stable formula, lies within 1e-4 of a pixel's
// edge (the poles aside): such a direction may round into the pixel beside
// the one sampled, whose pdf differs.
bool onPixelEdge(const EnvironmentDistribution& d, const Vec3& w) {
  double phi = std::atan2(double(w.z), double(w.x));
  if (phi < 0.0) phi += 2.0 * kPi;
  const double theta = std::atan2(std::hypot(double(w.x), double(w.z)), double(w.y));
  const double column = phi / (2.0 * kPi) * d.width, row = theta / kPi * d.height;
  const bool innerRowEdge = std::round(row) >= 1 && std::round(row) <= d.height - 1;
  return std::abs(column - std::round(column)) < 1e-4 || (innerRowEdge && std::abs(row - std::round(row)) < 1e-4);
}

Warp environmentWarp() {
  Warp warp{"environment", "T7.5", "sampleEnvironment against environmentPdf over the sphere",
            {{"map", 0, 0, 3, true, false,
              "0 sky with a sun, 1 bright poles, 2 constant, 3 one lit pixel (--map FILE: your own)"}},
            [](const Values& p, const WarpFiles& files) {
              WarpSetup s;
              const Image map = files.environmentMap.empty() ? labMap(count(p, "map"))
                                                             : userMap(files.environmentMap, &s.note);
              const auto distribution =
                  std::make_shared<EnvironmentDistribution>(buildEnvironmentDistribution(map));
              s.domain = Domain::Sphere;
              // A piecewise-constant pdf: fine midpoints per cell.
              s.sphereSubdivision = files.environmentMap.empty() ? 32 : kUserMapMidpoints;
              s.sample = [distribution](Vec2 u) -> std::optional<Vec3> {
                const std::optional<EnvironmentSample> e = sampleEnvironment(*distribution, u);
                if (!e) return std::nullopt;
                return e->direction;
              };
              s.pdf = pointwise([distribution](const Vec3& w) { return double(environmentPdf(*distribution, w)); });
              // Each sample's pdf against environmentPdf of its direction: at
              // the poles a theta from acos(y) makes them disagree.
              s.reportedPdf = [distribution](Vec2 u) -> std::optional<double> {
                const std::optional<EnvironmentSample> e = sampleEnvironment(*distribution, u);
                if (!e || onPixelEdge(*distribution, e->direction)) return std::nullopt;
                return double(e->pdfSolidAngle);
              };
              s.mismatchMeans = "the pdf misses the Jacobian of the map: pdf = p(u, v) / (2 pi^2 sin theta); or "
                                "the CDF is off by one row or column; or (pdfs that disagree near the poles) theta "
                                "from acos(y), not atan2(sqrt(x^2 + z^2), y)";
              return s;
            }};
  warp.takesEnvironmentMap = true;
  return warp;
}

}  // namespace

void addEnvironmentWarps(std::vector<Warp>& warps) {
  warps.push_back(environmentWarp());
}

}  // namespace pathlab::lab
