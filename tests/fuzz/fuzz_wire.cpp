// The judge's decoders on arbitrary answers: the input's first byte picks
// one of the suites' requests, the rest is the candidate's answer to it,
// decoded through the call's shape as callMany decodes it (call.h). Every
// answer must decode or fail with a wire::WireError; nothing it makes the
// judge allocate may pass what the request allows (tools/fuzz runs this
// target under -malloc_limit_mb), even without the byte bound that callMany
// applies first; and an answer that decodes must lie within that bound
// (a bound below a right answer would refuse it).
// With PATHLAB_FUZZ_WRITE_SEEDS=DIR, the seeds are written there first
// (tools/fuzz's corpus, always in today's encoding): the right answer to
// each request, and an answer that starts with a count of 40,000 followed
// by as many zero bytes (40,000 empty optionals to a request for 16: a
// decoder that believed the count would allocate 1.4 MB).
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "../02-intersection/calls.h"
#include "../03-bvh/calls.h"
#include "../07-environment/calls.h"
#include "../09-mis/calls.h"
#include "../11-adaptive-sampling/calls.h"
#include "image_calls.h"
#include "trace_calls.h"

namespace {

using namespace pathlab;

// An 8 x 6 render at 4 samples per pixel of a lamp (two triangles) over a ball.
Scene smallScene() {
  Scene scene;
  scene.render.width = 8, scene.render.height = 6, scene.render.samplesPerPixel = 4;
  scene.materials.push_back(Material{.name = "lamp", .emission = Color(1.0f)});
  TriangleMesh lamp;
  lamp.positions = {Point3(-1, 1, -1), Point3(1, 1, -1), Point3(1, 1, 1), Point3(-1, 1, 1)};
  lamp.triangles = {glm::uvec3(0, 1, 2), glm::uvec3(0, 2, 3)};
  scene.meshes.push_back(lamp);
  scene.spheres.push_back(Sphere{Point3(0.0f), 0.5f, 0});
  scene.indexPrimitives();
  return scene;
}

// One request, and a right answer to it (the seed).
struct Case {
  std::function<void(const std::string&)> decode;  // throws WireError for a wrong answer
  std::string rightAnswer;
};

template <class C>
Case caseOf(std::vector<typename C::Args> items, const std::vector<typename C::Result>& right) {
  wire::Writer w;
  for (const auto& r : right) w.put(r);
  return {[items](const std::string& answer) {
            remote::decodeAnswer<C>(answer, items);
            if (answer.size() > remote::maxAnswerBytes<C>(items)) {
              std::fprintf(stderr, "an answer of %zu bytes decoded, over its shape's bound of %llu bytes\n",
                           answer.size(), static_cast<unsigned long long>(remote::maxAnswerBytes<C>(items)));
              std::abort();
            }
          },
          w.bytes()};
}

std::vector<Case> makeCases() {
  std::vector<Case> cases;
  const Scene scene = smallScene();
  test::PixelMoments moments{8, 6, 4, std::vector<Color>(48, Color(0.5f)), std::vector<Color>(48, Color(0.01f)), 0, true};
  cases.push_back(caseOf<calls::RenderMoments>({{scene, test::ImageOptions{}}}, {moments}));
  test::ImageOptions adaptive;
  adaptive.adaptive = AdaptiveSettings{};
  cases.push_back(caseOf<calls::RenderMoments>({{scene, adaptive}}, {moments}));

  std::vector<Aabb> boxes(10, Aabb{Point3(0.0f), Point3(1.0f)});
  Bvh bvh;
  bvh.nodes.push_back(BvhNode{Aabb{Point3(0.0f), Point3(1.0f)}, 0, 10});
  for (uint32_t i = 0; i < 10; ++i) bvh.primitives.push_back(i);
  cases.push_back(caseOf<calls::BuildBvh>({{boxes}}, {bvh}));
  const std::vector<calls::RayInRange> rays(3, {Ray{Point3(0.0f), Vec3(0, 0, -1)}, Interval{0.0f, 10.0f}});
  cases.push_back(caseOf<calls::TraverseServed>({{bvh, scene, rays, false}}, {{{true, {}}, {false, {}}, {true, {}}}}));

  Image map(8, 4, Color(1.0f));
  EnvironmentDistribution d;
  d.width = 8, d.height = 4;
  d.marginalCdf = {0.0f, 0.25f, 0.5f, 0.75f, 1.0f};
  d.conditionalCdf.assign(4 * 9, 0.5f);
  d.totalWeight = 32.0;
  cases.push_back(caseOf<calls::BuildEnvironmentDistribution>({{map}}, {d}));

  const std::vector<Vec3> us(16, Vec3(0.5f));
  std::vector<std::optional<LightSample>> lightSamples(16);
  lightSamples[3] = LightSample{Vec3(0, 1, 0), 2.0f, Color(1.0f), 0.5f};
  cases.push_back(caseOf<calls::SampleOneLight>({{scene, Point3(0.0f), us}}, {lightSamples}));

  const std::vector<Point3> positions = {Point3(0.0f), Point3(1, 0, 0), Point3(0, 1, 0)};
  const std::vector<glm::uvec3> triangles = {glm::uvec3(0, 1, 2), glm::uvec3(0, 2, 1)};
  const std::vector<Ray> meshRays(4, Ray{Point3(0.2f, 0.2f, 1.0f), Vec3(0, 0, -1)});
  using Hits = std::vector<calls::MeshHit>;
  cases.push_back(caseOf<calls::MeshHits>({{positions, triangles, meshRays}},
                                          {{Hits{{0u, 1.0f}, {1u, 1.0f}}, Hits{{0u, 1.0f}}, Hits{}, Hits{{1u, 1.0f}}}}));

  const std::vector<calls::DirectQuery> queries(2);
  cases.push_back(caseOf<calls::ShadowRays>({{scene, calls::TraceSettings{}, queries}}, {{Color(0.5f), Color(0.0f)}}));
  AdaptivePixel pixel;
  pixel.samples = 3;
  cases.push_back(caseOf<calls::SamplePixels>({{std::vector<std::vector<Color>>(3), AdaptiveSettings{}}}, {{pixel, pixel, pixel}}));
  return cases;
}

const std::vector<Case>& cases() {
  static const std::vector<Case> all = makeCases();
  return all;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  if (const char* folder = std::getenv("PATHLAB_FUZZ_WRITE_SEEDS"); folder && *folder) {
    std::filesystem::create_directories(folder);
    for (size_t k = 0; k < cases().size(); ++k) {
      std::ofstream out(std::filesystem::path(folder) / ("answer-" + std::to_string(k)), std::ios::binary);
      out.put(char(k));
      out << cases()[k].rightAnswer;
      std::ofstream lie(std::filesystem::path(folder) / ("long-count-" + std::to_string(k)), std::ios::binary);
      const uint64_t count = 40000;
      lie.put(char(k));
      lie.write(reinterpret_cast<const char*>(&count), sizeof count);
      lie << std::string(count, '\0');
    }
  }
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  const Case& c = cases()[data[0] % cases().size()];
  try {
    c.decode(std::string(reinterpret_cast<const char*>(data) + 1, size - 1));
  } catch (const pathlab::wire::WireError&) {
  }
  return 0;
}
