// Meshes built in code for the suites: only what a test needs.
#pragma once

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

#include "core/scene.h"

namespace pathlab::test {

// A closed, convex, consistently wound triangle mesh around `center`.
inline TriangleMesh icosphere(int subdivisions, Point3 center, float radius) {
  const float t = (1.0f + std::sqrt(5.0f)) / 2.0f;
  std::vector<Vec3> unit = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                            {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  for (Vec3& v : unit) v = glm::normalize(v);
  std::vector<glm::uvec3> faces = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                   {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                   {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                   {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (int s = 0; s < subdivisions; ++s) {
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> midpoint;
    auto middle = [&](uint32_t a, uint32_t b) {
      auto key = std::minmax(a, b);
      auto it = midpoint.find(key);
      if (it != midpoint.end()) return it->second;
      unit.push_back(glm::normalize(unit[a] + unit[b]));
      return midpoint[key] = uint32_t(unit.size() - 1);
    };
    std::vector<glm::uvec3> next;
    for (const glm::uvec3& f : faces) {
      uint32_t ab = middle(f.x, f.y), bc = middle(f.y, f.z), ca = middle(f.z, f.x);
      next.insert(next.end(), {{f.x, ab, ca}, {f.y, bc, ab}, {f.z, ca, bc}, {ab, bc, ca}});
    }
    faces = std::move(next);
  }
  TriangleMesh mesh;
  for (const Vec3& v : unit) mesh.positions.push_back(center + radius * v);
  mesh.triangles = faces;
  return mesh;
}

// A flat n x n grid of squares in the z = 0 plane over [0, n] x [0, n], each
// split along its diagonal: every vertex and edge lies on exact integers.
inline TriangleMesh planeGrid(int n) {
  TriangleMesh mesh;
  for (int y = 0; y <= n; ++y)
    for (int x = 0; x <= n; ++x) mesh.positions.emplace_back(float(x), float(y), 0.0f);
  auto index = [n](int x, int y) { return uint32_t(y * (n + 1) + x); };
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      mesh.triangles.emplace_back(index(x, y), index(x + 1, y), index(x + 1, y + 1));
      mesh.triangles.emplace_back(index(x, y), index(x + 1, y + 1), index(x, y + 1));
    }
  return mesh;
}

}  // namespace pathlab::test
