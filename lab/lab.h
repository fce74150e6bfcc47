// The sampling lab: every warp the tasks ask for (and the recitation's own
// examples), drawn and tested against its own pdf. A warp maps uniform
// points u in [0, 1)^2 to a domain (an interval, a square, the sphere, or a
// few discrete outcomes) and claims a density there; the lab draws N points
// (independent, stratified or Sobol), bins them, integrates the pdf over the
// same bins, and runs the suites' chi-square test (util/chi_square.h) on the
// two. `pathlab lab WARP` writes the figure; the GUI's lab panel redraws it live.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "demos.h"
#include "util/chi_square.h"
#include "util/math.h"

namespace pathlab::lab {

enum class Domain {
  Interval,  // a point is x in [lo.x, hi.x] (point.x); pdf per unit length
  Plane,     // (x, y) in [lo, hi] (point.x, point.y); pdf per unit area
  Sphere,    // a unit direction; pdf per unit solid angle
  Discrete,  // outcome k = point.x in 0 .. outcomes - 1; pdf = its probability
};

// One warp, set up for one choice of its parameters.
struct WarpSetup {
  Domain domain = Domain::Plane;
  Vec2 lo{0.0f}, hi{1.0f};
  std::vector<std::string> outcomes;  // Discrete: the outcomes' names
  // The warp of u; nothing when the sampler returns no sample.
  std::function<std::optional<Vec3>(Vec2 u)> sample;
  // Its claimed density at many points at once (a student's pdf function).
  std::function<std::vector<double>(const std::vector<Vec3>&)> pdf;
  // A mixture of two strategies (task 9): which one drew the sample of u
  // (true: the first), the first's density times its share integrated over
  // every cell (times n), and the two names. The lab then shows, per cell,
  // the share of samples the first drew beside the share its density
  // predicts (the balance heuristic's weight, averaged over the cell).
  std::function<bool(Vec2 u)> drawnByFirst;
  std::function<std::vector<double>(double n)> firstExpectedCounts;
  std::string firstName, secondName;
  int sphereSubdivision = 8;  // midpoints per cell side for the expected counts (32 for piecewise-constant maps)
  // The pdf integrated over every cell, times n, where the lab's midpoint
  // rule cannot do it (a small light's pdf, which has no bound at its
  // outline); unset: the midpoint rule.
  std::function<std::vector<double>(double n)> expectedCounts;
  // The pdf the sampler reports with its own sample of u (an environment
  // sample carries one); nothing where it reports none, or where the check
  // does not apply (a direction on a pixel's edge may round into the pixel
  // beside it). Unset: no check. Set: pdf of each sample's direction must
  // agree with it to kPdfAgreement and never be 0, or the warp is rejected.
  std::function<std::optional<double>(Vec2 u)> reportedPdf;
  std::string mismatchMeans;  // what a rejection usually means, for this warp
  std::string note;           // printed with the numbers (which map, and its size)
};

// Files a warp reads: the user's own environment map (`--map`, the GUI's
// map field); empty: the warp's built-in choices.
struct WarpFiles {
  std::string environmentMap;
};

struct Warp {
  std::string name;
  std::string task;     // "T5.1", ... or "seed" for the recitation's examples
  std::string summary;  // one line for --list
  std::vector<demo::Parameter> parameters;  // besides the common ones (samples, sequence, seed, grid)
  std::function<WarpSetup(const demo::Values&, const WarpFiles&)> setup;
  bool takesEnvironmentMap = false;  // reads WarpFiles::environmentMap
  // Other tasks whose code it runs besides its own (the scene's intersection,
  // a BSDF): its verdict means something only once they are done too.
  std::vector<int> alsoRuns = {};
};

// Every warp, in task order, the recitation's examples first.
const std::vector<Warp>& allWarps();
// Every task's warps, in task order: each tasks/NN-name/lab_warps.cpp defines
// add<Name>Warps (tasks/01-camera-rays: addCameraRaysWarps), and CMake
// generates this function, which calls them (apps/CMakeLists.txt).
void addTaskWarps(std::vector<Warp>& warps);
const Warp* findWarp(const std::string& name);

// The common parameters every warp has, then its own.
std::vector<demo::Parameter> parametersOf(const Warp& warp);

// The significance level of the lab's verdict: a correct warp with
// independent samples is rejected in 1 run in 1000.
constexpr double kSignificance = 1e-3;
// How far pdf(a sample's direction) may be from the pdf the sampler reported
// with it (WarpSetup::reportedPdf), relative.
constexpr double kPdfAgreement = 1e-3;

struct LabResult {
  demo::DemoResult shown;  // the figure and its numbers
  ChiSquareResult test;
  double pdfIntegral = 0.0;  // the claimed pdf integrated over the domain (should be 1)
  int noSample = 0, outside = 0;
  // Samples whose pdf read back from the direction is off the reported one
  // by more than kPdfAgreement, and of those, how many read back 0; checked
  // is how many were compared (0: the warp reports no pdf).
  int pdfChecked = 0, pdfDisagree = 0, pdfReadsZero = 0;
  bool accepted = false;
  std::string csv;  // cell, position, observed, expected: one line per cell
};

LabResult runWarp(const Warp& warp, const demo::Values& values, const WarpFiles& files = {});

// `pathlab lab` (lab_cli.h has its options).
struct LabArgs {
  std::string warp, output, map;
  std::optional<std::string> csv;  // given but empty is an error
  std::vector<std::string> settings;
  bool list = false, params = false, noFigure = false;
};
// Prints the verdict and its numbers; writes the figure and the CSV. Returns
// 0 (whatever the verdict: it is printed); throws pathlab::Error on bad input.
int runLab(const LabArgs& args);

}  // namespace pathlab::lab
