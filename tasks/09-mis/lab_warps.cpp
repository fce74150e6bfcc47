// Task 9's warps in the sampling lab (lab/lab.h): its sampling
// routines, called as this build links them (the student's file or the
// reference), each against its own pdf. lab/CMakeLists.txt compiles this
// file into the lab; addMisWarps is listed with the other tasks'.
#include <utility>

#include "lab_support.h"
#include "render/accelerator.h"
#include "render/task_wiring.h"
#include "scene/procedural.h"
#include "tasks/mis.h"
#include "util/error.h"

namespace pathlab::lab {
namespace {

// Veach's plates, ready to trace: the scene, its BVH and its lights.
// lightsOnly: the lights without the plates, so that a direction's light pdf
// is the light's, whatever plate stands in the way (sampleOneLight does not
// look for occluders either).
struct PlatesRig {
  Scene scene = veachPlatesScene();
  std::unique_ptr<Accelerator> accelerator;
  Lights lights;
  explicit PlatesRig(bool lightsOnly = false) {
    if (lightsOnly) scene.meshes.clear();
    scene.indexPrimitives();
    accelerator = std::make_unique<Accelerator>(scene);
    lights = Lights::fromScene(scene, kLinkedTasks.environment);
  }
  TraceContext context() const { return TraceContext(scene, *accelerator, lights, kLinkedTasks.lobes); }
};

// A third uniform number from the bits of u (a hash): sampleOneLight takes
// three, the lab draws two.
float thirdUniform(Vec2 u) {
  uint32_t x, y;
  std::memcpy(&x, &u.x, 4), std::memcpy(&y, &u.y, 4);
  return float(mix64((uint64_t(x) << 32) | y) >> 40) * 0x1.0p-24f;
}

Warp misDirectionsWarp() {
  return {"mis-directions", "T9.2",
          "sampleOneLight and the BSDF's sampler at a point of Veach's plates: each pdf, and the mixture of both",
          {{"plate", 0, 0, 3, true, false, "the plate, 0 the smoothest (roughness 0.08) to 3 (0.35)"},
           {"light", 3, 0, 3, true, false, "the point of the plate in front of light 0 (the smallest) to 3"},
           {"strategy", 2, 0, 2, true, false,
            "0 light sampling (sampleOneLight against oneLightPdf), 1 BSDF sampling, 2 half of each "
            "(against (p_light + p_bsdf) / 2)"}},
          [](const Values& p, const WarpFiles&) {
            const auto rig = std::make_shared<const PlatesRig>();
            const auto lights = std::make_shared<const PlatesRig>(true);
            const int plate = count(p, "plate"), light = count(p, "light"), strategy = count(p, "strategy");
            // The shading point: on the plate's middle line, where it mirrors the
            // camera towards the light (x scaled by the camera's share of the depth).
            const TriangleMesh& mesh = rig->scene.meshes[size_t(plate)];
            const Point3 eye = rig->scene.camera.position;
            const Point3 middle = 0.5f * (mesh.positions[0] + mesh.positions[2]);
            const Point3 lightCentre = rig->scene.spheres[size_t(light)].center;
            const Point3 onPlate(lightCentre.x * (eye.z - middle.z) / (eye.z - lightCentre.z), middle.y, middle.z);
            TraceContext probe = rig->context();
            const std::optional<Hit> hit = probe.intersect(Ray{eye, glm::normalize(onPlate - eye)}, Interval{0.0f, kInfinity});
            if (!hit || int(hit->material) != plate) throw Error("mis-directions: the camera does not see the plate there (the lab finds it with tasks 2 and 3: are they done?)");
            const Hit at = *hit;
            const Vec3 wo = glm::normalize(eye - at.point);
            // The lab's frame has the scene's up (+y) for its pole, so that the
            // lights, in front of the plates (-z), lie near its equator, where
            // the (phi, cos theta) map is least distorted.
            auto toLab = [](const Vec3& w) { return Vec3(w.x, -w.z, w.y); };
            auto fromLab = [](const Vec3& v) { return Vec3(v.x, v.z, -v.y); };
            auto bsdfPdf = [rig, at, wo, fromLab](const Vec3& v) {
              TraceContext context = rig->context();
              return double(context.bsdf(at, wo).pdf(wo, fromLab(v)));
            };
            auto lightPdf = [lights, at, fromLab](const Vec3& v) {
              TraceContext context = lights->context();
              const Vec3 wi = fromLab(v);
              return double(oneLightPdf(context, at.point, wi, context.intersect(Ray{at.point, wi}, Interval{0.0f, kInfinity})));
            };
            auto sampleLight = [lights, at, toLab](Vec3 u) -> std::optional<Vec3> {
              const std::optional<LightSample> s = sampleOneLight(lights->context(), at.point, u);
              if (!s || !(s->pdf > 0.0f)) return std::nullopt;
              return toLab(s->wi);
            };
            auto sampleBsdf = [rig, at, wo, toLab](Vec2 u) -> std::optional<Vec3> {
              TraceContext context = rig->context();
              const std::optional<BsdfSample> s = context.bsdf(at, wo).sample(wo, u);
              if (!s || !(s->pdf > 0.0f)) return std::nullopt;
              return toLab(s->wi);
            };
            WarpSetup s;
            s.domain = Domain::Sphere;
            s.note = format("plate %d (roughness %.2f) at (%.2f, %.2f, %.2f), in front of light %d (radius %.3f)", plate,
                            double(rig->scene.materials[size_t(plate)].roughness), double(at.point.x),
                            double(at.point.y), double(at.point.z), light,
                            double(rig->scene.spheres[size_t(light)].radius));
            // The expected counts of each strategy. Light sampling's: the
            // directions that reach a light integrated over the light's surface
            // (dw = cos' dA / d^2: the pdf of area sampling has no bound at a
            // sphere's outline, which no midpoint rule over directions
            // integrates), the others over directions (where the pdf should be 0).
            auto lightCounts = [lights, at, lightPdf, toLab, fromLab](double n) {
              TraceContext context = lights->context();
              auto reachesLight = [&](const Vec3& v) {
                return context.intersect(Ray{at.point, fromLab(v)}, Interval{0.0f, kInfinity}).has_value();
              };
              std::vector<double> counts = DirectionHistogram::expected(
                  [&](const std::vector<Vec3>& directions) {
                    std::vector<double> values;
                    for (const Vec3& wi : directions) values.push_back(reachesLight(wi) ? 0.0 : lightPdf(wi));
                    return values;
                  },
                  n, 8);
              constexpr int kZ = 400, kPhiSteps = 800;  // per sphere: points uniform by area
              std::vector<uint32_t> primitiveOf(lights->scene.spheres.size());
              for (uint32_t k = 0; k < lights->scene.primitives.size(); ++k) {
                if (lights->scene.primitives[k].isSphere()) primitiveOf[lights->scene.primitives[k].index] = k;
              }
              for (const Sphere& sphere : lights->scene.spheres) {
                const double dA = double(sphere.radius) * sphere.radius * (2.0 / kZ) * (2.0 * kPi / kPhiSteps);
                for (int a = 0; a < kZ; ++a)
                  for (int b = 0; b < kPhiSteps; ++b) {
                    const double z = -1.0 + (a + 0.5) * 2.0 / kZ, phi = (b + 0.5) * 2.0 * kPi / kPhiSteps;
                    const double rho = std::sqrt(1.0 - z * z);
                    const Vec3 normal(float(rho * std::cos(phi)), float(rho * std::sin(phi)), float(z));
                    const Vec3 toPoint = sphere.center + sphere.radius * normal - at.point;
                    const float distance = glm::length(toPoint);
                    const Vec3 wi = toPoint / distance;
                    const float cosLight = -glm::dot(normal, wi);
                    if (!(cosLight > 0.0f)) continue;
                    // The pdf asked at this very point, even where another light hides
                    // it (the sampler does not look: its density there is the sum of
                    // both lights'), and exactly there (near the outline a float ray
                    // finds a point whose cos', the pdf's divisor, is not this one's).
                    Hit point;
                    point.t = distance;
                    point.point = sphere.center + sphere.radius * normal;
                    point.geometricNormal = point.shadingNormal = normal;
                    point.primitive = primitiveOf[size_t(&sphere - lights->scene.spheres.data())];
                    point.material = sphere.material;
                    counts[size_t(DirectionHistogram::cellOf(toLab(wi)))] +=
                        n * double(oneLightPdf(context, at.point, wi, point)) * dA * cosLight / (double(distance) * distance);
                  }
              }
              return counts;
            };
            // The BSDF's: a bounded pdf, over directions (a sharp lobe: 96
            // midpoints a side where it varies).
            auto bsdfCounts = [bsdfPdf](double n) {
              return DirectionHistogram::expectedRefined(pointwise(bsdfPdf), n, 16, 96);
            };
            if (strategy == 0) {
              s.sample = [=](Vec2 u) { return sampleLight(Vec3(u, thirdUniform(u))); };
              s.pdf = pointwise(lightPdf);
              s.expectedCounts = lightCounts;
              s.mismatchMeans = "oneLightPdf is not sampleOneLight's density: the light's choice probability, or the "
                                "area-to-solid-angle conversion";
            } else if (strategy == 1) {
              s.sample = sampleBsdf;
              s.pdf = pointwise(bsdfPdf);
              s.expectedCounts = bsdfCounts;
              s.mismatchMeans = "the BSDF's pdf is not its sampler's (task 8)";
            } else {
              // u.x < 1/2: light sampling, else BSDF sampling (u.x stretched back to [0, 1)).
              s.sample = [=](Vec2 u) {
                return u.x < 0.5f ? sampleLight(Vec3(2.0f * u.x, u.y, thirdUniform(u)))
                                  : sampleBsdf(Vec2(std::min(2.0f * u.x - 1.0f, 0x1.fffffep-1f), u.y));
              };
              s.pdf = pointwise([=](const Vec3& wi) { return 0.5 * (lightPdf(wi) + bsdfPdf(wi)); });
              s.expectedCounts = [=](double n) {
                std::vector<double> counts = lightCounts(0.5 * n);
                const std::vector<double> bsdf = bsdfCounts(0.5 * n);
                for (size_t i = 0; i < counts.size(); ++i) counts[i] += bsdf[i];
                return counts;
              };
              s.drawnByFirst = [](Vec2 u) { return u.x < 0.5f; };
              s.firstExpectedCounts = [=](double n) { return lightCounts(0.5 * n); };
              s.firstName = "light sampling";
              s.secondName = "BSDF sampling";
              s.mismatchMeans = "one of the two pdfs is not its sampler's (try strategy 0 and 1 alone)";
            }
            return s;
          }};
}

}  // namespace

void addMisWarps(std::vector<Warp>& warps) {
  Warp directions = misDirectionsWarp();
  // The plates are found with tasks 2 and 3, their BSDF is task 8's, and
  // sampleOneLight calls task 4's lightDirection.
  directions.alsoRuns = {2, 3, 4, 8};
  warps.push_back(std::move(directions));
}

}  // namespace pathlab::lab
