// Framework tests: reproducible rendering, the two traversals, NaN
// accounting, image I/O, random numbers and the sampling strategies. Linked
// with the reference tasks.
#include "suite/doctest_strings.h"

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "check.h"
#include "course_scene.h"
#include "util/error.h"
#include "util/image.h"
#include "scene/procedural.h"
#include "util/random.h"
#include "render/render.h"
#include "render/strategies.h"
#include "scene/scene_io.h"
#include "tasks/path_tracing.h"
#include "meshes.h"
#include "render_support.h"
#include "statistics.h"

using namespace pathlab;
using namespace pathlab::test;

namespace {

bool bitIdentical(const Image& a, const Image& b) {
  return a.width == b.width && a.height == b.height &&
         std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(Color)) == 0;
}

}  // namespace

TEST_CASE("render: 1, 2 and 8 threads, and any tile size, give bit-identical images") {
  Scene scene = defaultScene();
  scene.render.width = 64;
  scene.render.height = 48;
  scene.render.samplesPerPixel = 5;
  RenderOptions options;
  options.progress = false;
  options.threads = 1;
  Image one = render(scene, options).image;
  options.threads = 2;
  Image two = render(scene, options).image;
  options.threads = 8;
  Image eight = render(scene, options).image;
  options.tileSize = 7;
  Image oddTiles = render(scene, options).image;
  options.threads = 3;
  options.tileSize = 64;
  Image bigTiles = render(scene, options).image;
  CHECK(bitIdentical(one, two));
  CHECK(bitIdentical(one, eight));
  CHECK(bitIdentical(one, oddTiles));
  CHECK(bitIdentical(one, bigTiles));
  scene.render.seed = 1;
  CHECK_FALSE(bitIdentical(one, render(scene, options).image));  // the seed matters
}

TEST_CASE("render: --accel fast and task3 give bit-identical images (the same hits)") {
  // The scan-like mesh (tens of thousands of tiny triangles, shared edges)
  // and the default box with its spheres, mirror and glass.
  for (int which = 0; which < 2; ++which) {
    Scene scene = which == 0 ? defaultScene() : scanLikeScene();
    scene.render.width = 64;
    scene.render.height = 48;
    scene.render.samplesPerPixel = 4;
    RenderOptions options;
    options.progress = false;
    options.traversal = Traversal::Task3;
    const RenderResult task3 = render(scene, options);
    options.traversal = Traversal::Fast;
    const RenderResult fast = render(scene, options);
    CAPTURE(which);
    CHECK(bitIdentical(task3.image, fast.image));
    CHECK(task3.stats.rays == fast.stats.rays);
  }
  CHECK(defaultTraversal("1:reference 2:reference 3:reference 4:student") == Traversal::Fast);
  CHECK(defaultTraversal("1:reference 2:reference 3:student 4:reference") == Traversal::Task3);
  CHECK(defaultTraversal("1:reference 2:student 3:reference 4:reference") == Traversal::Task3);  // packets are the reference's test
  CHECK(defaultTraversal("unknown") == Traversal::Task3);
}

TEST_CASE("render: a cancelled render stops early and says how far it got") {
  Scene scene = defaultScene();
  scene.render.samplesPerPixel = 64;
  std::atomic<bool> cancel{true};
  RenderOptions options;
  options.progress = false;
  options.cancel = &cancel;
  RenderResult result = render(scene, options);
  CHECK(result.stats.interrupted);
  CHECK(result.stats.completedSpp == 0);
}

TEST_CASE("render: NaN and Inf samples are counted, located and left out, never clamped") {
  Scene scene = defaultScene();
  scene.render.width = 20;
  scene.render.height = 10;
  scene.render.samplesPerPixel = 4;
  RenderOptions options;
  options.progress = false;
  options.threads = 2;
  options.estimator = [](TraceContext& context, const Ray&, Sampler&) -> Color {
    if (context.pixel == IVec2(7, 3)) return Color(std::nanf(""), 1.0f, 1.0f);
    if (context.pixel == IVec2(2, 8)) return Color(kInfinity);
    return Color(5.0f);  // above 1: must not be clamped
  };
  RenderResult result = render(scene, options);
  CHECK(result.stats.nonFiniteSamples == 8);
  REQUIRE(result.stats.firstNonFinitePixel.has_value());
  CHECK(*result.stats.firstNonFinitePixel == IVec2(7, 3));  // first in scanline order
  CHECK(result.image.at(7, 3) == Color(0.0f));
  CHECK(result.image.at(0, 0) == Color(5.0f));
  CHECK(result.stats.completedSpp == 4);
}

TEST_CASE("image: EXR round-trips exactly, PNG within one 8-bit step") {
  Image image(5, 3);
  for (size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = Color(0.1f * float(i), 0.5f, 3.0f);
  auto dir = std::filesystem::temp_directory_path();
  writeImage(image, (dir / "pathlab-test.exr").string());
  Image exr = readImage((dir / "pathlab-test.exr").string());
  CHECK(bitIdentical(image, exr));
  writeImage(image, (dir / "pathlab-test.png").string());
  Image png = readImage((dir / "pathlab-test.png").string());
  REQUIRE(png.width == 5);
  for (size_t i = 0; i < image.pixels.size(); ++i) {
    for (int c = 0; c < 3; ++c) {
      float expected = std::min(1.0f, image.pixels[i][c]);
      CHECK(std::abs(linearToSrgb(png.pixels[i][c]) - linearToSrgb(expected)) <= 0.5f / 255.0f + 1e-6f);
    }
  }
  CHECK_THROWS_AS(readImage((dir / "no-such-image.exr").string()), Error);
  // Written through a temporary file and a rename: nothing else is left behind.
  CHECK_FALSE(std::filesystem::exists(dir / ".pathlab-test.partial.exr"));
  CHECK_THROWS_AS(writeImage(image, (dir / "x.unknown").string()), Error);
}

TEST_CASE("random: the sampler is uniform in [0, 1) and independent across dimensions and pixels") {
  // Chi-square over 64 bins with 640k draws: the statistic's mean is 63 and
  // its standard deviation 11.2; 150 is p < 1e-9, so no false failures.
  constexpr int kBins = 64, kDraws = 10000;
  std::vector<int> counts(kBins, 0);
  double productSum = 0.0;
  for (uint32_t pixel = 0; pixel < 64; ++pixel) {
    for (uint32_t s = 0; s < kDraws / 2; ++s) {
      Sampler sampler(pixel, s, 7);
      float a = sampler.next1D(), b = sampler.next1D();
      REQUIRE(a >= 0.0f);
      REQUIRE(a < 1.0f);
      counts[size_t(a * kBins)]++;
      counts[size_t(b * kBins)]++;
      productSum += (a - 0.5) * (b - 0.5);
    }
  }
  double n = 0;
  for (int c : counts) n += c;
  double chi2 = 0.0;
  for (int c : counts) chi2 += (c - n / kBins) * (c - n / kBins) / (n / kBins);
  CHECK(chi2 < 150.0);
  // Correlation of consecutive dimensions: standard error 1/sqrt(n/2).
  CHECK(std::abs(productSum / (n / 2) * 12.0) < 6.0 / std::sqrt(n / 2));
  Sampler a(1, 2, 3), b(1, 2, 3);
  CHECK(a.next1D() == b.next1D());
}

TEST_CASE("lights: a constant sky's pixel radiance is its colour, in every direction") {
  // pixelRadiance is what lighting integrates; without a map there is no
  // pixel to read (it read outside an empty image before).
  Scene scene;
  scene.environment = Environment{};
  scene.environment->color = Color(0.3f, 0.5f, 0.7f);
  scene.environment->scale = 2.0f;
  const Lights lights = Lights::fromScene(scene, kLinkedTasks.environment);
  REQUIRE(lights.environment.has_value());
  test::Random random(17);
  for (int i = 0; i < 100; ++i) {
    const Vec3 w(random.unitVector());
    CHECK(lights.environment->pixelRadiance(w) == Color(0.6f, 1.0f, 1.4f));
    CHECK(lights.environment->radiance(w) == Color(0.6f, 1.0f, 1.4f));
  }
}

TEST_CASE("strategies: every sampling strategy, and task 9's four estimators, are unbiased (closed enclosure and sky furnace)") {
  // Inside a closed enclosure of albedo 1/2 and emission 1/2, L = 1 exactly
  // (any closed shape: 320 triangles are enough); each strategy must agree
  // within 5 standard errors (false failure 5.7e-7). Paths stop after 16
  // bounces, which leaves out 2^-17 = 7.6e-6 of L: about 1 % of the smallest
  // standard error here (6.7e-4, no-rr), so the false-failure rate stays 5.7e-7.
  Scene enclosure;
  enclosure.materials.push_back(Material{.name = "wall", .albedo = Color(0.5f), .emission = Color(0.5f)});
  TriangleMesh mesh = test::icosphere(2, Point3(0.0f), 1.0f);
  for (glm::uvec3& t : mesh.triangles) std::swap(t.y, t.z);  // facing inwards
  enclosure.meshes.push_back(mesh);
  // A grey sky over an albedo-0.8 sphere: every camera ray that hits it sees 0.8 * 0.5.
  Scene sky;
  sky.materials.push_back(Material{.name = "ball", .albedo = Color(0.8f)});
  sky.spheres.push_back(Sphere{Point3(0.0f), 1.0f, 0});
  sky.environment = Environment{};
  sky.environment->image = Image(16, 8, Color(0.5f));
  struct Case {
    const char* name;
    SamplingStrategy strategy;
    int lightSamples = 1;
    std::optional<MisEstimator> mis;  // task 9's tracePathMis with these weights instead
  };
  const Case cases[] = {
      {"recipe", {}, 1, std::nullopt},
      {"recipe, 4 light samples", {}, 4, std::nullopt},
      {"uniform-hemisphere", {.cosineSampling = false}, 1, std::nullopt},
      {"no-nee", {.lightSampling = false}, 1, std::nullopt},
      {"no-rr", {.russianRoulette = false}, 1, std::nullopt},
      {"task 9, mis-balance", {}, 1, MisEstimator::Balance},
      {"task 9, mis-power", {}, 1, MisEstimator::Power},
      {"task 9, light sampling alone", {}, 1, MisEstimator::LightSampling},
      {"task 9, BSDF sampling alone", {}, 1, MisEstimator::BsdfSampling},
  };
  test::Rig insideRig(enclosure), skyRig(sky);
  for (const Case& strategy : cases) {
    for (int scene = 0; scene < 2; ++scene) {
      TraceContext context = scene == 0 ? insideRig.context(16, strategy.lightSamples) : skyRig.context(8, strategy.lightSamples);
      test::Random random(81 + uint32_t(scene));
      test::MeanEstimate m;
      for (int i = 0; i < 20000; ++i) {
        Sampler sampler(uint32_t(i), 0, test::testSeed(81));
        Ray ray = scene == 0 ? Ray{Point3(0.1f, 0.0f, -0.2f), Vec3(random.unitVector())}
                             : Ray{Point3(0.0f, 0.0f, 4.0f), Vec3(glm::normalize(random.inCube(0.6) - test::DVec3(0, 0, 4)))};
        m.add((strategy.mis ? tracePathMis(context, ray, sampler, misWeights(*strategy.mis))
                            : traceWithStrategy(context, ray, sampler, strategy.strategy)).y);
      }
      const double expected = scene == 0 ? 1.0 : 0.4;
      m.judgeByOwnNoise();  // the framework's strategies, not a candidate's
      CAPTURE(strategy.name);
      CAPTURE(scene);
      INFO(m.describe(expected));
      CHECK(m.agrees(expected));
    }
  }
}

namespace {

// Diffuse, mirror and glass spheres on a floor under a map with a bright spot.
Scene mappedSkyScene() {
  Scene scene;
  scene.materials.push_back(Material{.name = "floor", .albedo = Color(0.6f)});
  scene.materials.push_back(Material{.name = "mirror", .type = MaterialType::Mirror, .albedo = Color(0.9f)});
  scene.materials.push_back(Material{.name = "glass", .type = MaterialType::Glass, .albedo = Color(1.0f)});
  test::addQuad(scene, {-4, -1, 4}, {8, 0, 0}, {0, 0, -8}, 0);
  scene.spheres.push_back(Sphere{Point3(-1.2f, 0.0f, 0.0f), 1.0f, 0});
  scene.spheres.push_back(Sphere{Point3(1.2f, 0.0f, 0.0f), 1.0f, 1});
  scene.spheres.push_back(Sphere{Point3(0.0f, 0.5f, 1.5f), 0.5f, 2});
  scene.environment = Environment{};
  scene.environment->image = Image(32, 16, Color(0.3f, 0.4f, 0.6f));
  scene.environment->image.at(20, 4) = Color(500.0f);
  scene.camera.position = Point3(0.0f, 1.0f, 6.0f);
  scene.camera.lookAt = Point3(0.0f, 0.0f, 0.0f);
  return scene;
}

}  // namespace

TEST_CASE("strategies: the recipe strategy is the model answers' tracePath, sample for sample") {
  // The same random numbers in the same order: bit-identical radiance on the
  // default scene (lights, mirror, glass) and under an environment map.
  for (int which = 0; which < 2; ++which) {
    Scene scene = which == 0 ? defaultScene() : mappedSkyScene();
    test::Rig rig(std::move(scene));
    TraceContext recipe = rig.context(6, 2), strategy = rig.context(6, 2);
    const CameraBasis basis = cameraBasis(rig.scene().camera);
    int differing = 0;
    for (uint32_t i = 0; i < 4000; ++i) {
      const IVec2 pixel(int(i % 64), int(i / 64));
      const Ray ray = generateCameraRay(rig.scene().camera, basis, Point2(pixel) * 4.0f + 0.5f, {256, 256});
      Sampler a(i, 0, 7), b(i, 0, 7);
      const Color x = tracePath(recipe, ray, a), y = traceWithStrategy(strategy, ray, b, SamplingStrategy{});
      if (x != y) ++differing;
    }
    CAPTURE(which);
    CHECK(differing == 0);
    CHECK(recipe.rays == strategy.rays);
  }
}
