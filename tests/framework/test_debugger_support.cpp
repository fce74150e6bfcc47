// What the GUI stands on: the progressive render, the pixel inspector, the
// camera controls, display encoding and every debugger view on the default
// scene. Linked with the reference tasks.
#include "suite/doctest_strings.h"

#include <cmath>
#include <cstring>

#include "core/camera.h"
#include "debug/debug_views.h"
#include "debug/inspect.h"
#include "render/render.h"
#include "render/task_wiring.h"
#include "scene/scene_io.h"
#include "util/image.h"

using namespace pathlab;

namespace {

Scene smallDefaultScene(int spp) {
  Scene scene = defaultScene();
  scene.render.width = 48;
  scene.render.height = 36;
  scene.render.samplesPerPixel = spp;
  return scene;
}

bool sameBits(const Image& a, const Image& b) {
  return a.width == b.width && a.height == b.height &&
         std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(Color)) == 0;
}

}  // namespace

TEST_CASE("progressive: small passes give the same image as render(), pass by pass") {
  const Scene scene = smallDefaultScene(12);
  RenderOptions options;
  options.progress = false;
  options.threads = 2;
  const Image whole = render(scene, options).image;

  options.maxPassSpp = 2;  // passes 1, 1, 2, 2, 2, 2, 2
  ProgressiveRender progressive(scene, options);
  std::vector<int> sppAfterPass;
  while (progressive.step()) sppAfterPass.push_back(progressive.stats().completedSpp);
  sppAfterPass.push_back(progressive.stats().completedSpp);
  CHECK(sppAfterPass == std::vector<int>{1, 2, 4, 6, 8, 10, 12});
  CHECK(progressive.done());
  CHECK_FALSE(progressive.step());
  CHECK(sameBits(progressive.image(), whole));

  // After 4 samples the image is the 4-spp render, whatever the passes were.
  Scene four = scene;
  four.render.samplesPerPixel = 4;
  ProgressiveRender partial(scene, options);
  while (partial.stats().completedSpp < 4) partial.step();
  options.maxPassSpp = 64;
  CHECK(sameBits(partial.image(), render(four, options).image));
}

TEST_CASE("progressive: cancelling stops before the next pass") {
  const Scene scene = smallDefaultScene(64);
  std::atomic<bool> cancel{false};
  RenderOptions options;
  options.progress = false;
  options.cancel = &cancel;
  ProgressiveRender progressive(scene, options);
  CHECK(progressive.step());
  cancel = true;
  CHECK_FALSE(progressive.step());
  CHECK(progressive.stats().completedSpp == 1);
  CHECK(progressive.stats().interrupted);
}

TEST_CASE("inspector: re-traced samples are the render's samples, with every ray recorded") {
  const Scene scene = smallDefaultScene(8);
  RenderOptions options;
  options.progress = false;
  const Image image = render(scene, options).image;
  const Accelerator accelerator(scene);
  const Lights lights = Lights::fromScene(scene, kLinkedTasks.environment);
  for (IVec2 pixel : {IVec2(24, 20), IVec2(3, 30), IVec2(40, 5)}) {
    CAPTURE(pixel);
    const PixelInspection inspection = inspectPixel(scene, accelerator, lights, options, pixel, 8);
    REQUIRE(inspection.samples.size() == 8);
    // The same sum in the same order: bit-identical to the rendered pixel.
    const Color rendered = image.at(pixel.x, pixel.y);
    CHECK(std::memcmp(&inspection.mean, &rendered, sizeof(Color)) == 0);
    for (const InspectedSample& sample : inspection.samples) {
      REQUIRE_FALSE(sample.rays.empty());
      CHECK_FALSE(sample.rays[0].shadow);  // the camera ray first
      CHECK(sample.raster.x >= float(pixel.x));
      CHECK(sample.raster.x < float(pixel.x + 1));
      CHECK(sample.lines.size() == sample.rays.size());
      for (const TracedRay& ray : sample.rays) {
        if (ray.hit && !ray.shadow) CHECK(glm::length(ray.ray.at(ray.record.t) - ray.record.point) < 1e-3f);
      }
    }
  }
  // The report names what happened.
  const std::string text =
      formatInspection(inspectPixel(scene, accelerator, lights, options, IVec2(24, 20), 2));
  CHECK(text.find("camera ray") != std::string::npos);
  CHECK(text.find("light sample") != std::string::npos);
  CHECK(text.find("sample 1 at") != std::string::npos);
}

TEST_CASE("inspector: NaN samples are flagged") {
  const Scene scene = smallDefaultScene(4);
  RenderOptions options;
  options.estimator = [](TraceContext& context, const Ray&, Sampler&) {
    return context.pixel.x == 5 ? Color(std::nanf("")) : Color(1.0f);
  };
  const Accelerator accelerator(scene);
  const Lights lights = Lights::fromScene(scene, kLinkedTasks.environment);
  const PixelInspection bad = inspectPixel(scene, accelerator, lights, options, IVec2(5, 5), 4);
  CHECK(bad.nonFinite == 4);
  CHECK(formatInspection(bad).find("NaN/Inf") != std::string::npos);
  CHECK(inspectPixel(scene, accelerator, lights, options, IVec2(6, 5), 4).nonFinite == 0);
}

TEST_CASE("camera controls: orbit keeps the distance and the target, and stops short of the poles") {
  Camera camera;
  camera.position = {0.0f, 1.0f, 4.0f};
  camera.lookAt = {0.0f, 1.0f, 0.0f};
  const Camera turned = orbitCamera(camera, 90.0f, 0.0f);
  CHECK(glm::length(turned.position - Point3(4.0f, 1.0f, 0.0f)) < 1e-5f);  // yaw about +y: z -> x
  CHECK(turned.lookAt == camera.lookAt);
  const Camera round = orbitCamera(orbitCamera(camera, 200.0f, 0.0f), 160.0f, 0.0f);
  CHECK(glm::length(round.position - camera.position) < 1e-4f);
  const Camera raised = orbitCamera(camera, 0.0f, 30.0f);  // drag up: the eye rises
  CHECK(raised.position.y > camera.position.y);
  CHECK(std::abs(glm::length(raised.position - raised.lookAt) - 4.0f) < 1e-4f);
  const Camera top = orbitCamera(camera, 0.0f, 120.0f);  // past the pole: clamped at 5 degrees
  const float polar = glm::degrees(std::acos(glm::normalize(top.position - top.lookAt).y));
  CHECK(polar == doctest::Approx(5.0f).epsilon(1e-3));

  const Camera panned = panCamera(camera, Vec2(10.0f, 0.0f), 100);
  CHECK(panned.position.x < camera.position.x);  // dragging right moves the scene right: the eye goes left
  CHECK(panned.position - camera.position == panned.lookAt - camera.lookAt);
  const Camera closer = dollyCamera(camera, 0.5f);
  CHECK(glm::length(closer.position - closer.lookAt) == doctest::Approx(2.0f));
}

TEST_CASE("display: 8-bit sRGB encoding inverts srgbToLinear for every byte") {
  Image image(256, 1);
  for (int v = 0; v < 256; ++v) image.at(v, 0) = Color(srgbToLinear(float(v) / 255.0f));
  const std::vector<uint8_t> bytes = encodeSrgb8(image, 4);
  for (int v = 0; v < 256; ++v) {
    CHECK(bytes[size_t(4 * v)] == v);
    CHECK(bytes[size_t(4 * v + 3)] == 255);
  }
  CHECK(encodeSrgb8(Image(1, 1, Color(0.25f)), 3, 4.0f)[0] == 255);  // exposure scales before encoding
}

TEST_CASE("views: every debugger view renders the default scene, with and without an orbit camera") {
  Scene scene = smallDefaultScene(4);
  for (const DebugView& view : allDebugViews()) {
    CAPTURE(view.task);
    CAPTURE(view.name);
    DebugViewRequest request(scene, scene.render.width, scene.render.height);
    request.pixel = {20, 25};
    const DebugOutput output = view.render(request);
    CHECK(output.image.width > 0);
    if (view.inputs & kCameraImage) {
      CHECK(output.image.width == request.width);
      CHECK(output.image.height >= request.height);
    }
    if (view.inputs & kUsesViewCamera) {
      request.viewCamera = orbitCamera(scene.camera, 40.0f, 20.0f);
      const DebugOutput orbited = view.render(request);
      CHECK_FALSE(sameBits(orbited.image, output.image));
    }
  }
}
