// What the lab's warps share: each task's warps are in its folder
// (tasks/NN-name/lab_warps.cpp), the recitation's examples in lab_warps.cpp.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <memory>
#include <numbers>
#include <optional>
#include <vector>

#include "demo_support.h"
#include "lab.h"

namespace pathlab::lab {

using demo::count;
using demo::format;
using demo::Values;

inline constexpr double kPi = std::numbers::pi;

// A pdf evaluated point by point.
inline std::function<std::vector<double>(const std::vector<Vec3>&)> pointwise(std::function<double(const Vec3&)> pdf) {
  return [pdf](const std::vector<Vec3>& points) {
    std::vector<double> values;
    values.reserve(points.size());
    for (const Vec3& p : points) values.push_back(pdf(p));
    return values;
  };
}

}  // namespace pathlab::lab
