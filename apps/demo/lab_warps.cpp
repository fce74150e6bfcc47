// The sampling lab's warps: the recitation's examples (each with the
// classic mistake a parameter switches on, for the lecture), then every
// sampling routine of tasks 1, 4, 5, 6 and 7, called as this build links
// them (the student's files, or the reference).
#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>

#include "demo_support.h"
#include "lab.h"
#include "tasks/camera_rays.h"
#include "tasks/direct_lighting.h"
#include "tasks/environment.h"
#include "tasks/mirror_glass.h"
#include "tasks/path_tracing.h"

namespace pathlab::lab {

using demo::count;
using demo::Values;

namespace {

constexpr double kPi = std::numbers::pi;

// A pdf evaluated point by point.
std::function<std::vector<double>(const std::vector<Vec3>&)> pointwise(std::function<double(const Vec3&)> pdf) {
  return [pdf](const std::vector<Vec3>& points) {
    std::vector<double> values;
    values.reserve(points.size());
    for (const Vec3& p : points) values.push_back(pdf(p));
    return values;
  };
}

// ---- The recitation's examples -------------------------------------------

Warp pdfCdfWarp() {
  return {"pdf-cdf", "seed", "f(x) = 0.6(x-1)^3 - 0.3x^2 - 0.1x + 1 on [0, 2] by inverting its CDF",
          {{"mistake", 0, 0, 1, true, false, "1: invert an unnormalised CDF, 1.2 F (x = F^-1(u / 1.2))"}},
          [](const Values& p) {
            const bool mistake = count(p, "mistake") == 1;
            WarpSetup s;
            s.domain = Domain::Interval;
            s.lo = {0.0f, 0.0f}, s.hi = {2.0f, 1.0f};
            s.sample = [mistake](Vec2 u) -> std::optional<Vec3> {
              return Vec3(float(demo::invertExampleCdf(mistake ? u.x / 1.2 : u.x)), 0.0f, 0.0f);
            };
            s.pdf = pointwise([](const Vec3& x) { return demo::examplePdf(x.x); });
            s.mismatchMeans = "the CDF inverted is not the pdf's (not normalised to 1 at the end, or a wrong antiderivative)";
            return s;
          }};
}

Warp annulusWarp() {
  return {"annulus", "seed", "uniform points in an annulus: r = sqrt(q r2^2 + (1 - q) r1^2), phi = 2 pi u",
          {{"r1", 0.3, 0.0, 0.95, false, false, "inner radius"},
           {"r2", 1.0, 0.1, 1.0, false, false, "outer radius"},
           {"mistake", 0, 0, 1, true, false, "1: r = r1 + q (r2 - r1), uniform in r (the Jacobian r forgotten)"}},
          [](const Values& p) {
            const double r2 = p.at("r2"), r1 = std::min(p.at("r1"), 0.95 * r2);
            const bool mistake = count(p, "mistake") == 1;
            WarpSetup s;
            s.lo = Vec2(float(-r2)), s.hi = Vec2(float(r2));
            s.sample = [=](Vec2 u) -> std::optional<Vec3> {
              const double r = mistake ? r1 + u.x * (r2 - r1) : std::sqrt(u.x * r2 * r2 + (1.0 - u.x) * r1 * r1);
              const double phi = 2.0 * kPi * u.y;
              return Vec3(float(r * std::cos(phi)), float(r * std::sin(phi)), 0.0f);
            };
            s.pdf = pointwise([=](const Vec3& x) {
              const double r = std::hypot(double(x.x), double(x.y));
              return r >= r1 && r <= r2 ? 1.0 / (kPi * (r2 * r2 - r1 * r1)) : 0.0;
            });
            s.mismatchMeans = "the radius is not drawn by area: dA = r dr dphi, so r needs the square root";
            return s;
          }};
}

Warp uniformHemisphereWarp() {
  return {"uniform-hemisphere", "seed", "uniform directions on the hemisphere: cos theta = u1, phi = 2 pi u2",
          {{"mistake", 0, 0, 1, true, false, "1: theta = pi/2 u1, uniform in theta (sin theta forgotten)"}},
          [](const Values& p) {
            const bool mistake = count(p, "mistake") == 1;
            WarpSetup s;
            s.domain = Domain::Sphere;
            s.sample = [mistake](Vec2 u) -> std::optional<Vec3> {
              const double z = mistake ? std::cos(0.5 * kPi * u.x) : u.x, r = std::sqrt(std::max(0.0, 1.0 - z * z));
              const double phi = 2.0 * kPi * u.y;
              return Vec3(float(r * std::cos(phi)), float(r * std::sin(phi)), float(z));
            };
            s.pdf = pointwise([](const Vec3& w) { return w.z > 0.0f ? 1.0 / (2.0 * kPi) : 0.0; });
            s.mismatchMeans = "the density is in (theta, phi), not per solid angle: dw = sin theta dtheta dphi";
            return s;
          }};
}

Warp discreteWarp() {
  return {"discrete", "seed", "a discrete distribution by stacking its probabilities into CDF blocks",
          {{"mistake", 0, 0, 1, true, false, "1: the blocks from the weights without dividing by their sum"}},
          [](const Values& p) {
            const std::vector<double> weights = {1.0, 2.5, 0.5, 3.0, 2.0, 1.0};
            double total = 0.0;
            for (double w : weights) total += w;
            std::vector<double> cdf;
            double running = 0.0;
            const bool mistake = count(p, "mistake") == 1;
            for (double w : weights) cdf.push_back(running += mistake ? w / 5.0 : w / total);
            if (!mistake) cdf.back() = 1.0;
            WarpSetup s;
            s.domain = Domain::Discrete;
            for (size_t k = 0; k < weights.size(); ++k) s.outcomes.push_back(std::to_string(k));
            s.sample = [cdf](Vec2 u) -> std::optional<Vec3> {
              return Vec3(float(std::min(demo::sampleDiscrete(cdf, u.x), cdf.size() - 1)), 0.0f, 0.0f);
            };
            s.pdf = pointwise([weights, total](const Vec3& k) { return weights[size_t(k.x)] / total; });
            s.mismatchMeans = "the CDF does not end at 1 (weights not divided by their sum), or a block is off by one";
            return s;
          }};
}

// ---- Task 1 ------------------------------------------------------------------

Warp pixelSampleWarp() {
  return {"pixel-sample", "T1.1", "pixelSamplePosition: points in pixel (3, 7), drawn relative to its corner", {},
          [](const Values&) {
            WarpSetup s;
            s.lo = Vec2(-0.25f), s.hi = Vec2(1.25f);  // a margin: a sample outside the pixel shows
            s.sample = [](Vec2 u) -> std::optional<Vec3> {
              const Point2 p = pixelSamplePosition(IVec2(3, 7), u);
              return Vec3(p.x - 3.0f, p.y - 7.0f, 0.0f);
            };
            s.pdf = pointwise([](const Vec3& x) { return x.x >= 0.0f && x.x < 1.0f && x.y >= 0.0f && x.y < 1.0f ? 1.0 : 0.0; });
            s.mismatchMeans = "the sample is not pixel + u: an offset of half a pixel, or u scaled";
            return s;
          }};
}

// ---- Task 4 ------------------------------------------------------------------

Warp lightDirectionsWarp() {
  return {"light-directions", "T4.3",
          "lightDirection: points sampled by area on a square light, as directions with their solid-angle pdf",
          {{"height", 1.0, 0.05, 10.0, false, true, "the light's height above the shading point"},
           {"size", 1.0, 0.05, 10.0, false, true, "the light's side"},
           {"offset", 0.5, 0.0, 10.0, false, false, "the light's centre, sideways from straight above"}},
          [](const Values& p) {
            const float h = float(p.at("height")), side = float(p.at("size")), offset = float(p.at("offset"));
            // The light faces down (-z) towards the shading point at the origin.
            auto lightPoint = [=](Point3 point) {
              AreaSample a;
              a.point = point;
              a.normal = Vec3(0.0f, 0.0f, -1.0f);
              a.radiance = Color(1.0f);
              a.pdfArea = 1.0f / (side * side);
              return a;
            };
            WarpSetup s;
            s.domain = Domain::Sphere;
            s.sphereSubdivision = 32;  // the light's outline is a sharp edge of the pdf
            s.sample = [=](Vec2 u) -> std::optional<Vec3> {
              const Point3 point(offset + (u.x - 0.5f) * side, (u.y - 0.5f) * side, h);
              const std::optional<LightDirection> d = lightDirection(Point3(0.0f), lightPoint(point));
              if (!d) return std::nullopt;
              return d->wi;
            };
            s.pdf = pointwise([=](const Vec3& w) {
              if (!(w.z > 0.0f)) return 0.0;
              const Point3 hit = w * (h / w.z);
              if (std::abs(hit.x - offset) > 0.5f * side || std::abs(hit.y) > 0.5f * side) return 0.0;
              const std::optional<LightDirection> d = lightDirection(Point3(0.0f), lightPoint(hit));
              return d ? double(d->pdfSolidAngle) : 0.0;
            });
            s.mismatchMeans = "the area-to-solid-angle conversion: pdf = pdfArea r^2 / cos(theta') with the cosine "
                              "at the light";
            return s;
          }};
}

// ---- Task 5 ------------------------------------------------------------------

Warp cosineHemisphereWarp() {
  return {"cosine-hemisphere", "T5.1", "sampleDiffuseDirection against diffuseDirectionPdf (local frame, normal +z)", {},
          [](const Values&) {
            WarpSetup s;
            s.domain = Domain::Sphere;
            s.sample = [](Vec2 u) -> std::optional<Vec3> { return sampleDiffuseDirection(u); };
            s.pdf = pointwise([](const Vec3& w) { return double(diffuseDirectionPdf(w)); });
            s.mismatchMeans = "the pdf is not the sampler's: cosine sampling has pdf cos(theta) / pi (and 0 below "
                              "the horizon)";
            return s;
          }};
}

// ---- Task 6 ------------------------------------------------------------------

// The outcome of a delta BSDF sample: 0 reflection, 1 refraction.
int lobeOf(const Vec3& wo, const BsdfSample& s) { return s.wi.z * wo.z > 0.0f ? 0 : 1; }

Warp mirrorWarp() {
  return {"mirror", "T6.4", "sampleMirror: every sample the mirror direction of wo, reported with probability 1",
          {{"angle", 40.0, 0.0, 89.9, false, false, "incident angle from the normal, degrees"}},
          [](const Values& p) {
            const float theta = float(p.at("angle") * kPi / 180.0);
            const Vec3 wo(std::sin(theta), 0.0f, std::cos(theta)), mirrored(-wo.x, -wo.y, wo.z);
            // The probability the sample reports for the mirror direction (the lab's own, not reflect()'s).
            const BsdfSample first = sampleMirror(wo, Color(1.0f));
            const double reported = glm::length(first.wi - mirrored) < 1e-4f ? double(first.pdf) : 0.0;
            WarpSetup w;
            w.domain = Domain::Discrete;
            w.outcomes = {"the mirror direction", "elsewhere"};
            w.sample = [=](Vec2) -> std::optional<Vec3> {
              const BsdfSample s = sampleMirror(wo, Color(1.0f));
              if (!(s.pdf > 0.0f)) return std::nullopt;
              return Vec3(glm::length(s.wi - mirrored) < 1e-4f ? 0.0f : 1.0f, 0.0f, 0.0f);
            };
            w.pdf = pointwise([reported](const Vec3& k) { return k.x == 0.0f ? reported : 0.0; });
            w.mismatchMeans = "wi is not wo mirrored about the normal (-wo.x, -wo.y, wo.z), or its probability is not 1";
            return w;
          }};
}

Warp glassWarp() {
  return {"glass", "T6.5", "sampleGlass: how often each lobe is chosen against the probability it reports",
          {{"angle", 40.0, 0.0, 89.9, false, false, "incident angle from the normal, degrees"},
           {"ior", 1.5, 1.0, 3.0, false, false, "index of refraction"},
           {"inside", 0, 0, 1, true, false, "1: wo inside the glass (below the surface)"}},
          [](const Values& p) {
            const float theta = float(p.at("angle") * kPi / 180.0), ior = float(p.at("ior"));
            const float side = count(p, "inside") == 1 ? -1.0f : 1.0f;
            const Vec3 wo(std::sin(theta), 0.0f, side * std::cos(theta));
            // The probability each lobe reports, seen over a fine sweep of u.
            std::vector<double> reported(2, 0.0);
            for (int i = 0; i < 1000; ++i) {
              const BsdfSample s = sampleGlass(wo, Color(1.0f), Color(1.0f), ior, (float(i) + 0.5f) / 1000.0f);
              if (s.pdf > 0.0f) reported[size_t(lobeOf(wo, s))] = s.pdf;
            }
            WarpSetup w;
            w.domain = Domain::Discrete;
            w.outcomes = {"reflection", "refraction"};
            w.sample = [=](Vec2 u) -> std::optional<Vec3> {
              const BsdfSample s = sampleGlass(wo, Color(1.0f), Color(1.0f), ior, u.x);
              if (!(s.pdf > 0.0f)) return std::nullopt;
              return Vec3(float(lobeOf(wo, s)), 0.0f, 0.0f);
            };
            w.pdf = pointwise([reported](const Vec3& k) { return reported[size_t(k.x)]; });
            w.mismatchMeans = "the lobe is not chosen with the probability the sample reports (Fresnel F for "
                              "reflection, 1 - F for refraction; total internal reflection always reflects)";
            return w;
          }};
}

// ---- Task 7 ------------------------------------------------------------------

// The maps the lab offers: a sky with a sun (a hot spot), bright poles, a
// constant map, a single lit pixel.
Image labMap(int which) {
  constexpr int kWidth = 64, kHeight = 32;
  Image map(kWidth, kHeight, Color(which == 3 ? 0.0f : 1.0f));
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      Color& c = map.at(x, y);
      if (which == 0) c = Color(0.3f + 0.7f * float(y) / kHeight) + (x == 40 && y == 10 ? Color(2000.0f) : Color(0.0f));
      if (which == 1) c = Color(y == 0 || y == kHeight - 1 ? 50.0f : 0.5f);
    }
  if (which == 3) map.at(17, 9) = Color(1.0f);
  return map;
}

Warp environmentWarp() {
  return {"environment", "T7.5", "sampleEnvironment against environmentPdf over the sphere",
          {{"map", 0, 0, 3, true, false, "0 sky with a sun, 1 bright poles, 2 constant, 3 one lit pixel"}},
          [](const Values& p) {
            const auto distribution = std::make_shared<EnvironmentDistribution>(
                buildEnvironmentDistribution(labMap(count(p, "map"))));
            WarpSetup s;
            s.domain = Domain::Sphere;
            s.sphereSubdivision = 32;  // a piecewise-constant pdf: fine midpoints per cell
            s.sample = [distribution](Vec2 u) -> std::optional<Vec3> {
              const std::optional<EnvironmentSample> e = sampleEnvironment(*distribution, u);
              if (!e) return std::nullopt;
              return e->direction;
            };
            s.pdf = pointwise([distribution](const Vec3& w) { return double(environmentPdf(*distribution, w)); });
            s.mismatchMeans = "the pdf misses the Jacobian of the map: pdf = p(u, v) / (2 pi^2 sin theta); or the "
                              "CDF is off by one row or column";
            return s;
          }};
}

}  // namespace

const std::vector<Warp>& allWarps() {
  static const std::vector<Warp> warps = {pdfCdfWarp(),          annulusWarp(),         uniformHemisphereWarp(),
                                          discreteWarp(),        pixelSampleWarp(),     lightDirectionsWarp(),
                                          cosineHemisphereWarp(), mirrorWarp(),          glassWarp(),
                                          environmentWarp()};
  return warps;
}

}  // namespace pathlab::lab
