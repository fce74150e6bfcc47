// Reading JSON with messages that name the file, the field and what was
// expected: the scene loader's JSON layer (scene_io.cpp reads scenes with
// it). Private to the framework's sources.
#pragma once

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "util/error.h"
#include "util/math.h"

namespace pathlab::json {

using Json = nlohmann::json;

// Where we are in the file: its name for messages and the folder that
// relative paths resolve against.
struct Source {
  std::string name;
  std::filesystem::path baseDir;
};

// A value named in a message, in a few words: never its whole text (a
// 200 MB string or a deep array is described, not echoed).
std::string describe(const Json& j);

// Parses with two checks nlohmann's parser does not make: nesting deeper
// than kMaxDepth levels, and a key given twice in one object (the parser
// would keep the last silently). Errors name `name` and the line.
Json parse(std::string_view text, const std::string& name);

// "path[i]", for messages about array elements.
inline std::string indexed(const std::string& path, size_t i) { return path + "[" + std::to_string(i) + "]"; }

// Edit distance between two keys, for did-you-mean suggestions.
size_t editDistance(const std::string& a, const std::string& b);
// Keys longer than this get no did-you-mean (edit distance is quadratic).
inline constexpr size_t kMaxSuggestedKey = 64;

// The values a number may take: [min, max], without an end that is open.
// Every bounded field of a scene says its range through this one type, so
// that each is checked, and reported, the same way.
struct Range {
  double min, max;
  bool minOpen = false, maxOpen = false;
  bool holds(double v) const { return (minOpen ? v > min : v >= min) && (maxOpen ? v < max : v <= max); }
  std::string text() const {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%c%g, %g%c", minOpen ? '(' : '[', min, max, maxOpen ? ')' : ']');
    return buffer;
  }
};

// A JSON object whose keys are checked against the allowed ones, with typed
// accessors that name the field in every error.
class Object {
 public:
  Object(const Source& source, const Json& json, std::string path, std::vector<std::string> allowed)
      : source_(source), json_(json), path_(std::move(path)) {
    if (!json.is_object()) fail(path_, "expected an object, got " + describe(json));
    for (const auto& [key, value] : json.items()) {
      if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
      std::string message = "unknown key " + inQuotes(key);
      std::string best;
      size_t bestDistance = SIZE_MAX;
      for (const std::string& candidate : allowed) {
        if (key.size() > kMaxSuggestedKey) break;
        size_t d = editDistance(key, candidate);
        if (d < bestDistance) bestDistance = d, best = candidate;
      }
      if (!best.empty() && bestDistance <= std::max<size_t>(2, key.size() / 3)) {
        message += " (did you mean " + inQuotes(best) + "?)";
      } else {
        message += " (expected one of:";
        for (const std::string& candidate : allowed) message += " " + candidate;
        message += ")";
      }
      fail(path_, message);
    }
  }

  [[noreturn]] void fail(const std::string& field, const std::string& message) const {
    throw Error(source_.name + ": " + (field.empty() ? "" : field + ": ") + message);
  }

  std::string field(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }
  bool has(const std::string& key) const { return json_.contains(key); }
  const Json& at(const std::string& key) const { return json_.at(key); }
  const Source& source() const { return source_; }

  float number(const std::string& key, float fallback) const {
    return has(key) ? toFloat(at(key), field(key)) : fallback;
  }

  // A number within `range` (the fallback when the key is absent).
  float number(const std::string& key, float fallback, const Range& range) const {
    const float value = number(key, fallback);
    if (has(key) && !range.holds(value)) fail(field(key), "expected a number in " + range.text() + ", got " + at(key).dump());
    return value;
  }

  // A colour whose components each lie within `range`.
  Color color(const std::string& key, Color fallback, const Range& range) const {
    const Color c = vec3(key, fallback);
    if (has(key) && !(range.holds(c.x) && range.holds(c.y) && range.holds(c.z))) {
      fail(field(key), "expected components in " + range.text() + ", got " + at(key).dump());  // 3 numbers
    }
    return c;
  }

  float positive(const std::string& key, float fallback) const {
    float value = number(key, fallback);
    if (!(value > 0.0f)) fail(field(key), "expected a positive number, got " + describe(at(key)));
    return value;
  }

  int64_t integer(const std::string& key, int64_t fallback, int64_t min, int64_t max) const {
    if (!has(key)) return fallback;
    const Json& j = at(key);
    double value = j.is_number() ? j.get<double>() : std::nan("");
    if (!j.is_number() || std::floor(value) != value) {
      fail(field(key), "expected an integer, got " + describe(j));
    }
    if (value < double(min) || value > double(max)) {
      fail(field(key), "expected an integer in [" + std::to_string(min) + ", " + std::to_string(max) +
                           "], got " + j.dump());  // a number
    }
    return j.is_number_unsigned() ? int64_t(std::min<uint64_t>(j.get<uint64_t>(), uint64_t(INT64_MAX)))
                                  : int64_t(value);
  }

  Vec3 vec3(const std::string& key, Vec3 fallback) const {
    return has(key) ? toVec3(at(key), field(key)) : fallback;
  }

  Color color(const std::string& key, Color fallback, float maxValue = FLT_MAX) const {
    Color c = vec3(key, fallback);
    for (int i = 0; i < 3; ++i) {
      if (c[i] < 0.0f || c[i] > maxValue) {
        std::string range = maxValue == FLT_MAX ? "non-negative" : "in [0, 1] (more would create energy)";
        fail(field(key), "expected colour components " + range + ", got " + at(key).dump());  // 3 numbers
      }
    }
    return c;
  }

  std::string string(const std::string& key, const std::string& fallback) const {
    if (!has(key)) return fallback;
    if (!at(key).is_string()) fail(field(key), "expected a string, got " + describe(at(key)));
    return at(key).get<std::string>();
  }

  const Json& array(const std::string& key) const {
    if (!at(key).is_array()) fail(field(key), "expected an array, got " + describe(at(key)));
    return at(key);
  }

  float toFloat(const Json& j, const std::string& where) const {
    if (!j.is_number()) fail(where, "expected a number, got " + describe(j));
    double value = j.get<double>();
    if (!std::isfinite(value) || std::abs(value) > double(FLT_MAX)) {
      fail(where, "expected a finite number, got " + j.dump());  // a number
    }
    return float(value);
  }

  Vec3 toVec3(const Json& j, const std::string& where) const {
    if (!j.is_array() || j.size() != 3) fail(where, "expected an array of 3 numbers, got " + describe(j));
    return {toFloat(j[0], where + "[0]"), toFloat(j[1], where + "[1]"), toFloat(j[2], where + "[2]")};
  }

 private:
  const Source& source_;
  const Json& json_;
  std::string path_;
};

}  // namespace pathlab::json
