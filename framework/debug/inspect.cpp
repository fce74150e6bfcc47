#include "debug/inspect.h"

#include <cmath>
#include <cstdio>

#include "core/bsdf.h"
#include "render/task_wiring.h"

namespace pathlab {
namespace {

std::string format(const char* pattern, auto... values) {
  char buffer[256];
  std::snprintf(buffer, sizeof buffer, pattern, values...);
  return buffer;
}

std::string vec(const Vec3& v) { return format("(%.3f, %.3f, %.3f)", double(v.x), double(v.y), double(v.z)); }

std::string describeHit(const Scene& scene, const TracedRay& traced) {
  if (!traced.hit) return "missed: background";
  const Hit& hit = traced.record;
  const Material& material = scene.materials[hit.material];
  std::string line = format("hit t=%.4g at ", double(hit.t)) + vec(hit.point) + " n=" + vec(hit.shadingNormal);
  line += format(" %s \"%s\", primitive %u", materialTypeName(material.type), material.name.c_str(), hit.primitive);
  if (material.isEmissive()) line += ", emissive";
  return line;
}

std::string mediumName(const Scene& scene, MediumIndex medium) {
  return medium == kVacuum ? std::string("vacuum") : "medium \"" + scene.media[size_t(medium)].name + "\"";
}

bool startsAt(const Ray& ray, const Point3& point) {
  return glm::length(ray.origin - point) <= 1e-3f * (1.0f + glm::length(point));
}

// Describes the rays of one sample. A bounce ray's direction was chosen by
// the BSDF at the previous hit: its pdf and f are evaluated there. In a
// scene with media (task 12) a ray may also start in mid-air on the ray
// before it (a scattering event: its direction from the phase function), or
// go straight on through an interface (no bounce: the medium changes); a
// shadow ray passes interfaces in pieces.
std::vector<std::string> describeRays(const Scene& scene, const std::vector<TracedRay>& rays) {
  std::vector<std::string> lines;
  const bool hasMedia = !scene.media.empty();
  const TracedRay* lastHit = nullptr;  // the vertex the next bounce leaves from
  const TracedRay* lastRay = nullptr;  // the last path ray, hit or not
  MediumIndex medium = scene.medium;
  int bounce = 0;
  for (size_t i = 0; i < rays.size(); ++i) {
    const TracedRay& traced = rays[i];
    if (traced.shadow) {
      const float distance = traced.range.max;
      // A shadow ray's closest hit is recorded where media need it (record.t finite).
      const bool throughInterface = hasMedia && traced.hit && std::isfinite(traced.record.t) &&
                                    scene.materials[traced.record.material].type == MaterialType::Interface;
      // Where media are: a piece past an interface, or a sample from a scattering point.
      std::string from = "light sample";
      const TracedRay* previous = i > 0 ? &rays[i - 1] : nullptr;
      if (hasMedia && previous && previous->shadow && std::isfinite(previous->record.t) &&
          startsAt(traced.ray, previous->record.point)) {
        from = "  on past it";
      } else if (hasMedia && lastRay && !(lastRay->hit && startsAt(traced.ray, lastRay->record.point))) {
        from = format("light sample from a scattering point at t=%.4g on the ray above",
                      double(glm::dot(traced.ray.origin - lastRay->ray.origin, lastRay->ray.direction)));
      }
      lines.push_back("  " + from + ": direction " + vec(traced.ray.direction) +
                      (std::isfinite(distance) ? format(", distance %.4g", double(distance)) : std::string(", to infinity")) +
                      (throughInterface ? format(": through an interface at t=%.4g, on", double(traced.record.t))
                                        : traced.hit ? std::string(": BLOCKED") : std::string(": reached the light")));
      continue;
    }
    std::string line;
    if (i == 0) {
      line = "camera ray: o=" + vec(traced.ray.origin) + " d=" + vec(traced.ray.direction) + ", ";
    } else if (hasMedia && lastRay && !(lastHit && startsAt(traced.ray, lastHit->record.point))) {
      // Scattered in the medium, on the previous path ray.
      ++bounce;
      const float t = glm::dot(traced.ray.origin - lastRay->ray.origin, lastRay->ray.direction);
      const float g = medium == kVacuum ? 0.0f : scene.media[size_t(medium)].g;
      line = format("bounce %d: scattered in ", bounce) + mediumName(scene, medium) +
             format(" at t=%.4g, phase sample wi=", double(t)) + vec(traced.ray.direction) +
             format(" cos=%.3f (g=%.2f), ", double(glm::dot(lastRay->ray.direction, traced.ray.direction)), double(g));
    } else if (hasMedia && lastHit && scene.materials[lastHit->record.material].type == MaterialType::Interface) {
      medium = scene.mediumAcross(lastHit->record, traced.ray.direction, medium);
      line = "  through the interface into " + mediumName(scene, medium) + ": ";
    } else {
      ++bounce;
      line = format("bounce %d: BSDF sample wi=", bounce) + vec(traced.ray.direction);
      if (lastHit) {
        const Hit& from = lastHit->record;
        const Vec3 wo = -lastHit->ray.direction;
        const Bsdf bsdf(scene.materials[from.material], from, wo, kLinkedTasks.lobes);
        if (bsdf.isDelta()) {
          line += " (delta lobe)";
        } else {
          const Color f = bsdf.f(wo, traced.ray.direction);
          line += format(" cos=%.3f pdf=%.4g f=", double(std::abs(glm::dot(from.shadingNormal, traced.ray.direction))),
                         double(bsdf.pdf(wo, traced.ray.direction))) + vec(f);
        }
        if (hasMedia) {
          const MediumIndex after = scene.mediumAcross(from, traced.ray.direction, medium);
          if (after != medium) line += ", into " + mediumName(scene, after);
          medium = after;
        }
      }
      line += ", ";
    }
    lines.push_back(line + describeHit(scene, traced));
    lastRay = &traced;
    if (traced.hit) lastHit = &traced;
  }
  return lines;
}

}  // namespace

PixelInspection inspectPixel(const Scene& scene, const Accelerator& accelerator, const Lights& lights,
                             const RenderOptions& options, IVec2 pixel, int samples) {
  PixelInspection inspection;
  inspection.pixel = pixel;
  const CameraBasis basis = cameraBasis(scene.camera);
  TraceContext context(scene, accelerator, lights, kLinkedTasks.lobes);
  context.pixel = pixel;
  Color sum(0.0f);
  for (int s = 0; s < samples; ++s) {
    InspectedSample sample;
    sample.index = uint32_t(s);
    context.log = &sample.rays;
    sample.radiance = estimatePixelSample(context, options, basis, sample.index);
    sample.finite = isFinite(sample.radiance);
    // The camera ray starts on the image plane; recover the raster position
    // from the same random numbers the render used.
    Sampler sampler = pixelSampler(scene.render, pixel, sample.index, options.sampler);
    sample.raster = pixelSamplePosition(pixel, sampler.next2D());
    sample.lines = describeRays(scene, sample.rays);
    if (sample.finite) {
      sum += sample.radiance;
    } else {
      ++inspection.nonFinite;
    }
    inspection.samples.push_back(std::move(sample));
  }
  // The render counts a non-finite sample as a sample of zero.
  if (samples > 0) inspection.mean = sum / float(samples);
  return inspection;
}

std::string formatInspection(const PixelInspection& inspection) {
  std::string text = format("pixel %d,%d: %zu samples, mean ", inspection.pixel.x, inspection.pixel.y,
                            inspection.samples.size()) + vec(inspection.mean);
  if (inspection.nonFinite > 0) text += format(", %d NaN/Inf samples", inspection.nonFinite);
  text += "\n";
  for (const InspectedSample& sample : inspection.samples) {
    text += format("sample %u at (%.3f, %.3f): L = ", sample.index, double(sample.raster.x), double(sample.raster.y)) +
            vec(sample.radiance) + (sample.finite ? "" : "  NaN/Inf!") + "\n";
    for (const std::string& line : sample.lines) text += "  " + line + "\n";
  }
  return text;
}

}  // namespace pathlab
