// Autograder suite for task 6 — mirror and glass. Geometry identities are
// checked to float precision; Fresnel lobe selection by a chi-square test
// (alpha = 1e-4, its false-failure rate); furnace scenes within 5 measured
// standard errors (5.7e-7). Seeds are fixed (PATHLAB_TEST_SEED varies them).
// candidate::f(...) is the student's f, computed in the candidate process
// (calls.h); expected values are computed here, in the judge.
#include "suite/doctest_strings.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <numbers>

#include "check.h"
#include "metamorphic.h"
#include "image_scenes.h"
#include "image_test.h"
#include "suite/grading.h"
#include "core/bsdf.h"
#include "calls.h"
#include "reference_noise.h"
#include "render_support.h"
#include "statistics.h"

using namespace pathlab;
using namespace pathlab::test;

namespace {

// A sample's path weight f |cos theta| / pdf, in the local frame (cos theta = wi.z).
Color pathWeight(const BsdfSample& s) { return s.f * (std::abs(s.wi.z) / s.pdf); }

// Random unit directions on the outside (z > 0) or inside (z < 0).
Vec3 randomDirection(Random& random, bool outside) {
  DVec3 d = random.unitVector();
  d.z = std::abs(d.z) < 1e-3 ? 1e-3 : std::abs(d.z);
  return Vec3(glm::normalize(outside ? d : DVec3(d.x, d.y, -d.z)));
}

double sinTheta(const Vec3& w) { return std::sqrt(std::max(0.0, 1.0 - double(w.z) * double(w.z))); }

// The path radiance through a sphere of `material` in a uniform environment.
MeanEstimate furnace(const Material& material, float environment, int paths) {
  Scene scene;
  scene.materials.push_back(material);
  scene.spheres.push_back(Sphere{Point3(0.0f), 1.0f, 0});
  scene.environment = Environment{};
  scene.environment->color = Color(environment);
  Rig rig(std::move(scene));
  TraceContext context = rig.context(64, 1);
  Random random(61);
  std::vector<calls::PathQuery> queries;
  for (int i = 0; i < paths; ++i) {
    DVec3 target = random.inCube(0.6);
    Point3 origin(0.0f, 0.0f, 3.0f);
    queries.emplace_back(Ray{origin, Vec3(glm::normalize(target - DVec3(origin)))}, uint32_t(i), testSeed(61));
  }
  MeanEstimate m;
  for (const Color& L : candidate::tracePaths(context, queries)) m.addGrey(L);
  limitNoise(m, "06-mirror-glass");
  return m;
}

}  // namespace

TEST_CASE("T6.1 reflect: angle out equals angle in, same plane, unit length, reflect twice = identity" *
          grading(2, "about the normal +z: wi = (-wo.x, -wo.y, wo.z)")) {
  Random random(62);
  for (int i = 0; i < 1000; ++i) {
    Vec3 wo = randomDirection(random, i % 2 == 0);
    Vec3 wi = candidate::reflect(wo);
    INFO("wo " << str(wo) << " wi " << str(wi));
    HINT("reflect keeps the normal component: wi.z must equal wo.z, on both sides (wo.z < 0 too); negating z, "
         "or forcing wi above the surface with |wo.z|, fails here");
    CHECK(wi.z == doctest::Approx(wo.z).epsilon(1e-6));
    HINT("wi must be a unit vector: reflecting about +z only changes the signs of wo.x and wo.y, it never scales wo");
    CHECK(glm::length(wi) == doctest::Approx(1.0f).epsilon(1e-6));
    HINT("the tangent part of wi must be -(wo.x, wo.y), so that wo, wi and the normal lie in one plane and wo + "
         "wi = 2 wo.z n: swapping x and y, negating only one of them, or returning wo unchanged fails here");
    CHECK(std::abs(glm::dot(glm::cross(wo, wi), Vec3(0, 0, 1))) < 1e-5f);  // wo, wi and n coplanar
    CHECK(glm::length(wo + wi - 2.0f * wo.z * Vec3(0, 0, 1)) < 1e-5f);
    HINT("reflecting twice must give wo back: reflect must be the same formula, wi = (-wo.x, -wo.y, wo.z), "
         "for every wo on either side; a rule that differs between wo.z > 0 and wo.z < 0 fails here");
    CHECK(near(candidate::reflect(wi), wo, 1e-6f));
  }
}

TEST_CASE("T6.2 refract: Snell's law in both directions, and reversible" *
          grading(3, "entering (wo.z > 0) eta = 1/ior, leaving eta = ior; sin_t = eta sin_i; wi = (-eta wo.x, "
                     "-eta wo.y, -sign(wo.z) cos_t) lies on the other side")) {
  Random random(63);
  for (float ior : {1.5f, 2.4f, 1.33f}) {
    for (int i = 0; i < 500; ++i) {
      const bool entering = i % 2 == 0;
      Vec3 wo = randomDirection(random, entering);
      auto wi = candidate::refract(wo, ior);
      if (!entering && sinTheta(wo) * ior >= 1.0) continue;  // TIR: its own test
      CAPTURE(ior);
      INFO("wo " << str(wo));
      HINT("refract must return a ray whenever there is no total internal reflection: "
           "always when entering (wo.z > 0, eta = 1/ior), and when leaving (eta = ior) while eta^2 (1 - cos^2) < 1; "
           "returning nothing here means a wrong eta or TIR test");
      REQUIRE(wi.has_value());
      const double nO = entering ? 1.0 : ior, nT = entering ? ior : 1.0;
      HINT("Snell's law n_o sin_o = n_t sin_t must hold: sin_t = eta sin_i with eta = 1/ior entering (wo.z > 0) and "
           "eta = ior leaving; an eta not flipped with the side (or inverted), "
           "or eta where eta^2 belongs in sin_t^2, fails here");
      CHECK(nO * sinTheta(wo) == doctest::Approx(nT * sinTheta(*wi)).epsilon(1e-4));
      HINT("wi must be a unit vector: its tangent part -eta (wo.x, wo.y) has length sin_t, "
           "so |wi.z| must be cos_t = sqrt(1 - sin_t^2); keeping cos_i (wo.z) there, "
           "or scaling z by eta too, fails here");
      CHECK(glm::length(*wi) == doctest::Approx(1.0f).epsilon(1e-5));
      HINT("the refracted ray must go to the other side of the surface: wi.z = -cos_t when entering (wo.z > 0) "
           "and +cos_t when leaving; a z with wo's sign fails here");
      CHECK(wi->z * wo.z < 0.0f);                                                // the other side
      HINT("wo, wi and the normal must lie in one plane: the tangent part of wi must be eta times wo's, "
           "(-eta wo.x, -eta wo.y), the same factor on x and y; swapping x and y, or different factors, fails here");
      CHECK(std::abs(glm::dot(glm::cross(wo, *wi), Vec3(0, 0, 1))) < 1e-4f);    // same plane
      // Reversible where it is well conditioned (near grazing or the critical
      // angle, cos_t = sqrt(1 - sin^2) amplifies rounding).
      if (std::abs(wo.z) < 0.05f || std::abs(wi->z) < 0.05f) continue;
      auto back = candidate::refract(*wi, ior);
      HINT("refracting wi again must give a ray, and wo back: refract must use one rule on both sides, "
           "eta from the side of its input (1/ior for w.z > 0, ior for w.z < 0) and tangent part -eta (w.x, w.y); "
           "a rule that differs between entering and leaving, or a TIR test that fires too early, fails here");
      REQUIRE(back.has_value());
      CHECK(near(*back, wo, 1e-4f));
    }
  }
}

TEST_CASE("T6.2 refract: total internal reflection exactly past the critical angle, never before" *
          grading(2, "leaving glass, eta = ior > 1: when eta^2 (1 - cos^2) >= 1 there is no refracted ray; return "
                     "nothing exactly then")) {
  for (float ior : {1.5f, 1.33f, 2.4f}) {
    const float critical = std::asin(1.0f / ior);
    for (float offset : {1e-3f, 1e-2f, 0.2f}) {
      const float below = critical - offset, above = critical + offset;
      Vec3 inside(std::sin(below), 0.0f, -std::cos(below));
      Vec3 pastCritical(std::sin(above), 0.0f, -std::cos(above));
      CAPTURE(ior);
      CAPTURE(offset);
      HINT("leaving the glass just below the critical angle asin(1/ior) there must still be a refracted ray: "
           "TIR only when eta^2 (1 - cos^2) >= 1 with eta = ior; a test with a margin, on the wrong eta, "
           "or on cos where sin belongs, fails here");
      CHECK(candidate::refract(inside, ior).has_value());
      HINT("leaving the glass past the critical angle asin(1/ior) refract must return nothing: "
           "a missing TIR test (a NaN direction instead), or one using eta = 1/ior when leaving, fails here");
      CHECK_FALSE(candidate::refract(pastCritical, ior).has_value());
      // From outside there is never total internal reflection.
      HINT("entering from outside (wo.z > 0, eta = 1/ior < 1) there is never total internal reflection: "
           "returning nothing here means eta = ior on the way in, or the side decided wrongly");
      CHECK(candidate::refract(Vec3(std::sin(above), 0.0f, std::cos(above)), ior).has_value());
    }
  }
}

TEST_CASE("T6.2 refract: index 1 bends nothing (the ray goes straight through)" *
          grading(1, "with ior = 1, eta = 1: wi must be exactly -wo")) {
  Random random(64);
  for (int i = 0; i < 200; ++i) {
    Vec3 wo = randomDirection(random, i % 2 == 0);
    auto wi = candidate::refract(wo, 1.0f);
    HINT("with ior = 1, eta = 1 and sin_t = sin_i < 1, so refract must always return a ray: "
         "returning nothing here means a TIR test that fires before eta^2 (1 - cos^2) >= 1, or a wrong eta");
    REQUIRE(wi.has_value());
    // cos_t = sqrt(1 - sin^2) carries ~1e-7 / cos of rounding; |wo.z| >= 1e-3 here.
    HINT("with ior = 1 the ray goes straight through: wi must be -wo, tangent part -(wo.x, wo.y) and z on the side "
         "opposite wo's; a sign error on a component, or a tangent part scaled by anything but eta = 1, fails here");
    CHECK(near(*wi, -wo, 1e-4f));
  }
}

TEST_CASE("T6.3 Schlick: ((ior - 1) / (ior + 1))^2 at normal incidence, rising to 1 at grazing" *
          grading(2, "R0 = ((1 - ior) / (1 + ior))^2 and R = R0 + (1 - R0) (1 - cos)^5")) {
  // ior = 1 has no interface: the handout allows F = 0 there, in
  // schlickFresnel or in sampleGlass, so both answers are accepted at ior = 1.
  HINT("at ior = 1 and cos = 1 both terms vanish (R0 = ((1 - ior)/(1 + ior))^2 = 0, (1 - cos)^5 = 0), "
       "so F must be 0: cos^5 where (1 - cos)^5 belongs, or a wrong R0, fails here");
  CHECK(candidate::schlickFresnel(1.0f, 1.0f) == doctest::Approx(0.0).epsilon(1e-5));
  for (float c : {0.0f, 0.5f}) {
    const float r = candidate::schlickFresnel(c, 1.0f);
    CAPTURE(c);
    HINT("at ior = 1 (R0 = 0) F must be (1 - cos)^5, or 0 where you treat index 1 as no interface: "
         "a power other than 5, or cos where 1 - cos belongs, fails here");
    CHECK((r == doctest::Approx(std::pow(1.0 - c, 5.0)).epsilon(1e-5) || r == 0.0f));
  }
  for (float ior : {1.33f, 1.5f, 2.4f}) {
    const double r0 = std::pow((ior - 1.0) / (ior + 1.0), 2.0);
    CAPTURE(ior);
    HINT("at normal incidence (cos = 1) F must be R0 = ((ior - 1)/(ior + 1))^2: R0 not squared, "
         "another ratio of indices, or cos^5 where (1 - cos)^5 belongs, fails here");
    CHECK(candidate::schlickFresnel(1.0f, ior) == doctest::Approx(r0).epsilon(1e-5));
    HINT("at grazing incidence (cos = 0) F must be 1: R0 + (1 - R0) (1 - cos)^5 needs the (1 - R0) factor; "
         "without it, or with cos^5 where (1 - cos)^5 belongs, it fails here");
    CHECK(candidate::schlickFresnel(0.0f, ior) == doctest::Approx(1.0).epsilon(1e-5));
    HINT("between the ends F must be R0 + (1 - R0) (1 - cos)^5 exactly: at cos = 0.5 a power other than 5, "
         "or a different blend of R0 and 1, fails here");
    CHECK(candidate::schlickFresnel(0.5f, ior) == doctest::Approx(r0 + (1 - r0) * std::pow(0.5, 5)).epsilon(1e-5));
    float previous = 1.0f;
    for (float c = 0.0f; c <= 1.0f; c += 0.05f) {  // monotone: less reflection towards normal incidence
      const float r = candidate::schlickFresnel(c, ior);
      HINT("F must not grow as cos grows from 0 (grazing, F = 1) to 1 (normal incidence, F = R0): "
           "cos^5 where (1 - cos)^5 belongs makes it rise and fails here");
      CHECK(r <= previous + 1e-6f);
      previous = r;
    }
  }
}

TEST_CASE("T6.4 mirror: a delta lobe — wi = reflect(wo), weight = reflectance, never evaluated" *
          grading(2, "f = reflectance / |cos theta| with pdf 1 and isDelta = true, so the weight f |cos theta| / pdf "
                     "is the reflectance; f() and pdf() of a delta BSDF are 0, so direct lighting never evaluates it")) {
  Random random(65);
  for (int i = 0; i < 100; ++i) {
    Vec3 wo = randomDirection(random, true);
    BsdfSample s = candidate::sampleMirror(wo, Color(0.9f, 0.5f, 0.25f));
    HINT("sampleMirror must mark its sample as a delta (isDelta = true): "
         "a mirror's lobe has no density to evaluate, only the one direction it sends light");
    CHECK(s.isDelta);
    HINT("the mirror's wi must be (-wo.x, -wo.y, wo.z), the reflection of wo about the normal: a wi with z negated, "
         "or with x and y not negated, fails here");
    CHECK(near(s.wi, Vec3(-wo.x, -wo.y, wo.z), 1e-6f));
    HINT("a delta sample's pdf is the probability of choosing its lobe: a mirror has one lobe, so pdf must be 1");
    CHECK(s.pdf == doctest::Approx(1.0f));
    HINT("the weight f |cos theta| / pdf must be the reflectance: f = reflectance / |cos theta| with pdf 1; "
         "f = reflectance alone, without the 1 / |cos theta|, fails here");
    CHECK(near(pathWeight(s), Color(0.9f, 0.5f, 0.25f), 1e-5f));
  }
  Material mirror;
  mirror.type = MaterialType::Mirror;
  Hit hit;
  const BsdfLobes noTaskCode;  // a delta lobe's f and pdf call no task function
  const Bsdf bsdf(mirror, hit, Vec3(0, 0, 1), noTaskCode);
  HINT("a mirror's Bsdf must report isDelta() and give f() = 0 and pdf() = 0 (framework code, "
       "from the material type, calling no task function): "
       "a failure here points to a changed framework/core/bsdf.cpp, not to sampleMirror");
  CHECK(bsdf.isDelta());
  CHECK(bsdf.f(Vec3(0, 0, 1), glm::normalize(Vec3(0.3f, 0, 1))) == Color(0.0f));
  CHECK(bsdf.pdf(Vec3(0, 0, 1), glm::normalize(Vec3(0.3f, 0, 1))) == 0.0f);
}

TEST_CASE("T6.5 glass: reflection is chosen with the Fresnel probability (chi-square) and weighted right" *
          grading(3, "reflect when u < F (pdf F, weight f |cos| / pdf = reflectance), else refract (pdf 1 - F, weight "
                     "transmittance (n_o/n_t)^2); "
                     "F from Schlick with the outside cosine (or exact Fresnel); on total internal reflection always reflect")) {
  constexpr int kSamples = 200000;
  Random random(66);
  // Entering and leaving at fixed outside angles (sin theta outside), so
  // that leaving directions lie inside the escape cone: just inside it at
  // sin = 0.97 (grazing outside), and at indices other than 1.5.
  struct Trial {
    bool entering;
    double sinOutside;
    float ior;
  };
  const Trial trials[] = {{true, 0.3, 1.5f},  {true, 0.9, 1.5f},   {false, 0.2, 1.5f}, {false, 0.7, 1.5f},
                          {false, 0.97, 1.5f}, {true, 0.6, 2.4f}, {false, 0.6, 1.33f}};
  for (int trial = 0; trial < int(std::size(trials)); ++trial) {
    const bool entering = trials[trial].entering;  // (plain variables: INFO takes them by reference)
    const double sinOutside = trials[trial].sinOutside;
    const float ior = trials[trial].ior;
    const double phi = random.uniform(0.0, 2.0 * std::numbers::pi);
    const double sinWo = entering ? sinOutside : sinOutside / ior, cosWo = std::sqrt(1.0 - sinWo * sinWo);
    const Vec3 wo(DVec3(sinWo * std::cos(phi), sinWo * std::sin(phi), entering ? cosWo : -cosWo));
    const double cosOutside = std::sqrt(1.0 - sinOutside * sinOutside);
    // The handout allows Schlick's approximation or the exact dielectric
    // Fresnel equations: the reflected fraction must match one of them.
    const double r0 = std::pow((double(ior) - 1.0) / (double(ior) + 1.0), 2.0), m = 1.0 - cosOutside;
    const double schlick = r0 + (1 - r0) * m * m * m * m * m;
    const double cosInside = std::sqrt(1.0 - (1.0 - cosOutside * cosOutside) / (double(ior) * ior));
    const double rs = (cosOutside - ior * cosInside) / (cosOutside + ior * cosInside);
    const double rp = (cosInside - ior * cosOutside) / (cosInside + ior * cosOutside);
    const double exact = 0.5 * (rs * rs + rp * rp);
    std::vector<calls::SampleGlass::Args> queries;
    for (int i = 0; i < kSamples; ++i) {
      Sampler sampler(uint32_t(i), uint32_t(trial), testSeed(66));
      queries.emplace_back(wo, Color(0.9f), Color(0.8f), ior, sampler.next1D());
    }
    const std::vector<BsdfSample> samples = candidate::sampleGlass(queries);
    double reflections = 0.0;
    for (int i = 0; i < kSamples; ++i) {
      const BsdfSample& s = samples[size_t(i)];
      HINT("every glass sample, reflected and refracted alike, must set isDelta = true: "
           "both of glass's lobes are deltas; "
           "setting it on one branch only (e.g. not on total internal reflection) fails here");
      REQUIRE(s.isDelta);
      const bool reflected = s.wi.z * wo.z > 0.0f;
      reflections += reflected;
      if (i < 2000) {
        const double nO = entering ? 1.0 : ior, nT = entering ? ior : 1.0;
        const double expectedWeight = reflected ? 0.9 : 0.8 * (nO * nO) / (nT * nT);
        HINT("each sample's weight f |cos| / pdf must be the reflectance when it reflects, "
             "the transmittance times (n_o/n_t)^2 when it refracts (n_o on wo's side): "
             "pdf = the choice's probability, f = weight x pdf / |cos|; a weight of F or 1 - F, a missing 1/|cos|, "
             "or a missing or inverted (n_o/n_t)^2 fails here");
        CHECK(pathWeight(s).y == doctest::Approx(expectedWeight).epsilon(1e-4));
      }
    }
    // Each hypothesis is tested at p > 1e-4, so a correct sampler (which
    // matches at least one) fails with probability below 1e-4 per trial.
    auto matches = [&](double fresnel) {
      ChiSquareResult r = chiSquareTest({reflections, kSamples - reflections},
                                        {kSamples * fresnel, kSamples * (1.0 - fresnel)});
      return r.failure.empty() && r.pValue > 1e-4;
    };
    INFO("entering " << entering << ", ior " << ior << ", cos outside " << cosOutside << ": "
                     << reflections / kSamples << " reflected; Schlick F = " << schlick << ", exact F = " << exact);
    HINT("the fraction of samples that reflect must be F, Schlick's with the outside (index 1) cosine or exact "
         "Fresnel: Schlick with the inside or a negative cosine when leaving, "
         "or the two choices swapped (reflecting with probability 1 - F), fails here");
    CHECK((matches(schlick) || matches(exact)));
  }
  // Past the critical angle from inside, even by 0.1 %: always reflect, with
  // the reflectance. Just below it the ray still refracts for some u: which
  // part of [0, 1) refracts is the sampler's convention (u < F reflects, or
  // u >= 1 - F, or any other set of measure F), so every u of a fine grid is
  // tried and one must refract (1 - F is about 0.2 here: some 800 of them).
  for (double past : {1.001, 1.05}) {
    const double sinInside = past / 1.5;
    Vec3 tir(DVec3(sinInside, 0.0, -std::sqrt(1.0 - sinInside * sinInside)));
    for (float u : {0.0f, 0.5f, 0.999f}) {
      CAPTURE(past);
      BsdfSample s = candidate::sampleGlass(tir, Color(0.9f), Color(0.8f), 1.5f, u);
      HINT("past the critical angle from inside (refract gives no ray) glass must reflect whatever u is: "
           "wi on wo's side (wi.z < 0); tossing the Fresnel coin there anyway, "
           "or refracting into a NaN direction, fails here");
      CHECK(s.wi.z < 0.0f);
      HINT("on total internal reflection all light reflects with no choice made: "
           "pdf must be 1 and the weight f |cos| / pdf the reflectance (f = reflectance / |cos|); a pdf of F, "
           "or f carrying F, fails here");
      CHECK(s.pdf == doctest::Approx(1.0f));
      CHECK(pathWeight(s).y == doctest::Approx(0.9f));
    }
  }
  const double sinBelow = 0.999 / 1.5;
  Vec3 below(DVec3(sinBelow, 0.0, -std::sqrt(1.0 - sinBelow * sinBelow)));
  std::vector<calls::SampleGlass::Args> grid;
  for (int i = 0; i < 4096; ++i) grid.emplace_back(below, Color(0.9f), Color(0.8f), 1.5f, (float(i) + 0.5f) / 4096.0f);
  const std::vector<BsdfSample> nearCritical = candidate::sampleGlass(grid);
  const int refractions = int(std::count_if(nearCritical.begin(), nearCritical.end(),
                                            [](const BsdfSample& s) { return s.wi.z > 0.0f; }));
  INFO("just inside the escape cone (sin = 0.999 of the critical angle's): " << refractions
                                                                               << " of 4096 u refract");
  HINT("just inside the escape cone, where refract still gives a ray, "
       "some u must refract (1 - F is about 20 % there): an F of 1 or more (Schlick fed wo.z, negative inside, "
       "when leaving), or a TIR test that fires early, fails here");
  CHECK(refractions > 0);
}

TEST_CASE("T6.5 metamorphic: mirror and glass turned about the normal, or mirrored across it, turn their directions alike" *
          grading(1, "reflection and refraction see the normal (+z) and the angle to it, nothing else: no tangent axis "
                     "is special, and the lobe chosen for a u depends on cos(theta) alone")) {
  // The relations (docs/metamorphic.md): wo turned about +z by any angle, or
  // mirrored in x, gives reflect, refract and each sampleGlass draw (the
  // same u) turned or mirrored alike, with the same f and pdf. Beside them,
  // the truths: reflect(wo) = (-wo.x, -wo.y, wo.z), and refract obeys Snell.
  Random random(66);
  std::vector<Vec3> wos;
  for (int i = 0; i < 400; ++i) wos.push_back(randomDirection(random, i % 2 == 0));
  int untrue = 0;
  for (const Vec3& wo : wos) {
    if (!near(candidate::reflect(wo), Vec3(-wo.x, -wo.y, wo.z), 1e-6f)) ++untrue;
    const std::optional<Vec3> wi = candidate::refract(wo, 1.5f);
    const double nO = wo.z > 0 ? 1.0 : 1.5, nT = wo.z > 0 ? 1.5 : 1.0;
    if (wi && !(std::abs(nO * sinTheta(wo) - nT * sinTheta(*wi)) <= 1e-4)) ++untrue;
    if (!wi && wo.z > 0) ++untrue;
  }
  INFO(untrue << " of " << wos.size() << " directions reflect or refract wrongly");
  HINT("the relations below compare your directions with themselves, so they must first be right: reflect(wo) = "
       "(-wo.x, -wo.y, wo.z), and refract obeys Snell's law (always a ray when entering)");
  REQUIRE(untrue == 0);
  for (const Similarity& s : {Similarity{"turned 73 degrees about the normal", 1.0, rotationAbout({0, 0, 1}, 73)},
                              Similarity{"turned 200 degrees about the normal", 1.0, rotationAbout({0, 0, 1}, 200)},
                              Similarity{"mirrored in x", 1.0, mirrorX()}}) {
    int differing = 0;
    std::vector<calls::SampleGlass::Args> before, after;
    for (const Vec3& wo : wos) {
      if (!near(candidate::reflect(s.direction(wo)), s.direction(candidate::reflect(wo)), 1e-5f)) ++differing;
      const std::optional<Vec3> wi = candidate::refract(wo, 1.5f), turned = candidate::refract(s.direction(wo), 1.5f);
      const bool nearCritical = std::abs(sinTheta(wo) * 1.5 - 1.0) < 1e-4;
      if (!nearCritical && (wi.has_value() != turned.has_value() || (wi && !near(*turned, s.direction(*wi), 1e-5f)))) {
        ++differing;
      }
      const float u = float(random.uniform());
      before.emplace_back(wo, Color(0.9f), Color(0.8f), 1.5f, u);
      after.emplace_back(s.direction(wo), Color(0.9f), Color(0.8f), 1.5f, u);
    }
    const std::vector<BsdfSample> drawn = candidate::sampleGlass(before), drawnTurned = candidate::sampleGlass(after);
    for (size_t k = 0; k < drawn.size(); ++k) {
      const BsdfSample &a = drawn[k], &b = drawnTurned[k];
      // A u this close to the lobes' boundary (F, or 1 - F, whichever end the
      // convention takes) may fall either way once cos(theta) rounds anew.
      const float u = std::get<4>(before[k]), F = a.wi.z * std::get<0>(before[k]).z > 0.0f ? a.pdf : 1.0f - a.pdf;
      if (std::min(std::abs(u - F), std::abs(u - (1.0f - F))) < 1e-4f && a.wi.z * b.wi.z < 0.0f) continue;
      if (!near(b.wi, s.direction(a.wi), 1e-5f) || !near(Vec3(b.f), Vec3(a.f), 1e-5f * maxComponent(a.f) + 1e-7f) ||
          !(std::abs(b.pdf - a.pdf) <= 1e-5f * a.pdf)) {
        ++differing;
      }
    }
    CAPTURE(s.name);
    INFO(differing << " of " << 3 * wos.size() << " answers are not the turned or mirrored ones");
    HINT("reflect, refract or sampleGlass change when wo is turned about the normal or mirrored across it: only "
         "wo.z (cos theta) and the tangent part's direction may matter, flipped as a whole, never one tangent axis");
    CHECK(differing == 0);
  }
}

TEST_CASE("T6.5 furnace: a perfect mirror and lossless glass vanish in a uniform environment" *
          grading(3, "with reflectance = transmittance = 1 every path must carry exactly the environment: no energy "
                     "lost or created at the boundary (flip the normal and eta when leaving; (n_o/n_t)^2 cancels "
                     "between entering and leaving)")) {
  Material mirror;
  mirror.type = MaterialType::Mirror;
  mirror.albedo = Color(1.0f);
  MeanEstimate m = furnace(mirror, 1.0f, 20000);
  INFO("mirror: " << m.describe(1.0));
  HINT("a white mirror under a white sky must give every path exactly 1: its weight f |cos| / pdf must be exactly "
       "the reflectance (f = reflectance / |cos|, pdf 1); a missing 1 / |cos| or a pdf other than 1 "
       "loses or adds light here");
  CHECK(m.agrees(1.0));
  for (float ior : {1.5f, 1.0f}) {
    Material glass;
    glass.type = MaterialType::Glass;
    glass.albedo = Color(1.0f);
    glass.transmittance = Color(1.0f);
    glass.ior = ior;
    MeanEstimate g = furnace(glass, 1.0f, 40000);
    CAPTURE(ior);
    INFO("glass: " << g.describe(1.0));
    HINT("lossless glass (R = T = 1) under a white sky must give 1 on average: "
         "each choice weighs 1 apart from (n_o/n_t)^2, which must follow wo's side so entering and leaving cancel; "
         "a weight F or 1 - F, an eta or index ratio not flipped when leaving, or light lost on TIR fails here");
    CHECK(g.agrees(1.0));
  }
}

TEST_CASE("T6.5 glass of index 1 is invisible: the light behind it arrives unchanged" *
          grading(2, "at ior = 1 Fresnel reflectance is 0 and refraction goes straight: every path must see "
                     "exactly the emitter behind the sphere")) {
  Scene scene;
  Material glass;
  glass.type = MaterialType::Glass;
  glass.albedo = Color(1.0f);
  glass.transmittance = Color(1.0f);
  glass.ior = 1.0f;
  scene.materials.push_back(glass);
  scene.spheres.push_back(Sphere{Point3(0.0f), 1.0f, 0});
  uint32_t emitter = addMaterial(scene, Color(0.0f), Color(3.0f));
  addQuad(scene, {-5, -5, -3}, {10, 0, 0}, {0, 10, 0}, emitter);  // behind the sphere, facing +z
  Rig rig(std::move(scene));
  TraceContext context = rig.context(8, 1);
  Random random(67);
  std::vector<calls::PathQuery> queries;
  for (int i = 0; i < 2000; ++i) {
    DVec3 target = random.inCube(0.7);
    Point3 origin(0.0f, 0.0f, 4.0f);
    queries.emplace_back(Ray{origin, Vec3(glm::normalize(target - DVec3(origin)))}, uint32_t(i), testSeed(67));
  }
  int wrong = 0;
  for (const Color& L : candidate::tracePaths(context, queries)) {
    if (!(glm::length(Vec3(L) - Vec3(3.0f)) <= 1e-3f)) ++wrong;  // every channel, and NaN is wrong
  }
  INFO(wrong << " of 2000 paths through index-1 glass did not see the emitter's 3.0");
  CHECK(wrong == 0);
}

// ---------------------------------------------------------------- images

namespace {

// Glass and mirrors under a sky: a glass sphere (refraction both ways), a
// thick glass slab seen at a grazing angle (total internal reflection
// inside it), a sphere of index 1 (invisible) and a mirror wall.
Scene glassUnderSkyScene() {
  Scene scene = sceneFromJson(R"({
    "camera": { "position": [0, 1.1, 4], "look_at": [0, 0.5, 0], "up": [0, 1, 0], "vfov": 42 },
    "render": { "width": 48, "height": 36, "spp": 64, "max_depth": 6 },
    "materials": {
      "ground": { "albedo": [0.6, 0.6, 0.6] },
      "red":    { "albedo": [0.7, 0.2, 0.15] },
      "glass":  { "type": "glass", "reflectance": [1, 1, 1], "transmittance": [0.9, 1, 0.9], "ior": 1.5 },
      "air":    { "type": "glass", "reflectance": [1, 1, 1], "transmittance": [1, 1, 1], "ior": 1.0 },
      "mirror": { "type": "mirror", "reflectance": [0.9, 0.85, 0.8] }
    },
    "meshes": [
      { "name": "ground", "material": "ground", "quad": { "corner": [-4, 0, 4], "edge_u": [8, 0, 0], "edge_v": [0, 0, -8] } },
      { "name": "mirror wall", "material": "mirror", "quad": { "corner": [-2, 0, -1.5], "edge_u": [4, 0, 0], "edge_v": [0, 1.6, 0] } },
      { "name": "slab front", "material": "glass", "quad": { "corner": [0.5, 0.05, 0.6], "edge_u": [1.2, 0, 0], "edge_v": [0, 0.5, 0] } },
      { "name": "slab back", "material": "glass", "quad": { "corner": [1.7, 0.05, 0.3], "edge_u": [-1.2, 0, 0], "edge_v": [0, 0.5, 0] } },
      { "name": "slab top", "material": "glass", "quad": { "corner": [0.5, 0.55, 0.6], "edge_u": [1.2, 0, 0], "edge_v": [0, 0, -0.3] } },
      { "name": "slab left", "material": "glass", "quad": { "corner": [0.5, 0.05, 0.3], "edge_u": [0, 0, 0.3], "edge_v": [0, 0.5, 0] } },
      { "name": "slab right", "material": "glass", "quad": { "corner": [1.7, 0.05, 0.6], "edge_u": [0, 0, -0.3], "edge_v": [0, 0.5, 0] } }
    ],
    "spheres": [
      { "center": [-0.6, 0.3, -0.8], "radius": 0.3, "material": "red" },
      { "center": [0.4, 0.35, -0.4], "radius": 0.35, "material": "air" },
      { "center": [0.4, 0.25, -0.4], "radius": 0.2, "material": "red" }
    ]
  })", "glass under a sky");
  // The glass ball is a mesh with vertex normals: refraction bends around
  // the shading normal, and inside from outside comes from the outward one.
  scene.meshes.push_back(smoothSphere(2, Point3(-0.8f, 0.5f, 0.2f), 0.5f, materialIndex(scene, "glass")));
  Environment sky;
  sky.imagePath = "(a sky made in code)";
  sky.image = skyMap(32, 16, 0.3f, 0.3f, 4.0f);
  scene.environment = sky;
  return scene;
}

}  // namespace

TEST_CASE("T6.5 image: mirror and glass spheres in a Cornell box, and glass, a slab and a mirror under a sky" *
          grading(4, "compare your pictures with the references (files named above): glass too dark or too bright "
                     "means its weight is not 1 (Fresnel chosen with probability F cancels F); a dark rim inside "
                     "the slab means total internal reflection is missing; a visible index-1 sphere, a bent ray")) {
  checkImage({"06-mirror-glass", "cornell-mirror-glass", cornellBox(48, 36, 64, 6, true), {}});
  checkImage({"06-mirror-glass", "glass-under-sky", glassUnderSkyScene(), {}});
}
