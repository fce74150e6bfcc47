// The rough materials' parameters (task 8), as the task functions take them:
// core data, so a task API can name them without depending on the Bsdf.
#pragma once

#include "util/math.h"

namespace pathlab {

// A rough metal: its roughness in [0, 1] (alpha = roughness^2, task 8), and
// its Fresnel reflectance either from F0 (Schlick's approximation) or, when
// exactFresnel, from the complex index of refraction eta + i k per channel.
struct RoughConductor {
  float roughness = 0.5f;
  Color f0{0.9f};
  bool exactFresnel = false;
  Color eta{0.2f};
  Color k{3.0f};
};

// A rough plastic: a diffuse base of albedo `diffuse` under a clear GGX coat
// of the given roughness and index of refraction ior.
struct RoughPlastic {
  float roughness = 0.5f;
  Color diffuse{0.5f};
  float ior = 1.5f;
};

}  // namespace pathlab
