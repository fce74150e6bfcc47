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

// The point of a plate the lab samples from, with both strategies' samplers
// and pdfs in the lab's frame. The lab's frame has the scene's up (+y) for
// its pole, so that the lights, in front of the plates (-z), lie near its
// equator, where the (phi, cos theta) map is least distorted.
struct PlatePoint {
  std::shared_ptr<const PlatesRig> rig = std::make_shared<const PlatesRig>();
  std::shared_ptr<const PlatesRig> lights = std::make_shared<const PlatesRig>(true);
  Hit at;
  Vec3 wo;

  static Vec3 toLab(const Vec3& w) { return Vec3(w.x, -w.z, w.y); }
  static Vec3 fromLab(const Vec3& v) { return Vec3(v.x, v.z, -v.y); }

  double bsdfPdf(const Vec3& v) const {
    TraceContext context = rig->context();
    return double(context.bsdf(at, wo).pdf(wo, fromLab(v)));
  }
  double lightPdf(const Vec3& v) const {
    TraceContext context = lights->context();
    const Vec3 wi = fromLab(v);
    return double(oneLightPdf(context, at.point, wi, context.intersect(Ray{at.point, wi}, Interval{0.0f, kInfinity})));
  }
  std::optional<Vec3> sampleLight(Vec3 u) const {
    const std::optional<LightSample> s = sampleOneLight(lights->context(), at.point, u);
    if (!s || !(s->pdf > 0.0f)) return std::nullopt;
    return toLab(s->wi);
  }
  std::optional<Vec3> sampleBsdf(Vec2 u) const {
    TraceContext context = rig->context();
    const std::optional<BsdfSample> s = context.bsdf(at, wo).sample(wo, u);
    if (!s || !(s->pdf > 0.0f)) return std::nullopt;
    return toLab(s->wi);
  }

  // Light sampling's expected counts: the directions that reach a light
  // integrated over the light's surface (dw = cos' dA / d^2: the pdf of area
  // sampling has no bound at a sphere's outline, which no midpoint rule over
  // directions integrates), the others over directions (where the pdf should
  // be 0).
  std::vector<double> lightCounts(double n) const {
    TraceContext context = lights->context();
    std::vector<double> counts = DirectionHistogram::expected(
        [&](const std::vector<Vec3>& directions) {
          std::vector<double> values;
          for (const Vec3& v : directions) {
            const bool reachesLight =
                context.intersect(Ray{at.point, fromLab(v)}, Interval{0.0f, kInfinity}).has_value();
            values.push_back(reachesLight ? 0.0 : lightPdf(v));
          }
          return values;
        },
        n, 8);
    for (const Sphere& sphere : lights->scene.spheres) addSphereCounts(context, sphere, n, counts);
    return counts;
  }
  // The BSDF's: a bounded pdf, over directions (a sharp lobe: 96 midpoints a
  // side where it varies).
  std::vector<double> bsdfCounts(double n) const {
    return DirectionHistogram::expectedRefined(pointwise([this](const Vec3& v) { return bsdfPdf(v); }), n, 16, 96);
  }

 private:
  // One sphere light's share of light sampling's counts, over points uniform
  // by area.
  void addSphereCounts(const TraceContext& context, const Sphere& sphere, double n, std::vector<double>& counts) const {
    constexpr int kZ = 400, kPhiSteps = 800;
    const uint32_t primitive = primitiveOf(sphere);
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
        point.primitive = primitive;
        point.material = sphere.material;
        counts[size_t(DirectionHistogram::cellOf(toLab(wi)))] +=
            n * double(oneLightPdf(context, at.point, wi, point)) * dA * cosLight / (double(distance) * distance);
      }
  }
  uint32_t primitiveOf(const Sphere& sphere) const {
    const uint32_t index = uint32_t(&sphere - lights->scene.spheres.data());
    for (uint32_t k = 0; k < lights->scene.primitives.size(); ++k) {
      if (lights->scene.primitives[k].isSphere() && lights->scene.primitives[k].index == index) return k;
    }
    throw Error("mis-directions: a sphere light without its primitive");
  }
};

// The shading point: on the plate's middle line, where it mirrors the camera
// towards the light (x scaled by the camera's share of the depth).
PlatePoint platePointFacing(int plate, int light) {
  PlatePoint p;
  const Scene& scene = p.rig->scene;
  const TriangleMesh& mesh = scene.meshes[size_t(plate)];
  const Point3 eye = scene.camera.position;
  const Point3 middle = 0.5f * (mesh.positions[0] + mesh.positions[2]);
  const Point3 lightCentre = scene.spheres[size_t(light)].center;
  const Point3 onPlate(lightCentre.x * (eye.z - middle.z) / (eye.z - lightCentre.z), middle.y, middle.z);
  TraceContext probe = p.rig->context();
  const std::optional<Hit> hit = probe.intersect(Ray{eye, glm::normalize(onPlate - eye)}, Interval{0.0f, kInfinity});
  if (!hit || int(hit->material) != plate)
    throw Error("mis-directions: the camera does not see the plate there (the lab finds it with tasks 2 and 3: are "
                "they done?)");
  p.at = *hit;
  p.wo = glm::normalize(eye - p.at.point);
  return p;
}

// What the lab checks for a strategy: 0 light sampling, 1 BSDF sampling, 2
// half of each (u.x < 1/2: light sampling, else BSDF sampling with u.x
// stretched back to [0, 1)), against the mixture's pdf.
void chooseStrategy(WarpSetup& s, const std::shared_ptr<const PlatePoint>& p, int strategy) {
  auto lightPdf = [p](const Vec3& v) { return p->lightPdf(v); };
  auto bsdfPdf = [p](const Vec3& v) { return p->bsdfPdf(v); };
  if (strategy == 0) {
    s.sample = [p](Vec2 u) { return p->sampleLight(Vec3(u, thirdUniform(u))); };
    s.pdf = pointwise(lightPdf);
    s.expectedCounts = [p](double n) { return p->lightCounts(n); };
    s.mismatchMeans =
        "oneLightPdf is not sampleOneLight's density: the light's choice probability, or the area-to-solid-angle "
        "conversion";
  } else if (strategy == 1) {
    s.sample = [p](Vec2 u) { return p->sampleBsdf(u); };
    s.pdf = pointwise(bsdfPdf);
    s.expectedCounts = [p](double n) { return p->bsdfCounts(n); };
    s.mismatchMeans = "the BSDF's pdf is not its sampler's (task 8)";
  } else {
    s.sample = [p](Vec2 u) {
      return u.x < 0.5f ? p->sampleLight(Vec3(2.0f * u.x, u.y, thirdUniform(u)))
                        : p->sampleBsdf(Vec2(std::min(2.0f * u.x - 1.0f, 0x1.fffffep-1f), u.y));
    };
    s.pdf = pointwise([=](const Vec3& v) { return 0.5 * (lightPdf(v) + bsdfPdf(v)); });
    s.expectedCounts = [p](double n) {
      std::vector<double> counts = p->lightCounts(0.5 * n);
      const std::vector<double> bsdf = p->bsdfCounts(0.5 * n);
      for (size_t i = 0; i < counts.size(); ++i) counts[i] += bsdf[i];
      return counts;
    };
    s.drawnByFirst = [](Vec2 u) { return u.x < 0.5f; };
    s.firstExpectedCounts = [p](double n) { return p->lightCounts(0.5 * n); };
    s.firstName = "light sampling";
    s.secondName = "BSDF sampling";
    s.mismatchMeans = "one of the two pdfs is not its sampler's (try strategy 0 and 1 alone)";
  }
}

Warp misDirectionsWarp() {
  return {"mis-directions",
          "T9.2",
          "sampleOneLight and the BSDF's sampler at a point of Veach's plates: each pdf, and the mixture of both",
          {{"plate", 0, 0, 3, true, false, "the plate, 0 the smoothest (roughness 0.08) to 3 (0.35)"},
           {"light", 3, 0, 3, true, false, "the point of the plate in front of light 0 (the smallest) to 3"},
           {"strategy", 2, 0, 2, true, false,
            "0 light sampling (sampleOneLight against oneLightPdf), 1 BSDF sampling, 2 half of each "
            "(against (p_light + p_bsdf) / 2)"}},
          [](const Values& values, const WarpFiles&) {
            const int plate = count(values, "plate"), light = count(values, "light");
            const auto p = std::make_shared<const PlatePoint>(platePointFacing(plate, light));
            const Scene& scene = p->rig->scene;
            WarpSetup s;
            s.domain = Domain::Sphere;
            s.note =
                format("plate %d (roughness %.2f) at (%.2f, %.2f, %.2f), in front of light %d (radius %.3f)", plate,
                       double(scene.materials[size_t(plate)].roughness), double(p->at.point.x), double(p->at.point.y),
                       double(p->at.point.z), light, double(scene.spheres[size_t(light)].radius));
            chooseStrategy(s, p, count(values, "strategy"));
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
