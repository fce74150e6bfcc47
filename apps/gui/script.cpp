#include "script.h"

#include <map>
#include <sstream>

#include "util/error.h"

namespace pathlab::gui {

std::vector<ScriptCommand> parseScript(const std::string& text, const std::string& name) {
  static const std::map<std::string, size_t> arity = {
      {"panel", 1},  {"view", 1},     {"click", 2},      {"orbit", 2}, {"view-orbit", 2}, {"depth", 1},
      {"exposure", 1}, {"wait", 0},   {"wait-spp", 1}, {"wait-panel", 0},   {"screenshot", 1}, {"quit", 0},
      {"lab", 1},      {"lab-set", 2},  {"lab-map", 1}, {"lab-verdict", 0}, {"panels", 0}};
  std::vector<ScriptCommand> commands;
  std::istringstream lines(text);
  std::string line;
  for (int number = 1; std::getline(lines, line); ++number) {
    std::istringstream words(line);
    ScriptCommand command;
    command.line = number;
    if (!(words >> command.verb) || command.verb[0] == '#') continue;
    for (std::string word; words >> word;) command.args.push_back(word);
    const auto known = arity.find(command.verb);
    const std::string where = name + ":" + std::to_string(number) + ": ";
    if (known == arity.end()) throw Error(where + "unknown command \"" + command.verb + "\"");
    if (command.args.size() != known->second) {
      throw Error(where + command.verb + " takes " + std::to_string(known->second) + " argument(s), got " +
                  std::to_string(command.args.size()));
    }
    const bool textArgument = command.verb == "view" || command.verb == "screenshot" || command.verb == "lab" ||
                              command.verb == "lab-map";
    for (size_t i = 0; i < command.args.size(); ++i) {
      const std::string& arg = command.args[i];
      if (command.verb == "lab-set" && i == 0) continue;  // the parameter's name
      size_t used = 0;
      try {
        (void)std::stod(arg, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (!textArgument && used != arg.size()) throw Error(where + command.verb + ": \"" + arg + "\" is not a number");
    }
    commands.push_back(std::move(command));
  }
  return commands;
}

}  // namespace pathlab::gui
