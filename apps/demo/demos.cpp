#include "demos.h"

#include <algorithm>
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
    double value = 0.0;
    try {
      size_t used = 0;
      value = std::stod(setting.substr(equals + 1), &used);
      if (used != setting.size() - equals - 1) throw std::invalid_argument("trailing characters");
    } catch (const std::exception&) {
      throw Error("--set " + setting + ": \"" + setting.substr(equals + 1) + "\" is not a number");
    }
    if (!(value >= known->min && value <= known->max)) {
      throw Error("--set " + setting + ": " + name + " must be between " + std::to_string(known->min) + " and " +
                  std::to_string(known->max));
    }
    values[name] = value;
  }
  return values;
}

}  // namespace pathlab::demo
