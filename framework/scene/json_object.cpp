#include "scene/json_object.h"

#include <algorithm>
#include <unordered_map>

#include "util/error.h"

namespace pathlab::json {
namespace {

// Deeper JSON is refused while parsing: nothing in a scene nests past 5
// levels, and describing a value back (or destroying it) must not recurse
// 100,000 levels deep.
constexpr int kMaxDepth = 64;

std::string lineAndColumn(std::string_view text, size_t byte) {
  size_t line = 1, column = 1;
  for (size_t i = 0; i + 1 < byte && i < text.size(); ++i) {
    if (text[i] == '\n') ++line, column = 1;
    else ++column;
  }
  return std::to_string(line) + ":" + std::to_string(column);
}

// The line of the n-th object key (counting from 0) in JSON text that
// parses at least that far: a key is a string followed by ':'.
size_t lineOfKey(std::string_view text, size_t n) {
  size_t seen = 0, line = 1;
  for (size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\n') ++line;
    if (text[i] != '"') continue;
    const size_t keyLine = line;
    for (++i; i < text.size() && text[i] != '"'; ++i) {
      if (text[i] == '\\') ++i;
    }
    size_t j = i + 1;
    while (j < text.size() && (text[j] == ' ' || text[j] == '\t' || text[j] == '\r' || text[j] == '\n')) ++j;
    if (j < text.size() && text[j] == ':' && seen++ == n) return keyLine;
  }
  return line;
}

// The checks no DOM parser makes, in one SAX pass before the DOM is built:
// nesting depth and keys given twice. (Not nlohmann's parser callback: its
// DOM builder rescans the enclosing array at every object's end, so a scene
// of 100,000 lights took seconds and 10^6 never finished loading.)
class SceneChecks final : public nlohmann::json_sax<Json> {
 public:
  SceneChecks(std::string_view text, const std::string& name) : text_(text), name_(name) {}

  bool null() override { return true; }
  bool boolean(bool) override { return true; }
  bool number_integer(number_integer_t) override { return true; }
  bool number_unsigned(number_unsigned_t) override { return true; }
  bool number_float(number_float_t, const string_t&) override { return true; }
  bool string(string_t&) override { return true; }
  bool binary(binary_t&) override { return true; }
  bool start_object(std::size_t) override {
    enter();
    keysOfOpenObjects_.emplace_back();
    return true;
  }
  bool end_object() override {
    keysOfOpenObjects_.pop_back();
    --depth_;
    return true;
  }
  bool start_array(std::size_t) override {
    enter();
    return true;
  }
  bool end_array() override {
    --depth_;
    return true;
  }
  bool key(string_t& key) override {
    const size_t ordinal = keyCount_++;
    auto [it, inserted] = keysOfOpenObjects_.back().try_emplace(key, ordinal);
    if (!inserted) {
      throw Error(name_ + ":" + std::to_string(lineOfKey(text_, ordinal)) + ": key " + inQuotes(it->first) +
                  " is given twice in one object (first on line " + std::to_string(lineOfKey(text_, it->second)) + ")");
    }
    return true;
  }
  // The DOM parse that follows reports the error, with its position.
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override { return false; }

 private:
  void enter() {
    if (depth_ >= kMaxDepth) {
      throw Error(name_ + ": nesting deeper than " + std::to_string(kMaxDepth) + " levels (a scene needs 5)");
    }
    ++depth_;
  }

  std::string_view text_;
  const std::string& name_;
  int depth_ = 0;
  size_t keyCount_ = 0;
  std::vector<std::unordered_map<std::string, size_t>> keysOfOpenObjects_;
};

}  // namespace

Json parse(std::string_view text, const std::string& name) {
  try {
    SceneChecks checks(text, name);
    Json::sax_parse(text.begin(), text.end(), &checks);
    return Json::parse(text.begin(), text.end());
  } catch (const Json::out_of_range& e) {
    // e.g. a number literal too large for a double ("1e999")
    std::string what = e.what();
    size_t bracket = what.find("] ");
    throw Error(name + ": invalid JSON: " + (bracket == std::string::npos ? what : what.substr(bracket + 2)));
  } catch (const Json::parse_error& e) {
    // nlohmann's message starts "[json.exception.parse_error.101] parse error at line 3, column 5: ..."
    std::string what = e.what();
    size_t colon = what.find(": ");
    std::string detail = colon == std::string::npos ? what : what.substr(colon + 2);
    throw Error(name + ":" + lineAndColumn(text, e.byte) + ": invalid JSON: " + detail);
  }
}

size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}


std::string describe(const Json& j) {
  if (j.is_array()) return "array of " + std::to_string(j.size()) + " elements";
  if (j.is_object()) return "object of " + std::to_string(j.size()) + " keys";
  if (j.is_string()) return "string " + inQuotes(j.get_ref<const std::string&>(), 40);
  return std::string(j.type_name()) + " " + j.dump();
}


}  // namespace pathlab::json
