// The lecture demos: each turns a few parameters into a figure and a few
// lines of numbers. `pathlab-demo NAME` writes the figure as a PNG;
// `pathlab-demo NAME --gui` redraws it live as the sliders move.
#pragma once

#include <functional>
#include <map>
#include <string>
#include <vector>

#include "figure.h"

namespace pathlab::demo {

struct Parameter {
  std::string name;
  double value, min, max;
  bool integer = false;
  bool logarithmic = false;  // slider spacing
  std::string help;
  // A choice among names: value k is choices[k] (min 0, max the last), and
  // --set NAME=CHOICE takes the name as well as the number.
  std::vector<std::string> choices{};
};

using Values = std::map<std::string, double>;

// "0 independent, 1 stratified, 2 sobol": a choice's values and names ("" for a number).
std::string choiceNames(const Parameter& p);

struct DemoResult {
  Figure figure;
  std::string numbers;  // what the figure shows, in numbers, one fact per line
};

struct Demo {
  std::string name;
  std::string summary;  // one line for --list
  std::vector<Parameter> parameters;
  std::function<DemoResult(const Values&)> run;
};

// Every demo, in lecture order.
const std::vector<Demo>& allDemos();

// "--set samples=1000" settings, checked against the parameters and their
// ranges (an Error names what is allowed); the rest keep their defaults.
Values parseSettings(const std::string& owner, const std::vector<Parameter>& parameters,
                     const std::vector<std::string>& settings);
// Where -o OUT puts NAME's figure: a .png file as given; a folder (existing,
// or ending in /) gets NAME.png; anything else is a prefix: OUT.png.
std::string figurePath(const std::string& out, const std::string& name);

// The demos' own numerics, exposed for tests.
// The example density of demo 1 on [0, 2] and its CDF.
double examplePdf(double x);
double exampleCdf(double x);
// Solves exampleCdf(x) = u for x in [0, 2]: Newton's method from `start`
// (default 2u: F is nearly linear), falling back to bisection whenever a
// step leaves the bracket. `iterations` receives the number of steps taken.
double invertExampleCdf(double u, int* iterations = nullptr, bool* usedBisection = nullptr, double start = -1.0);
// The first index i with cdf[i] > u (cdf ascending, cdf.back() == 1).
size_t sampleDiscrete(const std::vector<double>& cdf, double u);

}  // namespace pathlab::demo
