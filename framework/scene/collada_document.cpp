#include "scene/collada_document.h"

#include <cerrno>
#include <cstdio>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "util/error.h"
#include "util/input_file.h"

namespace pathlab::collada {
namespace {

std::string printable(std::string_view text) { return printableLine(text); }

// "/COLLADA/library_nodes/node/node": where an element is, as pugixml's
// xml_node::path() says it. Not that function: it returns a std::string,
// which a libc++ build cannot take from Debian's libstdc++-built pugixml.
std::string elementPath(pugi::xml_node node) {
  std::vector<std::string_view> names;
  for (; node && node.type() == pugi::node_element; node = node.parent()) names.emplace_back(node.name());
  std::string path;
  for (auto name = names.rbegin(); name != names.rend(); ++name) (path += '/') += *name;
  return path;
}

}  // namespace

std::string formatted(const Vec3& v) {
  std::string out = "(";
  for (int i = 0; i < 3; ++i) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.2f", double(std::abs(v[i]) < 5e-3f ? 0.0f : v[i]));
    if (i) out += ' ';
    out += buffer;
  }
  return out + ")";
}

Document::Document(const std::string& path) : file_(path) {
  const std::string text = readInputFile(path, "COLLADA file", kMaxColladaBytes);
  pugi::xml_parse_result parsed = document_.load_buffer(text.data(), text.size());
  if (!parsed) {
    throw Error(printable(path + ": invalid XML at byte " + std::to_string(parsed.offset) + ": " + parsed.description()));
  }
  root_ = document_.child("COLLADA");
  if (!root_) throw Error(printable(path + ": not a COLLADA file (no <COLLADA> element)"));
  indexIds(root_);
}

void Document::fail(const std::string& where, const std::string& what) const {
  throw Error(printable(file_ + ": " + where + ": " + what));
}

// Every element with an id, walked without recursion; refuses nesting
// deeper than kMaxXmlDepth.
void Document::indexIds(pugi::xml_node root) {
  std::vector<std::pair<pugi::xml_node, size_t>> pending{{root, 0}};
  while (!pending.empty()) {
    auto [node, depth] = pending.back();
    pending.pop_back();
    if (depth > kMaxXmlDepth) {
      fail(elementPath(node).substr(0, 80), "elements nest deeper than " + std::to_string(kMaxXmlDepth) + " levels");
    }
    if (const char* id = node.attribute("id").value(); *id) ids_[id] = node;
    for (pugi::xml_node child : node.children()) pending.emplace_back(child, depth + 1);
  }
}

pugi::xml_node Document::resolve(const std::string& url, const std::string& where) const {
  if (url.size() < 2 || url[0] != '#') fail(where, "expected a reference like \"#id\", got \"" + url + "\"");
  auto it = ids_.find(url.substr(1));
  if (it == ids_.end()) fail(where, "refers to \"" + url + "\", which the file does not define");
  return it->second;
}

std::vector<float> Document::numbers(pugi::xml_node node, const std::string& where, size_t expected) const {
  std::vector<float> values;
  std::istringstream in(node.child_value());
  std::string token;
  while (in >> token) {
    char* end = nullptr;
    float v = std::strtof(token.c_str(), &end);
    if (*end != '\0' || !std::isfinite(v)) fail(where, "expected numbers, got " + inQuotes(token, 40));
    values.push_back(v);
  }
  if (expected && values.size() != expected) {
    fail(where, "expected " + std::to_string(expected) + " numbers, got " + std::to_string(values.size()));
  }
  return values;
}

long Document::integerAttribute(pugi::xml_node node, const char* name, long fallback, long max,
                                const std::string& where) const {
  pugi::xml_attribute attribute = node.attribute(name);
  if (!attribute) return fallback;
  const std::string text = attribute.value();
  char* end = nullptr;
  errno = 0;
  const long value = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || errno == ERANGE || value < 0 || value > max) {
    fail(where, std::string(name) + "=" + inQuotes(text, 40) + " is not an integer in [0, " + std::to_string(max) + "]");
  }
  return value;
}

std::vector<long> Document::indices(pugi::xml_node node, const std::string& where) const {
  std::vector<long> values;
  std::istringstream in(node.child_value());
  std::string token;
  while (in >> token) {
    char* end = nullptr;
    long v = std::strtol(token.c_str(), &end, 10);
    if (*end != '\0' || v < 0 || v == LONG_MAX) fail(where, "expected non-negative indices, got " + inQuotes(token, 40));
    values.push_back(v);
  }
  return values;
}

pugi::xml_node Document::courseTechnique(pugi::xml_node parent) {
  for (pugi::xml_node technique : parent.child("extra").children("technique")) {
    std::string profile = technique.attribute("profile").value();
    if (profile == "CMU462" || profile == "CGL") return technique;
  }
  return {};
}

Color Document::color(pugi::xml_node node, const std::string& where) const {
  std::vector<float> v = numbers(node, where);
  if (v.size() < 3) fail(where, "expected a colour of 3 or 4 numbers");
  Color c(v[0], v[1], v[2]);
  if (glm::any(glm::lessThan(c, Color(0.0f)))) fail(where, "colour components must not be negative");
  return c;
}

FloatSource Document::source(const std::string& url, const std::string& where) const {
  pugi::xml_node node = resolve(url, where);
  if (std::string(node.name()) == "vertices") {  // <vertices> forwards to its POSITION source
    for (pugi::xml_node input : node.children("input")) {
      if (std::string(input.attribute("semantic").value()) == "POSITION") {
        const std::string positions = input.attribute("source").value();
        if (std::string(resolve(positions, where + "/vertices").name()) != "source") {
          fail(where + "/vertices", "POSITION input " + inQuotes(positions) + " must name a <source>");
        }
        return source(positions, where + "/vertices");
      }
    }
    fail(where, "<vertices> without a POSITION input");
  }
  pugi::xml_node array = node.child("float_array");
  if (!array) fail(where, "source \"" + std::string(node.attribute("id").value()) + "\" has no float_array");
  FloatSource s;
  s.values = numbers(array, where + "/float_array");
  pugi::xml_node accessor = node.child("technique_common").child("accessor");
  s.stride = accessor ? accessor.attribute("stride").as_uint(1) : 3;
  if (s.stride < 3) fail(where, "accessor stride must be at least 3");
  s.count = s.values.size() / s.stride;
  return s;
}

}  // namespace pathlab::collada
