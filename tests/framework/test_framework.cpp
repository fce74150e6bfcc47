// Framework tests: scene loading and its error messages, reproducible
// rendering, image I/O, random numbers. Linked with the reference tasks.
#include <doctest/doctest.h>

#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "check.h"
#include "course_scene.h"
#include "pathlab/error.h"
#include "pathlab/image.h"
#include "pathlab/procedural.h"
#include "pathlab/random.h"
#include "pathlab/render.h"
#include "pathlab/strategies.h"
#include "pathlab/scene_io.h"
#include "pathlab/tasks/path_tracing.h"
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

bool bitIdentical(const Image& a, const Image& b) {
  return a.width == b.width && a.height == b.height &&
         std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(Color)) == 0;
}

}  // namespace

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

// The Cornell boxes the course ships, as its exporter writes them.
void checkCourseCornellBox(const Scene& scene, bool mirrorAndGlass) {
  CHECK(scene.meshes.size() == 6);   // floor, ceiling, three walls, the light
  CHECK(scene.triangleCount() == 12);
  REQUIRE(scene.spheres.size() == 2);
  CHECK(scene.spheres[0].radius == doctest::Approx(0.3f));
  CHECK(scene.pointLights.empty());  // the <area> light is the emissive mesh
  int emissive = 0, mirrors = 0, glass = 0;
  for (const TriangleMesh& m : scene.meshes) emissive += scene.materials[m.material].isEmissive();
  for (const Sphere& sphere : scene.spheres) {
    mirrors += scene.materials[sphere.material].type == MaterialType::Mirror;
    glass += scene.materials[sphere.material].type == MaterialType::Glass;
  }
  CHECK(emissive == 1);
  if (mirrorAndGlass) {
    CHECK(mirrors == 1);
    CHECK(glass == 1);
  }
  CHECK(scene.render.width == 400);
  CHECK(scene.render.height == 300);  // aspect ratio 1.333 from the file
  // Z-up file: the camera looks along -y with z up, at the box's centre.
  CHECK(near(glm::normalize(scene.camera.lookAt - scene.camera.position), Vec3(0, -1, 0), 1e-4f));
  CHECK(scene.camera.up.z > 0.99f);
  // The light faces down (-z): its geometric normal from the winding.
  for (const TriangleMesh& m : scene.meshes) {
    if (!scene.materials[m.material].isEmissive()) continue;
    const glm::uvec3& t = m.triangles[0];
    Vec3 n = glm::cross(m.positions[t.y] - m.positions[t.x], m.positions[t.z] - m.positions[t.x]);
    CHECK(n.z < 0.0f);
  }
}

TEST_CASE("scene: the course's COLLADA Cornell boxes load with their materials, lights and camera") {
  const auto dir = std::filesystem::temp_directory_path() / "pathlab-test-course";
  std::filesystem::create_directories(dir);
  for (const char* profile : {"CMU462", "CGL"}) {
    for (bool mirrorAndGlass : {false, true}) {
      CAPTURE(profile);
      CAPTURE(mirrorAndGlass);
      const auto path = dir / (std::string(profile) + (mirrorAndGlass ? "-CBspheres.dae" : "-CBspheres_lambertian.dae"));
      std::ofstream(path) << courseCornellBox({.profile = profile, .mirrorAndGlass = mirrorAndGlass});
      checkCourseCornellBox(loadScene(path.string()), mirrorAndGlass);
    }
  }
}

// What the code in its scope writes to stderr (file descriptor 2, so also
// what C stdio and std::cerr write), captured in a temporary file.
class StderrCapture {
 public:
  StderrCapture() {
    std::fflush(stderr);
    file_ = std::tmpfile();
    REQUIRE(file_ != nullptr);
    saved_ = dup(2);
    dup2(fileno(file_), 2);
  }
  ~StderrCapture() {
    restore();
    std::fclose(file_);
  }
  StderrCapture(const StderrCapture&) = delete;
  StderrCapture& operator=(const StderrCapture&) = delete;
  std::string text() {
    restore();
    std::string out;
    std::rewind(file_);
    for (int c; (c = std::fgetc(file_)) != EOF;) out += char(c);
    return out;
  }

 private:
  void restore() {
    if (saved_ < 0) return;
    std::fflush(stderr);
    dup2(saved_, 2);
    close(saved_);
    saved_ = -1;
  }
  std::FILE* file_ = nullptr;
  int saved_ = -1;
};

// A course file written by courseCornellBox (or given), loaded: the scene
// and what the load printed on stderr.
struct CourseLoad {
  Scene scene;
  std::string path;
  std::string printed;
};

std::string writeCourseFile(const std::string& name, const std::string& dae) {
  const auto dir = std::filesystem::temp_directory_path() / "pathlab-test-course-repairs";
  std::filesystem::create_directories(dir);
  const std::string path = (dir / name).string();
  std::ofstream(path) << dae;
  return path;
}

CourseLoad loadCourseBox(const std::string& name, const CourseBoxOptions& options) {
  CourseLoad load;
  load.path = writeCourseFile(name, courseCornellBox(options));
  StderrCapture capture;
  load.scene = loadScene(load.path);
  load.printed = capture.text();
  return load;
}

// The error a course file gives (or "" when it loads), and that nothing
// else was printed.
std::string courseFileError(const std::string& name, const std::string& dae) {
  const std::string path = writeCourseFile(name, dae);
  StderrCapture capture;
  std::string error;
  try {
    loadScene(path);
  } catch (const Error& e) {
    error = e.what();
  }
  CHECK(capture.text() == "");
  return error;
}

// A tiny render of a loaded course box: finite, and the camera sees the lit
// inside of the box (most pixels are not black), not the back of a wall.
void checkRendersTheBox(Scene scene) {
  scene.render.width = 24;
  scene.render.height = 18;
  scene.render.samplesPerPixel = 4;
  RenderOptions options;
  options.progress = false;
  options.threads = 2;
  RenderResult result = render(scene, options);
  CHECK(result.stats.nonFiniteSamples == 0);
  size_t lit = 0;
  bool allFinite = true;
  for (const Color& c : result.image.pixels) {
    allFinite = allFinite && finite(c);
    lit += maxComponent(c) > 0.0f;
  }
  CHECK(allFinite);
  CHECK(lit * 2 > result.image.pixels.size());
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  REQUIRE(at != std::string::npos);
  return text.replace(at, from.size(), to);
}

TEST_CASE("scene: a course camera matrix of 15 numbers loads as the course's viewer reads it, with one warning") {
  for (const char* profile : {"CMU462", "CGL"}) {
    for (bool mirrorAndGlass : {false, true}) {
      CAPTURE(profile);
      CAPTURE(mirrorAndGlass);
      CourseLoad load = loadCourseBox(std::string(profile) + "-camera15.dae",
                                      {.profile = profile, .mirrorAndGlass = mirrorAndGlass, .cameraMatrixNumbers = 15});
      // The missing 16th number is the bottom row's 1, which an affine
      // transform does not use: the camera is the file's.
      CHECK(load.printed == "warning: " + load.path +
                                ": node \"Camera\"/matrix has 15 numbers, not 16; the missing ones are taken as 0\n");
      checkCourseCornellBox(load.scene, mirrorAndGlass);
      if (mirrorAndGlass) checkRendersTheBox(load.scene);
    }
  }
}

TEST_CASE("scene: a course camera matrix too short for a direction is framed from the scene's bounds") {
  for (const char* profile : {"CMU462", "CGL"}) {
    CAPTURE(profile);
    // 8 numbers: the rotation's third row and the camera's height are 0.
    CourseLoad load = loadCourseBox(std::string(profile) + "-camera8.dae", {.profile = profile, .cameraMatrixNumbers = 8});
    CHECK(load.printed == "warning: " + load.path +
                              ": node \"Camera\"/matrix has 8 numbers, not 16; the missing ones are taken as 0, which "
                              "leaves the camera no usable direction, so it is framed from the scene's bounds: it looks "
                              "along (0.00 -0.97 0.24) at their centre, from the distance where they fill the view\n");
    const Camera& camera = load.scene.camera;
    REQUIRE(finite(camera.position));
    // From where the file's numbers put it, (0, 3, 0), at the box's centre.
    const Point3 center(0.0f, 0.0f, 0.75f);
    CHECK(near(camera.lookAt, center, 1e-3f));
    CHECK(near(glm::normalize(camera.lookAt - camera.position), glm::normalize(center - Point3(0, 3, 0)), 1e-3f));
    CHECK(camera.up.z > 0.9f);
    checkRendersTheBox(load.scene);
  }
  // The same for a full matrix with no rotation in it (it used to give a
  // camera of NaNs), in a warning of its own.
  const std::string path = writeCourseFile(
      "camera-singular.dae",
      replaced(courseCornellBox(), "-1 0 0 0 0 0 1 3 0 1 0 0 0 0 0 1", "0 0 0 0 0 0 0 3 0 0 0 0 0 0 0 1"));
  StderrCapture capture;
  const Scene scene = loadScene(path);
  CHECK(capture.text() == "warning: " + path +
                              ": node \"Camera\": the camera's transform gives no usable direction, so it is framed "
                              "from the scene's bounds: it looks along (0.00 -0.97 0.24) at their centre, from the "
                              "distance where they fill the view\n");
  CHECK(finite(scene.camera.position));
}

TEST_CASE("scene: a short matrix on a course geometry node keeps what still has area") {
  for (const char* profile : {"CMU462", "CGL"}) {
    CAPTURE(profile);
    SUBCASE("15 numbers: nothing changes") {
      CourseLoad load = loadCourseBox(std::string(profile) + "-wall15.dae", {.profile = profile, .backWallMatrixNumbers = 15});
      CHECK(load.printed == "warning: " + load.path +
                                ": node \"backWall\"/matrix has 15 numbers, not 16; the missing ones are taken as 0\n");
      checkCourseCornellBox(load.scene, true);
    }
    SUBCASE("8 numbers: the wall is flattened to a line and left out") {
      CourseLoad load = loadCourseBox(std::string(profile) + "-wall8.dae", {.profile = profile, .backWallMatrixNumbers = 8});
      CHECK(load.printed == "warning: " + load.path +
                                ": node \"backWall\"/matrix has 8 numbers, not 16; the missing ones are taken as 0; "
                                "that flattens the geometry of node \"backWall\", and what has no area left is left out\n");
      CHECK(load.scene.meshes.size() == 5);
      for (const TriangleMesh& m : load.scene.meshes) CHECK(m.name.find("backWall") == std::string::npos);
      checkRendersTheBox(load.scene);
    }
  }
}

TEST_CASE("scene: CS184 <microfacet> and <refraction> materials load as the closest PathLab material, with one warning") {
  const std::string metal = "in the metal's colour at normal incidence (0.93 0.79 0.40)\n";
  SUBCASE("rough microfacet: diffuse") {
    CourseLoad load = loadCourseBox("CGL-microfacet.dae", {.profile = "CGL", .microfacet = true});
    CHECK(load.printed == "warning: " + load.path +
                              ": effect \"gold-effect\" has a CGL <microfacet> material (alpha 0.5), which PathLab does "
                              "not have; it is rendered as diffuse " + metal);
    REQUIRE(load.scene.spheres.size() == 2);
    const Material& gold = load.scene.materials[load.scene.spheres[1].material];
    CHECK(gold.type == MaterialType::Diffuse);
    CHECK(near(gold.albedo, Vec3(0.9277f, 0.7883f, 0.4032f), 1e-3f));
    checkRendersTheBox(load.scene);
  }
  SUBCASE("nearly smooth microfacet: a mirror") {
    CourseLoad load =
        loadCourseBox("CGL-microfacet-smooth.dae", {.profile = "CGL", .microfacet = true, .microfacetAlpha = 0.05f});
    CHECK(load.printed == "warning: " + load.path +
                              ": effect \"gold-effect\" has a CGL <microfacet> material (alpha 0.05), which PathLab "
                              "does not have; it is rendered as a mirror " + metal);
    CHECK(load.scene.materials[load.scene.spheres[1].material].type == MaterialType::Mirror);
    checkRendersTheBox(load.scene);
  }
  SUBCASE("refraction: glass that reflects nothing") {
    CourseLoad load = loadCourseBox("CGL-refraction.dae", {.profile = "CGL", .refraction = true});
    CHECK(load.printed == "warning: " + load.path +
                              ": effect \"refraction-effect\" has a CGL <refraction> material, which PathLab does not "
                              "have; it is rendered as glass that reflects nothing\n");
    const Material& glass = load.scene.materials[load.scene.spheres[0].material];
    CHECK(glass.type == MaterialType::Glass);
    CHECK(glass.albedo == Color(0.0f));
    CHECK(glass.transmittance == Color(1.0f));
    CHECK(glass.ior == doctest::Approx(1.45f));
    checkRendersTheBox(load.scene);
  }
  SUBCASE("all of them and a 15-number camera: one line per kind of repair") {
    CourseLoad load = loadCourseBox("CGL-everything.dae",
                                    {.profile = "CGL", .cameraMatrixNumbers = 15, .microfacet = true, .refraction = true});
    CHECK(load.printed ==
          "warning: " + load.path + ": node \"Camera\"/matrix has 15 numbers, not 16; the missing ones are taken as 0\n" +
              "warning: " + load.path +
              ": effect \"refraction-effect\" has a CGL <refraction> material, which PathLab does not have; it is "
              "rendered as glass that reflects nothing (1 more effect is approximated likewise)\n");
    checkRendersTheBox(load.scene);
  }
}

TEST_CASE("scene: course files the loader cannot understand still give one clear error") {
  const std::string box = courseCornellBox({.profile = "CGL"});
  SUBCASE("a matrix of 17 numbers") {
    CHECK_THROWS_AS(loadScene(writeCourseFile("camera17.dae", courseCornellBox({.cameraMatrixNumbers = 17}))), Error);
    CHECK(courseFileError("camera17.dae", courseCornellBox({.cameraMatrixNumbers = 17}))
              .ends_with("camera17.dae: node \"Camera\"/matrix: expected 16 numbers, got 17"));
  }
  SUBCASE("a matrix with a word in it") {
    const std::string dae = replaced(box, "-1 0 0 0 0 0 1 3", "-1 0 0 0 0 zero 1 3");
    CHECK(courseFileError("camera-word.dae", dae).ends_with("node \"Camera\"/matrix: expected numbers, got \"zero\""));
  }
  SUBCASE("a material type nobody knows") {
    const std::string dae = replaced(box, "<mirror><reflectance>1 1 1</reflectance></mirror>", "<velvet/>");
    CHECK(courseFileError("velvet.dae", dae).find("effect \"chrome-effect\": material type <velvet> is not supported") !=
          std::string::npos);
  }
}

TEST_CASE("scene: COLLADA warnings and errors are one line, whatever the file and node names hold") {
  // An escape sequence and a newline in the file's name and in a node's id.
  const std::string dae = replaced(courseCornellBox({.cameraMatrixNumbers = 15}), "<node id=\"Camera\"",
                                   "<node id=\"Cam&#27;[2J&#10;era\"");
  const std::string path = writeCourseFile("box\x1b[31m\nred.dae", dae);
  std::string printed;
  {
    StderrCapture capture;
    loadScene(path);
    printed = capture.text();
  }
  CHECK(printed.find("box\\x1b[31m\\x0ared.dae: node \"Cam\\x1b[2J\\x0aera\"/matrix has 15 numbers") != std::string::npos);
  REQUIRE(!printed.empty());
  CHECK(printed.back() == '\n');
  for (size_t i = 0; i + 1 < printed.size(); ++i) CHECK(static_cast<unsigned char>(printed[i]) >= 0x20);
  // Errors too.
  const std::string badPath =
      writeCourseFile("bad\x1b[31m\n.dae", replaced(dae, "<mirror><reflectance>1 1 1</reflectance></mirror>", "<velvet/>"));
  try {
    loadScene(badPath);
    FAIL("loaded");
  } catch (const Error& e) {
    const std::string message = e.what();
    CHECK(message.find("bad\\x1b[31m\\x0a.dae: effect \"chrome-effect\": material type <velvet>") != std::string::npos);
    for (char c : message) CHECK(static_cast<unsigned char>(c) >= 0x20);
  }
}

TEST_CASE("scene: the course's own files, from the optional data folder $PATHLAB_DATA_DIR") {
  const std::string dir = dataDir();
  if (dir.empty()) {
    MESSAGE("skipped: PATHLAB_DATA_DIR is not set (README.md, Optional data)");
    return;
  }
  for (const char* name : {"CBspheres_lambertian.dae", "CBspheres.dae"}) {
    const std::string path = dir + "/course-scenes/" + name;
    if (!std::filesystem::exists(path)) {
      MESSAGE("skipped: no " << path);
      continue;
    }
    CAPTURE(path);
    checkCourseCornellBox(loadScene(path), std::string(name) == "CBspheres.dae");
  }
}

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

TEST_CASE("render: --accel fast and task3 give bit-identical images (the same hits, in the same order)") {
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
  options.radiance = [](TraceContext& context, const Ray&, Sampler&) -> Color {
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

TEST_CASE("strategies: every sampling strategy is unbiased (closed enclosure and sky furnace)") {
  // Inside a closed enclosure of albedo 1/2 and emission 1/2, L = 1 exactly;
  // each strategy must agree within 5 standard errors (false failure 5.7e-7).
  Scene enclosure;
  enclosure.materials.push_back(Material{.name = "wall", .albedo = Color(0.5f), .emission = Color(0.5f)});
  TriangleMesh mesh = test::icosphere(3, Point3(0.0f), 1.0f);
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
  };
  const Case cases[] = {
      {"recipe", {}},
      {"mis-balance", {.mis = MisHeuristic::Balance}},
      {"mis-power", {.mis = MisHeuristic::Power}},
      {"mis-power, 4 light samples", {.mis = MisHeuristic::Power}, 4},
      {"uniform-hemisphere", {.cosineSampling = false}},
      {"no-nee", {.lightSampling = false}},
      {"no-rr", {.russianRoulette = false}},
  };
  test::Rig insideRig(enclosure), skyRig(sky);
  for (const Case& strategy : cases) {
    for (int scene = 0; scene < 2; ++scene) {
      TraceContext context = scene == 0 ? insideRig.context(60, strategy.lightSamples) : skyRig.context(8, strategy.lightSamples);
      test::Random random(81 + uint32_t(scene));
      test::MeanEstimate m;
      for (int i = 0; i < 20000; ++i) {
        Sampler sampler(uint32_t(i), 0, test::testSeed(81));
        Ray ray = scene == 0 ? Ray{Point3(0.1f, 0.0f, -0.2f), Vec3(random.unitVector())}
                             : Ray{Point3(0.0f, 0.0f, 4.0f), Vec3(glm::normalize(random.inCube(0.6) - test::DVec3(0, 0, 4)))};
        m.add(traceWithStrategy(context, ray, sampler, strategy.strategy).y);
      }
      const double expected = scene == 0 ? 1.0 : 0.4;
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
