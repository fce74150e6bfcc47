// Framework tests: the course's COLLADA files, in both profiles, with the
// leniencies the course's viewer has. Linked with the reference tasks.
#include "suite/doctest_strings.h"

#if defined(_WIN32)
#include <io.h>
#else
#include <unistd.h>
#endif

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
#if defined(_WIN32)
int duplicate(int fd) { return _dup(fd); }
void duplicateOnto(int from, int to) { _dup2(from, to); }
void closeDescriptor(int fd) { _close(fd); }
int descriptorOf(std::FILE* file) { return _fileno(file); }
#else
int duplicate(int fd) { return ::dup(fd); }
void duplicateOnto(int from, int to) { ::dup2(from, to); }
void closeDescriptor(int fd) { ::close(fd); }
int descriptorOf(std::FILE* file) { return ::fileno(file); }
#endif

class StderrCapture {
 public:
  StderrCapture() {
    std::fflush(stderr);
    file_ = std::tmpfile();
    REQUIRE(file_ != nullptr);
    saved_ = duplicate(2);
    duplicateOnto(descriptorOf(file_), 2);
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
    duplicateOnto(saved_, 2);
    closeDescriptor(saved_);
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

