// Framework tests: JSON and OBJ scene loading and its error messages (the
// course's COLLADA files: test_collada.cpp; rendering, images, random
// numbers and strategies: test_render.cpp). Linked with the reference tasks.
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

// The one-line error a scene text produces, or "" when it loads.
std::string loadError(const std::string& json) {
  try {
    loadSceneFromJson(json, "test.json", ".");
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("maths: maxComponent ignores NaN components, as std::fmax does") {
  const float nan = std::nanf("");
  CHECK(maxComponent(Vec3(-1.0f, -3.0f, -2.0f)) == -1.0f);
  CHECK(maxComponent(Vec3(nan, 1.0f, 2.0f)) == 2.0f);
  CHECK(maxComponent(Vec3(3.0f, nan, 2.0f)) == 3.0f);
  CHECK(maxComponent(Vec3(0.5f, 1.0f, nan)) == 1.0f);
  CHECK(std::isnan(maxComponent(Vec3(nan))));
}

TEST_CASE("scene: the embedded default scene is the Cornell box with two spheres") {
  Scene scene = defaultScene();
  CHECK(scene.meshes.size() == 6);
  CHECK(scene.spheres.size() == 2);
  CHECK(scene.triangleCount() == 12);
  CHECK(scene.primitives.size() == 14);
  int emissive = 0;
  for (const Material& m : scene.materials) emissive += m.isEmissive();
  CHECK(emissive == 1);
}

TEST_CASE("scene: a minimal scene is a few lines and every field has a default") {
  Scene scene = loadSceneFromJson(R"({"spheres": [{"radius": 2}]})", "min.json", ".");
  REQUIRE(scene.spheres.size() == 1);
  CHECK(scene.spheres[0].radius == 2.0f);
  CHECK(scene.materials.size() == 1);  // the implicit "default" material
  CHECK(scene.render.width == 400);
  CHECK(scene.render.samplesPerPixel == 16);
  CHECK(loadError("{}") == "");
}

TEST_CASE("scene: errors name the file, the line or field, and what was expected") {
  SUBCASE("bad JSON gives line and column") {
    std::string e = loadError("{\n  \"spheres\": [\n    {\"radius\": 1,}\n  ]\n}");
    CHECK(e.rfind("test.json:3:", 0) == 0);
    CHECK(e.find("invalid JSON") != std::string::npos);
  }
  SUBCASE("truncated JSON") { CHECK(loadError("{\"spheres\": [").find("invalid JSON") != std::string::npos); }
  SUBCASE("unknown key with a suggestion") {
    std::string e = loadError(R"({"spheres": [{"raduis": 1}]})");
    CHECK(e == "test.json: spheres[0]: unknown key \"raduis\" (did you mean \"radius\"?)");
  }
  SUBCASE("unknown top-level key") {
    CHECK(loadError(R"({"camrea": {}})").find("did you mean \"camera\"") != std::string::npos);
  }
  SUBCASE("wrong type") {
    CHECK(loadError(R"({"spheres": [{"radius": "big"}]})") ==
          "test.json: spheres[0].radius: expected a number, got string \"big\"");
  }
  SUBCASE("negative radius") {
    CHECK(loadError(R"({"spheres": [{"radius": -0.5}]})") ==
          "test.json: spheres[0].radius: expected a positive number, got number -0.5");
  }
  SUBCASE("number too large for a float") {
    CHECK(loadError(R"({"spheres": [{"center": [0, 1e39, 0]}]})") ==
          "test.json: spheres[0].center[1]: expected a finite number, got 1e+39");
  }
  SUBCASE("number too large for JSON") {
    CHECK(loadError(R"({"spheres": [{"center": [0, 1e999, 0]}]})") ==
          "test.json: invalid JSON: number overflow parsing '1e999'");
  }
  SUBCASE("zero spp") {
    CHECK(loadError(R"({"render": {"spp": 0}})") ==
          "test.json: render.spp: expected an integer in [1, 1048576], got 0");
  }
  SUBCASE("fractional spp") {
    CHECK(loadError(R"({"render": {"spp": 2.5}})").find("expected an integer") != std::string::npos);
  }
  SUBCASE("absurd resolution") {
    CHECK(loadError(R"({"render": {"width": 1000000, "height": 1000000}})").find("render.width") != std::string::npos);
  }
  SUBCASE("unknown material") {
    std::string e = loadError(R"({"materials": {"red": {}}, "spheres": [{"material": "blue"}]})");
    CHECK(e == "test.json: spheres[0].material: unknown material \"blue\" (defined: \"red\")");
  }
  SUBCASE("albedo above one") {
    CHECK(loadError(R"({"materials": {"m": {"albedo": [1.2, 0, 0]}}})").find("materials.m.albedo") != std::string::npos);
  }
  SUBCASE("missing OBJ names the path it tried") {
    std::string e = loadError(R"({"meshes": [{"obj": "nowhere/bunny.obj"}]})");
    CHECK(e.find("meshes[0].obj: ") != std::string::npos);
    CHECK(e.find("nowhere/bunny.obj: cannot open OBJ file: No such file or directory") != std::string::npos);
  }
  SUBCASE("triangle index out of range") {
    CHECK(loadError(R"({"meshes": [{"positions": [[0,0,0],[1,0,0],[0,1,0]], "triangles": [[0,1,3]]}]})")
              .find("meshes[0].triangles[0]") != std::string::npos);
  }
  SUBCASE("zero-area mesh") {
    CHECK(loadError(R"({"meshes": [{"positions": [[0,0,0],[1,0,0],[2,0,0]], "triangles": [[0,1,2]]}]})")
              .find("zero area") != std::string::npos);
  }
  SUBCASE("camera looking at itself") {
    CHECK(loadError(R"({"camera": {"position": [1,2,3], "look_at": [1,2,3]}})").find("camera.look_at") != std::string::npos);
  }
  SUBCASE("field of view out of range") {
    CHECK(loadError(R"({"camera": {"vfov": 180}})").find("camera.vfov") != std::string::npos);
  }
}

TEST_CASE("scene: OBJ meshes load with transforms, relative to the scene file") {
  auto dir = std::filesystem::temp_directory_path() / "pathlab-test-obj";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "quad.obj") << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n";
  std::ofstream(dir / "scene.json") << R"({"meshes": [{"obj": "quad.obj", "transform": {"scale": 2, "translate": [0, 0, -3]}}]})";
  Scene scene = loadScene((dir / "scene.json").string());
  REQUIRE(scene.meshes.size() == 1);
  CHECK(scene.meshes[0].triangles.size() == 2);
  Vec3 lo(kInfinity), hi(-kInfinity);
  for (const Point3& p : scene.meshes[0].positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
  CHECK(near(lo, Vec3(0, 0, -3), 1e-6f));
  CHECK(near(hi, Vec3(2, 2, -3), 1e-6f));
}


TEST_CASE("scene: a coil is a closed loop of long, thin triangles facing out of the wire") {
  const Scene scene = loadSceneFromJson(
      R"({"meshes": [{"coil": {"turns": 3, "segments": 16, "sides": 6, "wire": 0.05}}]})", "c.json", ".");
  REQUIRE(scene.meshes.size() == 1);
  const TriangleMesh& mesh = scene.meshes[0];
  CHECK(mesh.triangles.size() == 2 * 3 * 16 * 6);
  int outward = 0;
  float leastAspect = kInfinity;  // longest edge / height
  for (const glm::uvec3& t : mesh.triangles) {
    const Point3 a = mesh.positions[t.x], b = mesh.positions[t.y], c = mesh.positions[t.z];
    const Vec3 n = glm::cross(b - a, c - a);
    const Point3 centroid = (a + b + c) / 3.0f;
    // The helix point at the centroid's height: the wire's axis there.
    const float s = (centroid.y + 1.0f) / 2.0f, angle = 2.0f * kPi * 3.0f * s;
    const Point3 axis(std::cos(angle), centroid.y, std::sin(angle));
    outward += glm::dot(n, centroid - axis) > 0.0f;
    const float longest = std::max({glm::length(b - a), glm::length(c - b), glm::length(a - c)});
    leastAspect = std::min(leastAspect, longest * longest / glm::length(n));
  }
  CHECK(outward == int(mesh.triangles.size()));
  CHECK(leastAspect > 6.0f);  // about 2 pi / 16 long, 2 pi 0.05 / 6 wide: 7.6
  CHECK(loadError(R"({"meshes": [{"coil": {"wire": 2}}]})").find("meshes[0].coil.wire") != std::string::npos);
  CHECK(loadError(R"({"meshes": [{"coil": {"turns": 0}}]})").find("meshes[0].coil.turns") != std::string::npos);
  CHECK(loadError(R"({"meshes": [{"coil": {"turns": 4096, "segments": 4096, "sides": 256}}]})")
            .find("more than 4,194,304 quads") != std::string::npos);
  CHECK(loadError(R"({"meshes": [{"coil": {}, "quad": {}}]})").find("exactly one of") != std::string::npos);
}
