// The BSDF at a hit, in the local shading frame where the normal is +z.
// Surfaces are two-sided: the frame's normal is flipped to the side wo
// leaves from. The diffuse lobe is built from task 4 (f) and task 5
// (direction sampling); mirror and glass from task 6 (delta lobes: sampled,
// never evaluated — f() and pdf() are 0 for them); rough conductor and rough
// plastic from task 8 (f, pdf and sample in the local frame). The task functions come
// in a BsdfLobes table (task_functions.h); estimators get their Bsdf from
// TraceContext::bsdf, which passes the linked tasks' table.
#pragma once

#include <optional>

#include "core/bsdf_sample.h"
#include "core/hit.h"
#include "core/scene.h"
#include "core/task_functions.h"
#include "util/frame.h"

namespace pathlab {

class Bsdf {
 public:
  Bsdf(const Material& material, const Hit& hit, const Vec3& wo, const BsdfLobes& lobes);

  // The shading normal, on the side of wo.
  const Vec3& normal() const { return frame_.n; }
  const Frame& frame() const { return frame_; }
  bool isDelta() const { return material_.isDelta(); }

  // f(wo, wi) for world-space unit directions; 0 for delta lobes.
  Color f(const Vec3& wo, const Vec3& wi) const;
  // Solid-angle density of sample() choosing wi; 0 for delta lobes.
  float pdf(const Vec3& wo, const Vec3& wi) const;
  // wi drawn from u in [0,1)^2; nothing if no direction can be sampled.
  std::optional<BsdfSample> sample(const Vec3& wo, Vec2 u) const;

 private:
  const Material& material_;
  const BsdfLobes* lobes_;
  Frame frame_;
  Frame outwardFrame_;
  Vec3 geometricNormal_;
};

}  // namespace pathlab
