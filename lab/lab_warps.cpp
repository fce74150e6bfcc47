// The sampling lab's warps: the recitation's examples (each with the
// classic mistake a parameter switches on, for the lecture), then every
// task's (tasks/NN-name/lab_warps.cpp), called as this build links them.
#include "lab_support.h"

namespace pathlab::lab {
namespace {

Warp pdfCdfWarp() {
  return {"pdf-cdf", "seed", "f(x) = 0.6(x-1)^3 - 0.3x^2 - 0.1x + 1 on [0, 2] by inverting its CDF",
          {{"mistake", 0, 0, 1, true, false, "1: invert an unnormalised CDF, 1.2 F (x = F^-1(u / 1.2))"}},
          [](const Values& p, const WarpFiles&) {
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
          [](const Values& p, const WarpFiles&) {
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
          [](const Values& p, const WarpFiles&) {
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
          [](const Values& p, const WarpFiles&) {
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

}  // namespace

const std::vector<Warp>& allWarps() {
  static const std::vector<Warp> warps = [] {
    std::vector<Warp> all = {pdfCdfWarp(), annulusWarp(), uniformHemisphereWarp(), discreteWarp()};
    addTaskWarps(all);
    return all;
  }();
  return warps;
}

}  // namespace pathlab::lab
