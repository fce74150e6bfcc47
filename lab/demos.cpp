#include "demos.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "demo_support.h"
#include "util/error.h"
#include "util/input_file.h"

namespace pathlab::demo {
namespace fs = std::filesystem;

const std::vector<Demo>& allDemos() {
  static const std::vector<Demo> demos = {pdfCdfDemo(), discreteDemo(),          annulusDemo(),     hemisphereDemo(),
                                          piDemo(),     renderingEquationDemo(), environmentDemo(), sequencesDemo()};
  return demos;
}

std::string figurePath(const std::string& out, const std::string& name) {
  if (out.empty()) return name + ".png";
  if (fs::path(out).extension() == ".png") return out;
  std::error_code notFolder;
  if (fs::is_directory(out, notFolder) || out.back() == '/') {
    createFolders(out);
    return (fs::path(out) / (name + ".png")).string();
  }
  return out + ".png";
}

namespace {

std::string shownNumber(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g", v);
  return buffer;
}

std::string choicesOf(const Parameter& p) {
  const std::string names = choiceNames(p);
  return names.empty() ? names : " (" + names + ")";
}

}  // namespace

std::string choiceNames(const Parameter& p) {
  std::string list;
  for (size_t k = 0; k < p.choices.size(); ++k) list += (k ? ", " : "") + std::to_string(k) + " " + p.choices[k];
  return list;
}

Values parseSettings(const std::string& owner, const std::vector<Parameter>& parameters,
                     const std::vector<std::string>& settings) {
  Values values;
  for (const Parameter& parameter : parameters) values[parameter.name] = parameter.value;
  for (const std::string& setting : settings) {
    const size_t equals = setting.find('=');
    const std::string name = setting.substr(0, equals);
    const auto known = std::find_if(parameters.begin(), parameters.end(),
                                    [&](const Parameter& p) { return p.name == name; });
    if (equals == std::string::npos || known == parameters.end()) {
      std::string names;
      for (const Parameter& p : parameters) names += (names.empty() ? "" : ", ") + p.name;
      throw Error("--set " + setting + ": " + owner + " has the parameters " + names + " (--set NAME=VALUE)");
    }
    const std::string text = setting.substr(equals + 1);
    const auto choice = std::find(known->choices.begin(), known->choices.end(), text);
    double value = 0.0;
    if (choice != known->choices.end()) {
      value = double(choice - known->choices.begin());
    } else {
      try {
        size_t used = 0;
        value = std::stod(text, &used);
        if (used != text.size()) throw std::invalid_argument("trailing characters");
      } catch (const std::exception&) {
        throw Error("--set " + setting + ": \"" + text + "\" is not a number" + choicesOf(*known));
      }
    }
    if (!(value >= known->min && value <= known->max)) {
      throw Error("--set " + setting + ": " + name + " must be between " + shownNumber(known->min) + " and " +
                  shownNumber(known->max) + choicesOf(*known));
    }
    if ((known->integer || !known->choices.empty()) && value != std::floor(value)) {
      throw Error("--set " + setting + ": " + name + " takes whole numbers" + choicesOf(*known));
    }
    values[name] = value;
  }
  return values;
}

}  // namespace pathlab::demo
