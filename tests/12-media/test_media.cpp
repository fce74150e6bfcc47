// Autograder suite for task 12 — homogeneous participating media. Tests run
// from basic to advanced; the first failure is usually the root cause.
// candidate::f(...) is the student's f, computed in the candidate process
// (calls.h).
//
// No test pins a convention: any inversion of the exponential (ln u or
// ln(1 - u)), any way of turning the Henyey-Greenstein CDF into a direction
// (either end of u, any frame around the direction, any phi), any unbiased
// transmittance estimator (exact, or a free flight that passes or not), and
// any order of random numbers pass. Statistical checks: chi-square tests at
// alpha = 1e-5 each, means within 5 judged standard errors (5.7e-7 each);
// the samplers' inputs are stratified, so a correct sampler's counts are
// all but exact and those tests cannot fail it at all.
#include "suite/doctest_strings.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "calls.h"
#include "check.h"
#include "suite/grading.h"
#include "image_scenes.h"
#include "image_test.h"
#include "meshes.h"
#include "metamorphic.h"
#include "reference_noise.h"
#include "render_support.h"
#include "scene/scene_io.h"
#include "statistics.h"
#include "util/frame.h"

using namespace pathlab;
using namespace pathlab::test;

namespace {

constexpr double kChiSquareP = 1e-5;
constexpr double kPiD = std::numbers::pi;

// ---- the judge's own formulas, in double ------------------------------------

double hgPdf(double cosTheta, double g) {
  const double d = 1.0 + g * g - 2.0 * g * cosTheta;
  return (1.0 - g * g) / (4.0 * kPiD * d * std::sqrt(d));
}

// P(cos theta <= c) under Henyey-Greenstein (cos against the direction travelled).
double hgCdf(double c, double g) {
  if (std::abs(g) < 1e-9) return 0.5 * (c + 1.0);
  return (1.0 - g * g) / (2.0 * g) * (1.0 / std::sqrt(1.0 + g * g - 2.0 * g * c) - 1.0 / (1.0 + g));
}

// n stratified numbers in (0, 1), shuffled by a fixed permutation (a sampler
// may use u any way it likes; the set is what matters).
std::vector<float> stratified(int n) {
  std::vector<float> us(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) us[size_t(i)] = float((i + 0.5) / n);
  Random random = Random::fixed(5);
  for (int i = n - 1; i > 0; --i) std::swap(us[size_t(i)], us[size_t(random.uniform(0.0, i + 1.0 - 1e-9))]);
  return us;
}

// ---- scenes ------------------------------------------------------------------

MediumIndex addMedium(Scene& scene, float sigmaT, Color albedo, float g) {
  scene.media.push_back(Medium{"m" + std::to_string(scene.media.size()), sigmaT, albedo, g});
  return MediumIndex(scene.media.size() - 1);
}

uint32_t addInterface(Scene& scene, MediumIndex interior) {
  Material m;
  m.name = "interface " + std::to_string(interior);
  m.type = MaterialType::Interface;
  m.interior = interior;
  scene.materials.push_back(m);
  return uint32_t(scene.materials.size() - 1);
}

// A sphere of `medium` behind an interface, as an analytic sphere or a
// closed mesh (outward normals): both must bound a medium alike.
void addMediumSphere(Scene& scene, Point3 centre, float radius, MediumIndex medium, bool mesh) {
  const uint32_t material = addInterface(scene, medium);
  if (!mesh) {
    scene.spheres.push_back(Sphere{centre, radius, material});
    return;
  }
  TriangleMesh sphere = icosphere(4, centre, radius);
  sphere.material = material;
  scene.meshes.push_back(sphere);
}

// The length of a segment from o along unit d, up to `length`, inside a sphere.
double chordInside(DVec3 o, DVec3 d, double length, DVec3 centre, double radius) {
  const DVec3 oc = o - centre;
  const double b = glm::dot(oc, d), c = glm::dot(oc, oc) - radius * radius, disc = b * b - c;
  if (disc <= 0.0) return 0.0;
  const double t0 = std::max(0.0, -b - std::sqrt(disc)), t1 = std::min(length, -b + std::sqrt(disc));
  return std::max(0.0, t1 - t0);
}

}  // namespace

// ---- T12.1 ------------------------------------------------------------------

TEST_CASE("T12.1 free flight: distances follow exp(-sigmaT t), and the rest reach the surface" *
          grading(4, "invert the CDF 1 - exp(-sigmaT t): t = -ln(1 - u) / sigmaT; a flight that would end at or "
                     "past tMax reaches the surface instead (scattered false, t = tMax). Sampling with the wrong "
                     "coefficient, or without the surface, shows as a skewed histogram")) {
  constexpr int kN = 20000, kBins = 16;
  const std::vector<float> us = stratified(kN);
  struct Case {
    float sigmaT, tMax;
  };
  for (const Case c : {Case{1.0f, kInfinity}, Case{2.5f, 0.6f}, Case{0.3f, 2.0f}, Case{40.0f, 0.05f}, Case{0.02f, 3.0f}}) {
    std::vector<calls::FlightQuery> queries;
    for (float u : us) queries.emplace_back(c.sigmaT, c.tMax, u);
    const std::vector<FreeFlight> flights = candidate::sampleFreeFlight(queries);
    HINT("sampleFreeFlight must return one flight per query it was given");
    REQUIRE(flights.size() == queries.size());
    // kBins bins of equal probability among the flights that scatter, and one for those that pass.
    const double pass = std::isinf(c.tMax) ? 0.0 : std::exp(-double(c.sigmaT) * double(c.tMax));
    std::vector<double> observed(kBins + 1, 0.0), expected(kBins + 1, (1.0 - pass) * kN / kBins);
    expected[kBins] = pass * kN;
    int bad = 0;
    std::string example;
    for (size_t i = 0; i < flights.size(); ++i) {
      const FreeFlight& f = flights[i];
      if (f.scattered && f.t >= 0.0f && f.t < c.tMax) {
        const double p = -std::expm1(-double(c.sigmaT) * double(f.t)) / (1.0 - pass);  // P(T <= t | scattered)
        observed[size_t(std::clamp(int(p * kBins), 0, kBins - 1))] += 1.0;
      } else if (!f.scattered && (f.t == c.tMax || std::abs(f.t - c.tMax) <= 1e-6f * c.tMax)) {
        observed[kBins] += 1.0;
      } else if (bad++ == 0) {
        example = "u = " + std::to_string(us[i]) + " gave t = " + std::to_string(f.t) + ", scattered " +
                  (f.scattered ? "true" : "false");
      }
    }
    CAPTURE(c.sigmaT);
    CAPTURE(c.tMax);
    INFO("flights that scatter must end in [0, tMax), the others at tMax exactly; " << bad << " did not ("
                                                                                    << example << ")");
    HINT("a flight that scatters ends in [0, tMax); one that does not reaches the surface: scattered false and t = "
         "tMax exactly (a flight that would end at or past tMax reaches the surface instead)");
    CHECK(bad == 0);
    const ChiSquareResult r = chiSquareTest(observed, expected);
    HINT("the distances do not follow exp(-sigmaT t): invert the CDF 1 - exp(-sigmaT t), t = -ln(1 - u) / sigmaT "
         "(or -ln(u) / sigmaT), with this query's sigmaT; too many or too few reaching the surface means the "
         "surface's probability exp(-sigmaT tMax) is off");
    INFO("distances against exp(-sigmaT t), " << kBins << " bins of equal probability and one for the surface: chi2 "
                                               << r.statistic << ", p = " << r.pValue << "; " << observed[kBins]
                                               << " reached the surface, expected " << expected[kBins] << " " << r.failure);
    CHECK(r.pValue >= kChiSquareP);
  }
}

TEST_CASE("T12.1 free flight: the pdf is the density at t, or the probability of reaching the surface" *
          grading(2, "scattered: pdf = sigmaT exp(-sigmaT t), the density of the t you returned; at the surface: "
                     "pdf = exp(-sigmaT tMax), the probability of getting there")) {
  const std::vector<float> us = stratified(2000);
  for (const float sigmaT : {0.5f, 3.0f, 60.0f}) {
    for (const float tMax : {0.25f, 2.0f, kInfinity}) {
      std::vector<calls::FlightQuery> queries;
      for (float u : us) queries.emplace_back(sigmaT, tMax, u);
      const std::vector<FreeFlight> flights = candidate::sampleFreeFlight(queries);
      HINT("sampleFreeFlight must return one flight per query it was given");
      REQUIRE(flights.size() == queries.size());
      int bad = 0;
      std::string example;
      for (const FreeFlight& f : flights) {
        const double expected = f.scattered ? double(sigmaT) * std::exp(-double(sigmaT) * double(f.t))
                                            : std::exp(-double(sigmaT) * double(tMax));
        if (!(std::abs(double(f.pdf) - expected) <= 1e-4 * expected + 1e-30) && bad++ == 0) {
          example = std::string(f.scattered ? "scattered" : "at the surface") + " at t = " + std::to_string(f.t) +
                    ": pdf " + std::to_string(f.pdf) + ", expected " + std::to_string(expected);
        }
      }
      CAPTURE(sigmaT);
      CAPTURE(tMax);
      INFO(bad << " of " << flights.size() << " pdfs wrong (" << example << ")");
      HINT("the pdf must be the probability of what you returned: sigmaT exp(-sigmaT t) at the t of a flight that "
           "scattered, exp(-sigmaT tMax) for one that reached the surface (the example says which)");
      CHECK(bad == 0);
    }
  }
}

TEST_CASE("T12.1 free flight: thin and dense media, a surface at 0, u at the ends of [0, 1)" *
          grading(1, "no t may be NaN, infinite (unless tMax is) or negative: mind ln(0) at u = 0 (use 1 - u, or "
                     "log1p(-u)), and a surface at distance 0 is always reached")) {
  std::vector<calls::FlightQuery> queries;
  for (const float sigmaT : {1e-5f, 1.0f, 1e5f})
    for (const float tMax : {0.0f, 1e-3f, 1.0f, 1e4f})
      for (const float u : {0.0f, 1e-7f, 0.5f, 1.0f - 1e-7f, 0.99999994f}) queries.emplace_back(sigmaT, tMax, u);
  const std::vector<FreeFlight> flights = candidate::sampleFreeFlight(queries);
  HINT("sampleFreeFlight must return one flight per query it was given");
  REQUIRE(flights.size() == queries.size());
  for (size_t i = 0; i < flights.size(); ++i) {
    // (Not structured bindings: Clang 14 cannot capture one in CAPTURE's lambda.)
    const float sigmaT = std::get<0>(queries[i]), tMax = std::get<1>(queries[i]), u = std::get<2>(queries[i]);
    const FreeFlight& f = flights[i];
    CAPTURE(sigmaT);
    CAPTURE(tMax);
    CAPTURE(u);
    CAPTURE(f.t);
    CAPTURE(f.scattered);
    CAPTURE(f.pdf);
    HINT("t must be finite and in [0, tMax] at every u: ln(0) at u = 0 (use 1 - u, or log1p(-u)) gives an "
         "infinite t, and a flight past tMax must stop at the surface");
    CHECK(std::isfinite(f.t));
    CHECK(f.t >= 0.0f);
    CHECK(f.t <= tMax);
    HINT("the pdf must be finite and not negative at every u, in thin and dense media alike");
    CHECK(std::isfinite(f.pdf));
    CHECK(f.pdf >= 0.0f);
    // A pdf of 0 is honest only for a surface whose probability underflows
    // (-ln(u) at u = 0 reaches it; the exponentials cancel in the weight).
    HINT("a pdf of 0 says the flight could not happen: only a surface whose probability exp(-sigmaT tMax) "
         "underflows may have it");
    if (f.scattered || std::exp(-double(sigmaT) * double(tMax)) > 1e-30) CHECK(f.pdf > 0.0f);
    HINT("a surface at distance 0 is always reached: no flight can scatter before it");
    if (tMax == 0.0f) CHECK_FALSE(f.scattered);
    // Where the surface is out of reach (exp(-sigmaT tMax) < 1e-30), every u
    // away from the ends of [0, 1) scatters, whichever end of it a sampler
    // maps to short flights.
    HINT("in a dense medium whose surface is out of reach (exp(-sigmaT tMax) < 1e-30) every flight scatters: a "
         "flight that reached the surface there has a t that overflowed or a comparison the wrong way round");
    if (sigmaT * tMax > 70.0f && u >= 1e-7f && u <= 1.0f - 1e-7f) CHECK(f.scattered);
  }
}

// ---- T12.2 ------------------------------------------------------------------

TEST_CASE("T12.1 metamorphic: a medium 2^20 times thinner over a distance 2^20 times longer gives the same flights, scaled" *
          grading(1, "only the optical depth sigmaT t matters: t = -ln(1 - u) / sigmaT scales with 1 / sigmaT, the "
                     "density sigmaT exp(-sigmaT t) with sigmaT, the probability of passing not at all; no fixed "
                     "epsilon on t, sigmaT or their product")) {
  // The relation (docs/metamorphic.md): sigmaT / k and tMax k (k a power of
  // two: every float scaled exactly) give each u the flight t k, with the
  // density / k when it scatters and the same probability when it passes.
  // Beside it, the truth: each answer's pdf is sigmaT exp(-sigmaT t) at its
  // own t, or exp(-sigmaT tMax) for a pass.
  std::vector<calls::FlightQuery> base;
  Random random(121);
  for (int i = 0; i < 2000; ++i) {
    base.emplace_back(float(std::exp(random.uniform(-3.0, 3.0))), float(std::exp(random.uniform(-2.0, 2.0))),
                      float(random.uniform()));
  }
  const std::vector<FreeFlight> before = candidate::sampleFreeFlight(base);
  HINT("sampleFreeFlight must return one flight per query it was given");
  REQUIRE(before.size() == base.size());
  int untrue = 0;
  for (size_t i = 0; i < base.size(); ++i) {
    const auto [sigma, tMax, u] = base[i];
    const FreeFlight& f = before[i];
    const double truth = f.scattered ? double(sigma) * std::exp(-double(sigma) * f.t) : std::exp(-double(sigma) * tMax);
    if (!(std::abs(double(f.pdf) - truth) <= 1e-4 * truth) || (f.scattered && !(f.t >= 0.0f && f.t < tMax))) ++untrue;
  }
  INFO(untrue << " of " << base.size() << " flights have a pdf that is not sigmaT exp(-sigmaT t) (or exp(-sigmaT tMax) "
              << "for a pass), or a scattering t outside [0, tMax)");
  HINT("the relation below compares your flights with themselves, so they must first be right: a scattering "
       "flight's pdf is sigmaT exp(-sigmaT t) at its t in [0, tMax), a pass's is exp(-sigmaT tMax)");
  REQUIRE(untrue == 0);
  for (const float k : {0x1p-20f, 0x1p20f}) {
    std::vector<calls::FlightQuery> scaled;
    for (const auto& [sigma, tMax, u] : base) scaled.emplace_back(sigma / k, tMax * k, u);
    const std::vector<FreeFlight> after = candidate::sampleFreeFlight(scaled);
    HINT("sampleFreeFlight must return one flight per query it was given");
    REQUIRE(after.size() == base.size());
    int differing = 0;
    for (size_t i = 0; i < base.size(); ++i) {
      const FreeFlight &a = before[i], &b = after[i];
      const bool same = a.scattered == b.scattered && std::abs(double(b.t) - double(a.t) * k) <= 1e-5 * double(a.t) * k &&
                        std::abs(double(b.pdf) - double(a.pdf) / (a.scattered ? k : 1.0f)) <= 1e-5 * double(b.pdf);
      if (!same) ++differing;
    }
    CAPTURE(k);
    INFO(differing << " of " << base.size() << " flights change when sigmaT is divided by k and tMax multiplied by it");
    HINT("a flight must depend on the optical depth alone: with sigmaT / k and tMax k each u gives t k, its density "
         "/ k, and the same probability of passing; a fixed epsilon on t or sigmaT, or t computed as -ln(1 - u) "
         "sigmaT, breaks that");
    CHECK(differing == 0);
  }
}

TEST_CASE("T12.2 phase: Henyey-Greenstein's value, a density over the sphere" *
          grading(2, "p = (1 - g^2) / (4 pi (1 + g^2 - 2 g cos)^1.5) with cos between the direction travelled and "
                     "the new one: g > 0 is onwards. pbrt's cosine against the direction back flips g")) {
  std::vector<calls::PhaseQuery> queries;
  for (const float g : {-0.9f, -0.5f, -0.1f, 0.0f, 0.2f, 0.7f, 0.95f})
    for (int i = 0; i <= 100; ++i) queries.emplace_back(-1.0f + 0.02f * float(i), g);
  const std::vector<float> values = candidate::henyeyGreenstein(queries);
  HINT("henyeyGreenstein must return one value per query it was given");
  REQUIRE(values.size() == queries.size());
  for (size_t i = 0; i < values.size(); ++i) {
    const float cosTheta = std::get<0>(queries[i]), g = std::get<1>(queries[i]);
    const double expected = hgPdf(cosTheta, g);
    CAPTURE(cosTheta);
    CAPTURE(g);
    CAPTURE(values[i]);
    CAPTURE(expected);
    HINT("p = (1 - g^2) / (4 pi (1 + g^2 - 2 g cos)^1.5), cos between the direction travelled and the new one (g > 0 "
         "is onwards; a cosine against the direction back flips g), normalised over the sphere (the 4 pi)");
    CHECK(std::abs(double(values[i]) - expected) <= 1e-4 * expected);
  }
}

TEST_CASE("T12.2 phase sampling: directions against the Henyey-Greenstein pdf, and their mean cosine is g" *
          grading(4, "invert the CDF of cos theta (cos = (1 + g^2 - s^2) / 2g, s = (1 - g^2) / (1 - g + 2 g u)), "
                     "phi uniform, and build the direction around the one travelled (Frame::fromNormal): the "
                     "histogram of cosines must follow p, and their mean is g")) {
  constexpr int kN = 40000, kCosBins = 20, kPhiBins = 8;
  const std::vector<Vec2> us = uniformPoints(kN, 61);
  Random random(61);
  for (const float g : {-0.8f, -0.3f, 0.0f, 0.4f, 0.9f}) {
    const DVec3 travel = random.unitVector();
    std::vector<calls::PhaseSampleQuery> queries;
    for (const Vec2& u : us) queries.emplace_back(Vec3(travel), g, u);
    const std::vector<Vec3> directions = candidate::sampleHenyeyGreenstein(queries);
    HINT("sampleHenyeyGreenstein must return one direction per query it was given");
    REQUIRE(directions.size() == queries.size());
    // Cells of equal probability in cos theta, times equal ranges of phi in the judge's own frame.
    const Frame frame = Frame::fromNormal(Vec3(travel));
    std::vector<double> observed(kCosBins * kPhiBins, 0.0), expected(kCosBins * kPhiBins, double(kN) / (kCosBins * kPhiBins));
    MeanEstimate cosine;
    int notUnit = 0;
    for (const Vec3& w : directions) {
      const DVec3 d(w);
      if (!(std::abs(glm::length(d) - 1.0) <= 1e-4)) {
        ++notUnit;
        continue;
      }
      const double c = std::clamp(glm::dot(d, travel), -1.0, 1.0);
      cosine.add(c);
      const double phi = std::atan2(double(glm::dot(w, frame.t)), double(glm::dot(w, frame.s))) + kPiD;
      const int i = std::clamp(int(hgCdf(c, g) * kCosBins), 0, kCosBins - 1);
      const int j = std::clamp(int(phi / (2.0 * kPiD) * kPhiBins), 0, kPhiBins - 1);
      observed[size_t(i * kPhiBins + j)] += 1.0;
    }
    CAPTURE(g);
    INFO(notUnit << " of " << kN << " directions not unit (or not finite)");
    HINT("every sampled direction must be a finite unit vector: sin theta = sqrt(max(0, 1 - cos^2)), and g = 0 "
         "handled apart (the inverted CDF divides by g)");
    CHECK(notUnit == 0);
    const ChiSquareResult r = chiSquareTest(observed, expected);
    HINT("the directions do not follow Henyey-Greenstein: the cosines must come from the inverted CDF of cos theta, "
         "phi uniform in [0, 2 pi), and the direction built around the one travelled (a frame of it)");
    INFO("chi-square of (cos theta, phi) against Henyey-Greenstein: chi2 " << r.statistic << ", p = " << r.pValue
                                                                           << " " << r.failure);
    CHECK(r.pValue >= kChiSquareP);
    // A cosine lies in [-1, 1]: with mean g its variance is at most
    // (1 - g)(1 + g) (Bhatia and Davis), whatever the sampler.
    cosine.setVarianceCeiling((1.0 - g) * (1.0 + g), "values in [-1, 1] with mean g: (1 - g)(1 + g)");
    INFO("mean cosine with the direction travelled: " << cosine.describe(g));
    HINT("the mean cosine with the direction travelled must be g: a mean of -g builds the direction around the "
         "direction back");
    CHECK(cosine.agrees(g));
  }
}

// ---- T12.3 ------------------------------------------------------------------

namespace {

// The candidate's transmittance for each query, kCalls times each (its own
// random streams), judged against `expected`: values in [0, 1], the mean
// within 5 standard errors of the judge's value, with a variance of at most
// T (1 - T), the most an estimator with values in [0, 1] and mean T can have.
void checkTransmittance(const Scene& scene, const std::vector<calls::TransmittanceQuery>& queries,
                        const std::vector<double>& expected, const std::string& what) {
  constexpr int kCalls = 20000;
  std::vector<calls::TransmittanceQuery> all;
  for (const auto& q : queries)
    for (int k = 0; k < kCalls; ++k) {
      auto copy = q;
      std::get<3>(copy) = uint32_t(k);
      std::get<4>(copy) = testSeed(std::get<4>(q));
      all.push_back(copy);
    }
  const std::vector<float> values = candidate::transmittance(scene, all);
  HINT("transmittance must return one value per query it was given");
  REQUIRE(values.size() == all.size());
  for (size_t q = 0; q < queries.size(); ++q) {
    const double t = expected[q];
    MeanEstimate m;
    int outside = 0, notZero = 0;
    for (int k = 0; k < kCalls; ++k) {
      const float v = values[q * kCalls + size_t(k)];
      if (!(v >= 0.0f && v <= 1.0f)) ++outside;
      if (v != 0.0f) ++notZero;
      m.add(std::isfinite(v) ? double(v) : 1e30);
    }
    m.setVarianceCeiling(std::max(t * (1.0 - t), 1e-12), "values in [0, 1] with mean T: T (1 - T)");
    const Ray& ray = std::get<0>(queries[q]);
    CAPTURE(what);
    INFO("ray from " << str(ray.origin) << " along " << str(ray.direction) << ", length " << std::get<1>(queries[q])
                     << ", starting in medium " << std::get<2>(queries[q]));
    INFO(outside << " of " << kCalls << " values outside [0, 1]");
    HINT("a transmittance is a fraction of light: every value must lie in [0, 1] (a NaN or a negative exponent "
         "fails here)");
    CHECK(outside == 0);
    // Past a surface nothing gets through: an estimator that is never
    // negative and has mean 0 is 0 on every call, whatever its method.
    if (t == 0.0) {
      INFO(notZero << " of " << kCalls << " values are not exactly 0 where a surface blocks the ray");
      HINT("past an opaque surface nothing gets through: a surface that is not an interface (no medium change) "
           "makes the transmittance 0");
      CHECK(notZero == 0);
    }
    INFO(m.describe(t));
    // An exact estimator has no noise to hide in: the rays' offsets at each
    // interface (a few 1e-5 along the ray) shift its value by about 1e-4 of T.
    HINT("the transmittance's mean must be exp(-sum of sigmaT d) over the media along the ray: each interface "
         "crossed changes the medium (scene.mediumAcross), and the segment's length counts only up to the "
         "query's distance");
    CHECK((m.agrees(t) || std::abs(m.mean() - t) <= 1e-3 * t));
  }
}

}  // namespace

TEST_CASE("T12.3 transmittance: exp(-sigmaT d) in a fog, through interfaces into other media, 0 past a surface" *
          grading(4, "multiply exp(-sigmaT length) over each stretch, in the medium of that stretch; go on past an "
                     "interface (scene.mediumAcross gives the medium beyond it); stop with 0 at any other surface")) {
  // A fog everywhere; no surfaces.
  {
    Scene scene;
    scene.medium = addMedium(scene, 0.7f, Color(0.5f), 0.3f);
    std::vector<calls::TransmittanceQuery> q;
    std::vector<double> expected;
    for (const float d : {0.05f, 1.0f, 3.0f, kInfinity}) {
      q.emplace_back(Ray{Point3(1, 2, 3), glm::normalize(Vec3(0.3f, -1, 0.2f))}, d, scene.medium, 0u, 301u);
      expected.push_back(std::exp(-0.7 * double(d)));
    }
    checkTransmittance(scene, q, expected, "a fog of sigmaT 0.7, no surfaces");
  }
  // Spheres of medium in a vacuum, and in a fog of another medium: an analytic sphere and a mesh.
  for (const bool fog : {false, true}) {
    Scene scene;
    const MediumIndex inside = addMedium(scene, 1.3f, Color(0.9f), 0.0f);
    if (fog) scene.medium = addMedium(scene, 0.25f, Color(0.9f), 0.5f);
    addMediumSphere(scene, Point3(0, 0, 0), 1.0f, inside, false);
    addMediumSphere(scene, Point3(3, 0, 0), 0.8f, inside, true);
    std::vector<calls::TransmittanceQuery> q;
    std::vector<double> expected;
    const double outsideSigma = fog ? 0.25 : 0.0;
    for (const double y : {0.0, 0.5, 0.75, 0.95}) {
      const DVec3 o(-2.0, y, 0.1), d = glm::normalize(DVec3(1.0, 0.0, 0.0));
      const double length = 6.0;
      const double a = chordInside(o, d, length, DVec3(0.0), 1.0);
      // The mesh's chord: the icosphere is not the sphere; the judge measures it on the mesh itself.
      q.emplace_back(Ray{Point3(o), Vec3(d)}, float(length), scene.medium, 0u, 302u);
      expected.push_back(a);  // finished below
    }
    // From inside the first sphere, out through it and into the fog.
    q.emplace_back(Ray{Point3(0, 0, 0), Vec3(0, 1, 0)}, 2.5f, inside, 0u, 303u);
    expected.push_back(1.0);
    // The mesh's chords, measured with the judge's own hits.
    Rig rig(scene);
    TraceContext context = rig.context();
    for (size_t i = 0; i < q.size(); ++i) {
      const Ray& ray = std::get<0>(q[i]);
      const float length = std::get<1>(q[i]);
      double inMedium = 0.0;
      bool in = std::get<2>(q[i]) == inside;
      float at = 0.0f;
      for (int k = 0; k < 16; ++k) {
        const std::optional<Hit> hit = context.intersect(ray, Interval{at, length});
        const float next = hit ? hit->t : length;
        if (in) inMedium += next - at;
        if (!hit) break;
        in = glm::dot(ray.direction, hit->geometricNormal) < 0.0f;
        at = next * (1.0f + 1e-6f) + 1e-6f;
      }
      expected[i] = std::exp(-1.3 * inMedium - outsideSigma * (double(length) - inMedium));
    }
    checkTransmittance(scene, q, expected,
                       fog ? "spheres of sigmaT 1.3 in a fog of 0.25" : "spheres of sigmaT 1.3 in a vacuum");
  }
  // Surfaces that block: a diffuse wall, and glass (light through glass is no shadow ray's business).
  {
    Scene scene;
    scene.medium = addMedium(scene, 0.4f, Color(1.0f), 0.0f);
    addQuad(scene, Point3(2, -5, -5), Vec3(0, 10, 0), Vec3(0, 0, 10), addMaterial(scene, Color(0.5f)));
    Material glass;
    glass.type = MaterialType::Glass;
    glass.interior = addMedium(scene, 2.0f, Color(1.0f), 0.0f);
    scene.materials.push_back(glass);
    scene.spheres.push_back(Sphere{Point3(0, 5, 0), 1.0f, uint32_t(scene.materials.size() - 1)});
    std::vector<calls::TransmittanceQuery> q = {
        {Ray{Point3(0, 0, 0), Vec3(1, 0, 0)}, 4.0f, scene.medium, 0u, 304u},
        {Ray{Point3(0, 0, 0), Vec3(0, 1, 0)}, 8.0f, scene.medium, 0u, 305u},
        {Ray{Point3(0, 0, 0), Vec3(1, 0, 0)}, 1.5f, scene.medium, 0u, 306u}};
    checkTransmittance(scene, q, {0.0, 0.0, std::exp(-0.4 * 1.5)}, "a wall at x = 2 and a glass ball at y = 5");
  }
  // To infinity (towards the sky) out of a sphere of medium in a vacuum: past
  // its interface the ray goes on, and a wall beyond still blocks it.
  {
    Scene scene;
    addMediumSphere(scene, Point3(0, 0, 0), 1.0f, addMedium(scene, 1.3f, Color(0.9f), 0.0f), false);
    addQuad(scene, Point3(2, -5, -5), Vec3(0, 10, 0), Vec3(0, 0, 10), addMaterial(scene, Color(0.5f)));
    const MediumIndex inside = 0;
    std::vector<calls::TransmittanceQuery> q = {{Ray{Point3(0, 0, 0), Vec3(1, 0, 0)}, kInfinity, inside, 0u, 307u},
                                                {Ray{Point3(0, 0, 0), Vec3(0, 1, 0)}, kInfinity, inside, 0u, 308u}};
    checkTransmittance(scene, q, {0.0, std::exp(-1.3)}, "a sphere of sigmaT 1.3, radius 1, and a wall at x = 2");
  }
}

TEST_CASE("T12.3 metamorphic: media spheres 1024 times larger with sigmaT / 1024, or reordered, give the same transmittance" *
          grading(1, "transmittance depends on the optical depth alone: nothing may be fixed in absolute units of "
                     "length, and the media are found from the surfaces crossed, whatever their order")) {
  // The relation (docs/metamorphic.md): lengths times 1024 with extinction
  // / 1024 (every float scaled exactly) keep each optical depth, so each
  // query's answer, from the same random numbers, is the same; so does the
  // scene with its spheres in reverse order. Beside it, the truth: in a fog
  // without surfaces, exp(-sigmaT d).
  {
    Scene fog;
    fog.medium = addMedium(fog, 0.7f, Color(0.5f), 0.3f);
    std::vector<calls::TransmittanceQuery> q = {{Ray{Point3(1, 2, 3), glm::normalize(Vec3(0.3f, -1, 0.2f))}, 1.0f,
                                                 fog.medium, 0u, 311u}};
    checkTransmittance(fog, q, {std::exp(-0.7)}, "a fog of sigmaT 0.7, no surfaces");
  }
  Scene scene;
  const MediumIndex inside = addMedium(scene, 1.3f, Color(0.9f), 0.0f);
  scene.medium = addMedium(scene, 0.25f, Color(0.9f), 0.5f);
  addMediumSphere(scene, Point3(0, 0, 0), 1.0f, inside, false);
  addMediumSphere(scene, Point3(3, 0, 0), 0.8f, inside, true);
  Random random(122);
  std::vector<calls::TransmittanceQuery> queries;
  for (int i = 0; i < 400; ++i) {
    const Point3 o(float(random.uniform(-2.0, 5.0)), float(random.uniform(-1.5, 1.5)), float(random.uniform(-1.5, 1.5)));
    const Vec3 d(random.unitVector());
    const bool fromInside = glm::length(o) < 1.0f;
    for (uint32_t k = 0; k < 10; ++k) queries.emplace_back(Ray{o, d}, 4.0f, fromInside ? inside : scene.medium, k, testSeed(313));
  }
  auto answers = [&](const Scene& s, float scale) {
    std::vector<calls::TransmittanceQuery> q = queries;
    for (auto& query : q) {
      std::get<0>(query).origin *= scale;
      std::get<1>(query) *= scale;
    }
    const std::vector<float> values = candidate::transmittance(s, q);
    return std::vector<double>(values.begin(), values.end());
  };
  const std::vector<double> base = answers(scene, 1.0f);
  const std::string larger = brokenPairs(base, 10, answers(transformed(scene, {"larger", 1024.0}), 1024.0f));
  INFO("the spheres 1024 times larger with sigmaT / 1024: " << larger);
  HINT("the transmittance changes when every length is 1024 times longer and every sigmaT 1024 times smaller: "
       "the optical depth sigmaT d is all that counts; a length or a step fixed in absolute units breaks it");
  CHECK(larger.empty());
  Scene reordered = scene;
  std::reverse(reordered.meshes.begin(), reordered.meshes.end());
  std::reverse(reordered.spheres.begin(), reordered.spheres.end());
  const std::string reorderedBroken = brokenPairs(base, 10, answers(reordered, 1.0f));
  INFO("the spheres in reverse order: " << reorderedBroken);
  HINT("the transmittance changes when the scene's objects come in another order: the medium beyond a surface "
       "comes from that surface (scene.mediumAcross), never from an object's index");
  CHECK(reorderedBroken.empty());
}

TEST_CASE("T12.3 direct lighting in media: through the phase function in a fog, and onto a surface in it" *
          grading(4, "task 4's estimate with two changes: the shadow ray's transmittance instead of its visibility, "
                     "and at a point in a medium the phase function henyeyGreenstein(dot(-wo, wi), g) instead of "
                     "f cos. Too bright: the shadow rays ignore the medium")) {
  constexpr int kCalls = 4000;
  Scene scene;
  scene.medium = addMedium(scene, 0.6f, Color(0.8f), 0.0f);
  const uint32_t floor = addMaterial(scene, Color(0.7f));
  addQuad(scene, Point3(-10, 0, 10), Vec3(20, 0, 0), Vec3(0, 0, -20), floor);
  // A small square area light facing down at height 2.
  const Color le(4.0f, 3.0f, 2.0f);
  const Point3 corner(-0.25f, 2.0f, -0.25f);
  const Vec3 eu(0.5f, 0.0f, 0.0f), ev(0.0f, 0.0f, 0.5f);  // u x v points down
  addQuad(scene, corner, eu, ev, addMaterial(scene, Color(0.0f), le));
  scene.pointLights.push_back(PointLight{Point3(1.5f, 1.5f, 0.5f), Color(2.0f, 2.5f, 3.0f)});
  // Three light samples per light: the estimate is their mean (one sample alone is right too).
  const calls::TraceSettings settings{3, 4};

  struct Vertex {
    bool onSurface;
    DVec3 point, wo;
    double g;
  };
  const std::vector<Vertex> vertices = {
      {false, DVec3(0.2, 1.0, 0.1), glm::normalize(DVec3(0.3, -1.0, 0.4)), 0.7},
      {false, DVec3(-0.5, 0.6, 0.3), glm::normalize(DVec3(-0.2, 0.3, 1.0)), -0.4},
      {true, DVec3(0.3, 0.0, -0.2), glm::normalize(DVec3(0.1, 1.0, 0.6)), 0.0}};
  std::vector<calls::VertexQuery> queries;
  for (size_t v = 0; v < vertices.size(); ++v) {
    const Vertex& x = vertices[v];
    // The query's ray arrives along -wo: at the surface point, or `distance` along it in the medium.
    const DVec3 origin = x.point + 1.5 * x.wo;
    for (int k = 0; k < kCalls; ++k) {
      queries.push_back({Ray{Point3(origin), Vec3(-x.wo)}, x.onSurface, 1.5f, float(x.g), scene.medium, uint32_t(k),
                         testSeed(400 + v)});
    }
  }
  const std::vector<Color> values = candidate::directLightingInMedia(scene, settings, queries);
  HINT("directLightingInMedia must return one value per query it was given");
  REQUIRE(values.size() == queries.size());

  const double sigmaT = 0.6;
  for (size_t v = 0; v < vertices.size(); ++v) {
    const Vertex& x = vertices[v];
    // The judge's value: the point light exactly, the area light by quadrature.
    auto scattering = [&](const DVec3& wi) {
      if (!x.onSurface) return hgPdf(glm::dot(-x.wo, wi), x.g);
      return std::max(0.0, wi.y) * 0.7 / kPiD;  // the floor's normal is +y
    };
    // Bounds for the variance's ceiling: a correct estimate lies between 0
    // and the point light's term plus the largest an area-light sample can
    // be, both untransmitted (an estimator of the transmittance may return
    // 1 or 0); its variance is at most the square of that range over 4.
    DVec3 expected(0.0);
    double pointBound = 0.0, largest = 0.0;
    {
      const DVec3 toLight = DVec3(1.5, 1.5, 0.5) - x.point;
      const double r = glm::length(toLight);
      expected += DVec3(2.0, 2.5, 3.0) * scattering(toLight / r) * std::exp(-sigmaT * r) / (r * r);
      pointBound = 3.0 * scattering(toLight / r) / (r * r);
    }
    constexpr int kGrid = 200;
    for (int i = 0; i < kGrid; ++i)
      for (int j = 0; j < kGrid; ++j) {
        const DVec3 p = DVec3(corner) + (i + 0.5) / kGrid * DVec3(eu) + (j + 0.5) / kGrid * DVec3(ev);
        const DVec3 toLight = p - x.point;
        const double r = glm::length(toLight);
        const DVec3 wi = toLight / r;
        const double cosLight = wi.y;  // the light faces down: -(-y) . wi
        if (cosLight <= 0.0) continue;
        const double value = scattering(wi) * cosLight / (r * r);
        expected += DVec3(le) * value * std::exp(-sigmaT * r) * (0.25 / (kGrid * kGrid));
        largest = std::max(largest, value * 0.25);  // f Le / pdf, pdf = r^2 / (A cos): A = 0.25
      }
    for (int channel = 0; channel < 3; ++channel) {
      MeanEstimate m;
      for (int k = 0; k < kCalls; ++k) {
        const float value = values[v * kCalls + size_t(k)][channel];
        m.add(std::isfinite(value) ? double(value) : 1e30);
      }
      const double range = pointBound + 4.0 * largest;  // Le <= 4, I <= 3
      m.setVarianceCeiling(range * range / 4.0, "values within the lights' range: range^2 / 4");
      CAPTURE(v);
      CAPTURE(channel);
      INFO(std::string(x.onSurface ? "a diffuse floor (albedo 0.7) in a fog of sigmaT 0.6" : "a point in a fog of sigmaT 0.6")
           << ", g " << x.g << ", at " << str(Vec3(x.point)) << ", wo " << str(Vec3(x.wo))
           << "; a point light and a small area light above");
      INFO(m.describe(expected[channel]));
      HINT("direct light at a vertex is wrong: at a point in the medium the phase function takes the BSDF's place "
           "(and no cosine), on the floor the BSDF and its cosine; both with the light dimmed by the transmittance "
           "to it, exp(-sigmaT r), not by a shadow ray's yes or no; the line printed says which vertex");
      CHECK(m.agrees(expected[channel]));
    }
  }
}

// ---- T12.4 ------------------------------------------------------------------

TEST_CASE("T12.4 furnace: a medium that absorbs nothing, in an index-matched sphere under a grey sky, returns the sky" *
          grading(4, "with albedo 1 no light is lost: every path must return the sky's radiance on average (0.8, "
                     "shown above in units of the sky: 1), whatever sigmaS and g. "
                     "Less: the surface's weight lacks 1 / P(pass), or a scattering event was counted as absorption; "
                     "more: light counted twice (emission after direct lighting)")) {
  struct Case {
    float sigmaT, g;
    bool mesh;
  };
  constexpr float kSky = 0.8f;
  for (const Case c : {Case{0.5f, -0.6f, false}, Case{2.0f, 0.0f, true}, Case{5.0f, 0.85f, false}}) {
    Scene scene;
    const MediumIndex medium = addMedium(scene, c.sigmaT, Color(1.0f), c.g);
    addMediumSphere(scene, Point3(0.0f), 1.0f, medium, c.mesh);
    scene.environment = Environment{};
    scene.environment->color = Color(kSky);
    Random random(71);
    std::vector<calls::PathQuery> queries;
    for (int i = 0; i < 6000; ++i) {
      const DVec3 target = random.inCube(0.6);
      const Point3 origin(0.0f, 0.0f, 4.0f);
      queries.emplace_back(Ray{origin, Vec3(glm::normalize(target - DVec3(origin)))}, uint32_t(i), testSeed(71));
    }
    MeanEstimate m;
    // Two light samples at each vertex (their mean; one alone is right too).
    for (const Color& L : candidate::tracePathsInMedia(scene, {2, 1000}, queries)) {
      // In units of the sky (not 1, so that a radiance divided where it should multiply shows).
      m.add(std::isfinite(L.x + L.y + L.z) ? double(L.x + L.y + L.z) / (3.0 * kSky) : 1e30);
    }
    limitNoise(m, "12-media");
    CAPTURE(c.sigmaT);
    CAPTURE(c.g);
    INFO(std::string(c.mesh ? "a sphere mesh" : "an analytic sphere") << " of medium, radius 1; paths aimed at it from outside");
    INFO(m.describe(1.0));
    CHECK(m.agrees(1.0));
  }
}

TEST_CASE("T12.4 absorption: behind a slab that only absorbs, a light is dimmed by exactly exp(-sigmaT d)" *
          grading(3, "a medium of albedo 0 scatters nothing: what passes is the light times the transmittance. "
                     "Brighter: the free flight samples with sigmaS (0 here) instead of sigmaT; darker: the surface "
                     "is weighted by the transmittance without dividing by P(pass)")) {
  Scene scene;
  const MediumIndex ink = addMedium(scene, 1.2f, Color(0.0f), 0.0f);
  // An interface box, x in [-1, 1], in front of an emitting wall at z = -3 facing +z.
  TriangleMesh box;
  box.positions = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}, {-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}};
  box.triangles = {{0, 3, 2}, {0, 2, 1}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                   {3, 7, 6}, {3, 6, 2}, {0, 4, 7}, {0, 7, 3}, {1, 2, 6}, {1, 6, 5}};
  box.material = addInterface(scene, ink);
  scene.meshes.push_back(box);
  const Color le(2.0f, 1.0f, 0.5f);
  addQuad(scene, Point3(-10, -10, -3), Vec3(20, 0, 0), Vec3(0, 20, 0), addMaterial(scene, Color(0.0f), le));
  Random random(81);
  std::vector<calls::PathQuery> queries;
  std::vector<double> distances;
  for (int i = 0; i < 4000; ++i) {
    const Point3 origin(float(random.uniform(-0.5, 0.5)), float(random.uniform(-0.5, 0.5)), 4.0f);
    const Vec3 direction = glm::normalize(Vec3(float(random.uniform(-0.05, 0.05)), float(random.uniform(-0.05, 0.05)), -1.0f));
    queries.emplace_back(Ray{origin, direction}, uint32_t(i), testSeed(81));
    distances.push_back(2.0 / std::abs(double(direction.z)));  // the box's depth along the ray (it stays inside x, y)
  }
  const std::vector<Color> radiance = candidate::tracePathsInMedia(scene, {1, 8}, queries);
  HINT("tracePathsInMedia must return one radiance per query it was given");
  REQUIRE(radiance.size() == queries.size());
  MeanEstimate ratio;  // radiance / (Le exp(-sigmaT d)), in red
  for (size_t i = 0; i < radiance.size(); ++i) {
    const double expected = double(le.x) * std::exp(-1.2 * distances[i]);
    ratio.add(std::isfinite(radiance[i].x) ? double(radiance[i].x) / expected : 1e30);
  }
  limitNoise(ratio, "12-media");
  INFO("camera rays through 2 units of a medium of sigmaT 1.2, albedo 0, onto a light of radiance " << str(le)
       << "; your radiance over Le exp(-sigmaT d): " << ratio.describe(1.0));
  HINT("through an absorbing slab the light must be dimmed by exactly exp(-sigmaT d). Brighter: the free flight "
       "samples with sigmaS (0 here) instead of sigmaT; darker: the surface is weighted by the transmittance "
       "without dividing by P(pass)");
  CHECK(ratio.agrees(1.0));

  // Beside the slab, through a vacuum: the light itself, Le. No noise is
  // needed here (Russian roulette on the camera ray, if any, may add up to a
  // variance of 0.1), and 40,000 rays leave a bias of 1 % nowhere to hide.
  std::vector<calls::PathQuery> clear;
  for (int i = 0; i < 40000; ++i) {
    const Point3 origin(float(random.uniform(1.5, 2.5)), float(random.uniform(-0.5, 0.5)), 4.0f);
    clear.emplace_back(Ray{origin, Vec3(0.0f, 0.0f, -1.0f)}, uint32_t(i), testSeed(82));
  }
  MeanEstimate seen;  // radiance / Le, in red
  seen.setVarianceCeiling(0.1, "0.1: Russian roulette on the camera ray, at most");
  for (const Color& L : candidate::tracePathsInMedia(scene, {1, 8}, clear)) {
    seen.add(std::isfinite(L.x) ? double(L.x) / double(le.x) : 1e30);
  }
  INFO("camera rays beside the medium, through a vacuum onto the light: your radiance over Le: " << seen.describe(1.0));
  HINT("through a vacuum, beside the medium, the light must be seen as it is (Le), and without noise: a path that "
       "samples a medium where there is none, or weights a vacuum's flight, fails here");
  CHECK_FALSE(seen.tooNoisy());
  CHECK(seen.agrees(1.0));
}

TEST_CASE("T12.4 absorption: a ball of ink in a haze that fills the scene: out of the ball, the haze again" *
          grading(2, "a ray that leaves an interface's interior enters the medium outside it, which is the "
                     "scene's (scene.mediumAcross(hit, wi, medium), or scene.medium), not a vacuum; inside, the "
                     "ball's own medium")) {
  // Both media only absorb, so what reaches the camera is exact: Le exp(-sigma_haze (d - c) - sigma_ink c),
  // c the chord through the ball, d the distance to the emitting wall. Leaving the ball into a vacuum
  // skips the haze behind it (2 units of it: the picture 22 % too bright).
  constexpr double kHaze = 0.1, kInk = 0.5;
  Scene scene;
  scene.medium = addMedium(scene, float(kHaze), Color(0.0f), 0.0f);
  addMediumSphere(scene, Point3(0.0f), 1.0f, addMedium(scene, float(kInk), Color(0.0f), 0.3f), false);
  const Color le(2.0f, 1.0f, 0.5f);
  addQuad(scene, Point3(-10, -10, -3), Vec3(20, 0, 0), Vec3(0, 20, 0), addMaterial(scene, Color(0.0f), le));
  Random random(83);
  std::vector<calls::PathQuery> queries;
  std::vector<double> expected;
  for (int i = 0; i < 20000; ++i) {
    const Point3 origin(float(random.uniform(-0.5, 0.5)), float(random.uniform(-0.5, 0.5)), 4.0f);
    const Vec3 direction = glm::normalize(Vec3(float(random.uniform(-0.05, 0.05)), float(random.uniform(-0.05, 0.05)), -1.0f));
    queries.emplace_back(Ray{origin, direction}, uint32_t(i), testSeed(83));
    const double d = 7.0 / std::abs(double(direction.z));  // to the wall at z = -3
    const double c = chordInside(DVec3(origin), DVec3(direction), d, DVec3(0.0), 1.0);
    expected.push_back(double(le.x) * std::exp(-kHaze * (d - c) - kInk * c));
  }
  const std::vector<Color> radiance = candidate::tracePathsInMedia(scene, {1, 8}, queries);
  HINT("tracePathsInMedia must return one radiance per query it was given");
  REQUIRE(radiance.size() == queries.size());
  HINT("a ray that leaves an interface's interior enters the medium outside it, here the scene's haze "
       "(scene.mediumAcross(hit, wi, medium), or scene.medium), not a vacuum; inside, the ball's own medium");
  MeanEstimate ratio;  // radiance / the exact transmitted light, in red
  for (size_t i = 0; i < radiance.size(); ++i)
    ratio.add(std::isfinite(radiance[i].x) ? double(radiance[i].x) / expected[i] : 1e30);
  limitNoise(ratio, "12-media");
  INFO("camera rays in a haze (sigmaT 0.1, albedo 0) through a ball of ink (sigmaT 0.5, albedo 0, behind an "
       "interface) onto a light: your radiance over Le exp(-0.1 (d - c) - 0.5 c): " << ratio.describe(1.0));
  CHECK(ratio.agrees(1.0));
}

namespace {

// media/scenes/fog-shafts.json at image-test size: the Cornell box full of
// fog up to a slotted plate (an interface box bounds it), a point light above
// the plate, out of the fog.
Scene fogBox() {
  return sceneFromJson(R"({
    "camera": { "position": [0, 0.75, 3.1], "look_at": [0, 0.75, 0], "up": [0, 1, 0], "vfov": 38 },
    "render": { "width": 48, "height": 36, "spp": 64, "max_depth": 6 },
    "media": { "fog": { "density": 0.6, "albedo": [0.9, 0.9, 0.9], "g": 0.3 } },
    "materials": {
      "white": { "albedo": [0.6, 0.6, 0.6] }, "red": { "albedo": [0.6, 0.2, 0.2] },
      "blue": { "albedo": [0.2, 0.2, 0.6] }, "plate": { "albedo": [0.1, 0.1, 0.1] },
      "fog boundary": { "type": "interface", "interior": "fog" }
    },
    "meshes": [
      { "material": "white", "quad": { "corner": [-1, 0, 1], "edge_u": [2, 0, 0], "edge_v": [0, 0, -2] } },
      { "material": "white", "quad": { "corner": [-1, 1.5, -1], "edge_u": [2, 0, 0], "edge_v": [0, 0, 2] } },
      { "material": "white", "quad": { "corner": [-1, 0, -1], "edge_u": [2, 0, 0], "edge_v": [0, 1.5, 0] } },
      { "material": "red", "quad": { "corner": [-1, 0, 1], "edge_u": [0, 0, -2], "edge_v": [0, 1.5, 0] } },
      { "material": "blue", "quad": { "corner": [1, 0, -1], "edge_u": [0, 0, 2], "edge_v": [0, 1.5, 0] } },
      { "material": "plate", "quad": { "corner": [-0.6, 1.15, 0.6], "edge_u": [0.4, 0, 0], "edge_v": [0, 0, -1.2] } },
      { "material": "plate", "quad": { "corner": [-0.1, 1.15, 0.6], "edge_u": [0.2, 0, 0], "edge_v": [0, 0, -1.2] } },
      { "material": "plate", "quad": { "corner": [0.2, 1.15, 0.6], "edge_u": [0.4, 0, 0], "edge_v": [0, 0, -1.2] } },
      { "material": "fog boundary",
        "positions": [[-1.01, -0.01, -1.01], [1.01, -0.01, -1.01], [1.01, 1.14, -1.01], [-1.01, 1.14, -1.01],
                      [-1.01, -0.01, 1.0], [1.01, -0.01, 1.0], [1.01, 1.14, 1.0], [-1.01, 1.14, 1.0]],
        "triangles": [[0, 3, 2], [0, 2, 1], [4, 5, 6], [4, 6, 7], [0, 1, 5], [0, 5, 4], [3, 7, 6], [3, 6, 2],
                      [0, 4, 7], [0, 7, 3], [1, 2, 6], [1, 6, 5]] }
    ],
    "spheres": [ { "center": [0.4, 0.3, 0.3], "radius": 0.3, "material": "white" } ],
    "lights": [ { "type": "point", "position": [0, 1.33, 0], "intensity": [3, 3, 3] } ]
  })", "fog box");
}

// A ball of a dense, coloured medium inside glass (media/scenes/jade.json's
// pebble, simplified) on a floor, all in a thin haze (the scene's medium:
// the camera is in it) under a large light. (No sky: light from infinitely
// far away never gets through a haze that fills all space.)
Scene jadeBall() {
  return sceneFromJson(R"({
    "camera": { "position": [0, 1.0, 3.0], "look_at": [0, 0.5, 0], "up": [0, 1, 0], "vfov": 35 },
    "render": { "width": 40, "height": 30, "spp": 64, "max_depth": 32 },
    "media": {
      "jade": { "density": 6, "albedo": [0.7, 0.95, 0.8], "g": 0.2 },
      "haze": { "density": 0.08, "albedo": [0.8, 0.8, 0.8], "g": -0.3 }
    },
    "medium": "haze",
    "materials": {
      "floor": { "albedo": [0.5, 0.5, 0.5] },
      "light": { "albedo": [0, 0, 0], "emission": [3, 3, 3] },
      "jade surface": { "type": "glass", "ior": 1.5, "interior": "jade" }
    },
    "meshes": [
      { "material": "floor", "quad": { "corner": [-3, 0, 3], "edge_u": [6, 0, 0], "edge_v": [0, 0, -6] } },
      { "material": "light", "quad": { "corner": [-1.5, 2.5, -1.5], "edge_u": [3, 0, 0], "edge_v": [0, 0, 3] } }
    ],
    "spheres": [ { "center": [0, 0.5, 0], "radius": 0.5, "material": "jade surface" } ]
  })", "jade ball");
}

}  // namespace

TEST_CASE("T12.4 image: the fog box with light shafts agrees with the converged picture" *
          grading(3, "compare your picture with the reference (files named above): a fog too thin or too thick "
                     "shows first in the shafts and on the far wall; shafts missing: the shadow rays ignore the fog")) {
  checkImage({"12-media", "fog-box", fogBox(), {}});
}

TEST_CASE("T12.4 image: a ball of medium inside glass, in a haze under a light, agrees with the converged picture" *
          grading(3, "compare your picture with the reference (files named above). Where the ball differs: its "
                     "medium is entered through glass, so after a BSDF sample that crosses the surface the medium "
                     "is scene.mediumAcross(hit, wi, medium). Where the floor, the light or the air differ: the "
                     "haze is the camera's medium (scene.medium), and every ray through it, shadow rays too, is "
                     "dimmed by its transmittance or scatters in it")) {
  checkImage({"12-media", "jade-ball", jadeBall(), {}});
}
