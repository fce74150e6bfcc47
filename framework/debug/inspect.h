// The pixel inspector: re-trace one pixel's samples exactly as the render
// took them (same random numbers) and record every ray, hit, BSDF sample,
// light sample and contribution. The GUI lists it; `pathlab debug --task 5
// --view paths` prints it and draws the paths.
#pragma once

#include <string>
#include <vector>

#include "core/trace.h"
#include "render/render.h"

namespace pathlab {

struct InspectedSample {
  uint32_t index = 0;        // sample number within the pixel
  Point2 raster{0.0f};       // where in the image plane the camera ray starts
  Color radiance{0.0f};      // the sample's contribution to the pixel (before averaging)
  bool finite = true;        // false: NaN or Inf, left out of the image
  std::vector<TracedRay> rays;      // in the order traced: the camera ray first
  std::vector<std::string> lines;  // one line per ray, in words (hits, normals, BSDF and light samples)
};

struct PixelInspection {
  IVec2 pixel{0, 0};
  Color mean{0.0f};          // of the finite samples, as the render averages them
  int nonFinite = 0;
  std::vector<InspectedSample> samples;
};

// Samples 0 .. samples-1 of `pixel`; options.integrator picks the estimator.
PixelInspection inspectPixel(const Scene& scene, const Accelerator& accelerator, const Lights& lights,
                             const RenderOptions& options, IVec2 pixel, int samples);

// The whole inspection as text: a header, then each sample and its lines.
std::string formatInspection(const PixelInspection& inspection);

}  // namespace pathlab
