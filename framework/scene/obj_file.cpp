// A strict OBJ reader. tinyobjloader, used before, reads "v nan nan nan" as
// zeros, drops a face with an out-of-range index without a word, counts a
// face's vertices in a byte (a 300-vertex polygon wraps) and ear-clips any
// polygon in quadratic time (150,000 vertices: 25 s): each is an error or a
// linear-time split here.
#include "scene/obj_file.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <unordered_map>
#include <vector>

// Numbers are read with std::from_chars: exact, locale-free, the whole
// token or nothing. libc++ has no floating-point from_chars before LLVM 20
// (macOS): there fast_float, the algorithm libstdc++'s uses, stands in.
#if defined(PATHLAB_HAVE_FAST_FLOAT)
#include <fast_float/fast_float.h>
namespace chars = fast_float;
#else
namespace chars = std;
#endif

#include "util/error.h"
#include "util/input_file.h"

namespace pathlab {
namespace {

struct Corner {
  int64_t position = 0;  // 0-based
  int64_t normal = -1;   // 0-based, -1 for none
};

class ObjParser {
 public:
  ObjParser(std::string_view text, const std::string& name) : text_(text), name_(shown(name, 200)) {}

  TriangleMesh parse() {
    size_t start = 0;
    while (start < text_.size()) {
      size_t end = text_.find('\n', start);
      if (end == std::string_view::npos) end = text_.size();
      ++line_;
      parseLine(text_.substr(start, end - start));
      start = end + 1;
    }
    if (faces_ == 0) throw Error(name_ + ": OBJ file has no faces");
    // Vertices are (position, normal) pairs, as OBJ indexes them separately;
    // normals are kept only if every corner has one.
    TriangleMesh mesh;
    mesh.name = name_;
    std::unordered_map<uint64_t, uint32_t> vertexOf;
    auto vertex = [&](const Corner& c) -> uint32_t {
      const int64_t normal = allCornersHaveNormals_ ? c.normal : -1;
      const uint64_t key = (uint64_t(c.position) << 32) | uint32_t(normal);
      auto [it, inserted] = vertexOf.try_emplace(key, uint32_t(mesh.positions.size()));
      if (inserted) {
        mesh.positions.push_back(positions_[size_t(c.position)]);
        if (normal >= 0) mesh.normals.push_back(normals_[size_t(normal)]);
      }
      return it->second;
    };
    mesh.triangles.reserve(triangles_.size());
    for (const auto& t : triangles_) mesh.triangles.emplace_back(vertex(t[0]), vertex(t[1]), vertex(t[2]));
    return mesh;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw Error(name_ + ":" + std::to_string(line_) + ": " + what);
  }

  static bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

  // The next whitespace-separated token of `rest`, removed from it.
  static std::string_view token(std::string_view& rest) {
    size_t i = 0;
    while (i < rest.size() && isSpace(rest[i])) ++i;
    size_t j = i;
    while (j < rest.size() && !isSpace(rest[j])) ++j;
    std::string_view t = rest.substr(i, j - i);
    rest.remove_prefix(j);
    return t;
  }

  Vec3 readVector(std::string_view rest, const char* what) const {
    Vec3 v;
    for (int k = 0; k < 3; ++k) {
      std::string_view t = token(rest);
      if (t.empty()) fail(std::string("expected 3 numbers for a ") + what);
      float value = 0.0f;
      auto [end, error] = chars::from_chars(t.data(), t.data() + t.size(), value);
      if (error != std::errc() || end != t.data() + t.size() || !std::isfinite(value)) {
        fail(std::string(what) + " component " + inQuotes(t, 40) + " is not a finite number");
      }
      v[k] = value;
    }
    return v;
  }

  // "7", "7/2", "7//3", "7/2/3"; negative indices count back from the last
  // element read so far.
  int64_t index(std::string_view t, size_t count, const char* what) const {
    int64_t value = 0;
    auto [end, error] = std::from_chars(t.data(), t.data() + t.size(), value);
    if (error != std::errc() || end != t.data() + t.size() || value == 0) {
      fail(std::string("expected a ") + what + " index, got " + inQuotes(t, 40));
    }
    const int64_t resolved = value > 0 ? value - 1 : int64_t(count) + value;
    if (resolved < 0 || resolved >= int64_t(count)) {
      fail("face refers to " + std::string(what) + " " + std::to_string(value) + " but the file has " +
           std::to_string(count) + " so far");
    }
    return resolved;
  }

  Corner corner(std::string_view t) const {
    Corner c;
    const size_t slash = t.find('/');
    c.position = index(t.substr(0, slash), positions_.size(), "vertex");
    if (slash != std::string_view::npos) {
      const size_t second = t.find('/', slash + 1);
      if (second != std::string_view::npos && second + 1 < t.size()) {
        c.normal = index(t.substr(second + 1), normals_.size(), "normal");
      }
    }
    return c;
  }

  void parseLine(std::string_view line) {
    if (const size_t hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
    std::string_view rest = line;
    const std::string_view keyword = token(rest);
    if (keyword == "v") {
      positions_.push_back(readVector(rest, "vertex"));
    } else if (keyword == "vn") {
      Vec3 n = readVector(rest, "normal");
      if (!(glm::length(n) > 0.0f)) fail("normal must not be zero");
      normals_.push_back(glm::normalize(n));
    } else if (keyword == "f") {
      corners_.clear();
      for (std::string_view t = token(rest); !t.empty(); t = token(rest)) corners_.push_back(corner(t));
      if (corners_.size() < 3) fail("a face needs at least 3 vertices, got " + std::to_string(corners_.size()));
      for (const Corner& c : corners_) allCornersHaveNormals_ = allCornersHaveNormals_ && c.normal >= 0;
      addFace();
    }
    // Everything else (vt, o, g, s, usemtl, mtllib, l, p, ...) adds no surface.
  }

  void triangle(size_t a, size_t b, size_t c) { triangles_.push_back({corners_[a], corners_[b], corners_[c]}); }

  Point3 at(size_t k) const { return positions_[size_t(corners_[k].position)]; }

  void addFace() {
    ++faces_;
    const size_t n = corners_.size();
    if (n == 3) return triangle(0, 1, 2);
    if (n == 4) {  // along the shorter diagonal (as tinyobjloader did: the same images)
      const Vec3 d02 = at(2) - at(0), d13 = at(3) - at(1);
      if (glm::dot(d02, d02) < glm::dot(d13, d13)) return triangle(0, 1, 2), triangle(0, 2, 3);
      return triangle(0, 1, 3), triangle(1, 2, 3);
    }
    // Project onto the plane of the Newell normal; convex polygons are fans.
    Vec3 normal(0.0f);
    for (size_t k = 0; k < n; ++k) {
      const Point3 p = at(k), q = at((k + 1) % n);
      normal += Vec3((p.y - q.y) * (p.z + q.z), (p.z - q.z) * (p.x + q.x), (p.x - q.x) * (p.y + q.y));
    }
    const int axis = std::abs(normal.x) > std::abs(normal.y) ? (std::abs(normal.x) > std::abs(normal.z) ? 0 : 2)
                                                             : (std::abs(normal.y) > std::abs(normal.z) ? 1 : 2);
    const float sign = normal[axis] < 0.0f ? -1.0f : 1.0f;
    std::vector<glm::vec2> p(n);
    for (size_t k = 0; k < n; ++k) p[k] = {at(k)[(axis + 1) % 3], at(k)[(axis + 2) % 3]};
    auto turn = [&](size_t a, size_t b, size_t c) {  // > 0: counter-clockwise about the normal
      const glm::vec2 u = p[b] - p[a], v = p[c] - p[b];
      return sign * (u.x * v.y - u.y * v.x);
    };
    // A fan from corner 0 covers the polygon when each of its triangles turns
    // counter-clockwise (convex polygons, and any seen whole from corner 0).
    // Tested per fan triangle, not per corner: a 150,000-vertex circle
    // written with 7 digits has corners that turn the wrong way by rounding.
    // The tolerance is what rounding the coordinates (float: 1.2e-7 of their
    // size) can do to a cross product of edges u and v: about that times |u| + |v|.
    float size = 0.0f;
    for (const glm::vec2& q : p) size = std::max({size, std::abs(q.x), std::abs(q.y)});
    bool fan = true;
    for (size_t k = 1; k + 1 < n && fan; ++k) {
      const float rounding = 1e-6f * size * (glm::length(p[k] - p[0]) + glm::length(p[k + 1] - p[k]));
      fan = turn(0, k, k + 1) >= -rounding;
    }
    if (fan) {
      for (size_t k = 1; k + 1 < n; ++k) triangle(0, k, k + 1);
      return;
    }
    if (n > kMaxConcavePolygonVertices) {
      fail("a non-convex polygon of " + std::to_string(n) + " vertices (at most " +
           std::to_string(kMaxConcavePolygonVertices) + " are triangulated; split it in a modeller)");
    }
    earClip(turn);
  }

  // O(n^2) ear clipping of a simple polygon; a polygon with no ear left
  // (self-intersecting) is finished as a fan of what remains.
  template <typename Turn>
  void earClip(Turn turn) {
    std::vector<size_t> left(corners_.size());
    for (size_t k = 0; k < left.size(); ++k) left[k] = k;
    auto inside = [&](size_t q, size_t a, size_t b, size_t c) {
      return turn(a, b, q) >= 0.0f && turn(b, c, q) >= 0.0f && turn(c, a, q) >= 0.0f;
    };
    size_t k = 0, stalled = 0;
    while (left.size() > 3 && stalled < left.size()) {
      const size_t m = left.size();
      const size_t a = left[k % m], b = left[(k + 1) % m], c = left[(k + 2) % m];
      bool ear = turn(a, b, c) > 0.0f;
      for (size_t j = 0; ear && j < m; ++j) {
        const size_t q = left[j];
        ear = q == a || q == b || q == c || !inside(q, a, b, c);
      }
      if (ear) {
        triangle(a, b, c);
        left.erase(left.begin() + std::ptrdiff_t((k + 1) % m));
        stalled = 0;
      } else {
        ++k, ++stalled;
      }
    }
    for (size_t j = 1; j + 1 < left.size(); ++j) triangle(left[0], left[j], left[j + 1]);
  }

  std::string_view text_;
  std::string name_;
  size_t line_ = 0;
  size_t faces_ = 0;
  std::vector<Point3> positions_;
  std::vector<Vec3> normals_;
  std::vector<Corner> corners_;  // of the face being read
  std::vector<std::array<Corner, 3>> triangles_;
  bool allCornersHaveNormals_ = true;
};

}  // namespace

TriangleMesh parseObj(std::string_view text, const std::string& name) { return ObjParser(text, name).parse(); }

TriangleMesh readObjFile(const std::string& path) {
  return parseObj(readInputFile(path, "OBJ file", kMaxMeshFileBytes), path);
}

}  // namespace pathlab
