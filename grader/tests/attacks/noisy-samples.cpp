// attack: a path tracer that renders nothing, but whose samples in 7 pixels of every 4 x 4 block are +1e15 and
// -1e15 in turn: honestly tallied, an enormous variance in those pixels, which widened every block's
// tolerance until black passed (the judge's caps on the candidate's variance stop it: such a pixel is
// judged alone, and a render may hold only as many as a correct one's fireflies)
// task: 5  base: none  expect: 0
#include "tasks/path_tracing.h"

namespace pathlab {

Vec3 sampleDiffuseDirection(Vec2) { return Vec3(0.0f, 0.0f, 1.0f); }
float diffuseDirectionPdf(const Vec3&) { return 0.0f; }

Color tracePath(TraceContext& context, Ray, Sampler& sampler) {
  if ((context.pixel.y % 4) * 4 + context.pixel.x % 4 >= 7) return Color(0.0f);  // 7 pixels of every 4 x 4 block
  return Color(sampler.next1D() < 0.5f ? 1e15f : -1e15f);
}

}  // namespace pathlab
