// Bad input at the framework's level (docs/reliability.md): the strict OBJ
// reader, JSON nesting and duplicate keys, the scene limits, message text,
// and the checked file reader and writer. The CLI test runs the same classes
// end to end (tests/inputs/catalog.txt).
#include "suite/doctest_strings.h"

#if !defined(_WIN32)
#include <sys/stat.h>  // mkfifo
#endif

#include <cmath>
#include <filesystem>
#include <fstream>

#include "scene/obj_file.h"
#include "scene/scene_io.h"
#include "util/error.h"
#include "util/input_file.h"
#include "util/platform.h"

using namespace pathlab;

namespace {

std::string objError(const std::string& text) {
  try {
    parseObj(text, "m.obj");
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

std::string sceneError(const std::string& json) {
  try {
    loadSceneFromJson(json, "s.json", ".");
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

double area(const TriangleMesh& mesh) {
  double sum = 0.0;
  for (const glm::uvec3& t : mesh.triangles) {
    const Vec3 e1 = mesh.positions[t.y] - mesh.positions[t.x], e2 = mesh.positions[t.z] - mesh.positions[t.x];
    sum += 0.5 * double(glm::length(glm::cross(e1, e2)));
  }
  return sum;
}

// A closed polygon in the z = 0 plane as OBJ text, corners counter-clockwise.
std::string polygonObj(const std::vector<glm::vec2>& corners) {
  std::string text;
  for (const glm::vec2& c : corners) text.append("v ").append(std::to_string(c.x)).append(" ").append(std::to_string(c.y)).append(" 0\n");
  text += "f";
  for (size_t k = 0; k < corners.size(); ++k) text.append(" ").append(std::to_string(k + 1));
  return text + "\n";
}

}  // namespace

TEST_CASE("OBJ: numbers that are not finite, and faces that point nowhere, are errors with the line") {
  CHECK(objError("v nan nan nan\nv 1 0 0\nv 0 1 0\nf 1 2 3\n") ==
        "m.obj:1: vertex component \"nan\" is not a finite number");
  CHECK(objError("v 0 0 0\nv 1 0 0\nv 0 1 0\nv inf 0 0\n").find("m.obj:4:") == 0);
  CHECK(objError("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3 9\n") == "m.obj:4: face refers to vertex 9 but the file has 3 so far");
  CHECK(objError("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -4\n").find("vertex -4") != std::string::npos);
  CHECK(objError("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\n") == "m.obj:4: a face needs at least 3 vertices, got 2");
  CHECK(objError("v 0 0 0\nv 1 0\n").find("m.obj:2: expected 3 numbers") == 0);
  CHECK(objError("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3x\n").find("expected a vertex index") != std::string::npos);
  CHECK(objError("# nothing\nv 0 0 0\n") == "m.obj: OBJ file has no faces");
}

TEST_CASE("OBJ: relative indices, normals on every corner or none, and what adds no surface") {
  const TriangleMesh mesh = parseObj(
      "mtllib materials.mtl\no thing\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 2\nvt 0 0\nusemtl red\ns off\n"
      "f -3//1 -2//1 -1//1  # a comment\n",
      "m.obj");
  REQUIRE(mesh.triangles.size() == 1);
  REQUIRE(mesh.normals.size() == 3);
  CHECK(mesh.normals[0] == Vec3(0, 0, 1));  // normalised
  const TriangleMesh mixed = parseObj("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\nf 2 4 3\n", "m.obj");
  CHECK(mixed.normals.empty());  // one corner without a normal: none are kept
  CHECK(mixed.positions.size() == 4);
}

TEST_CASE("OBJ: quads split along the shorter diagonal; polygons keep their area, convex or not") {
  // A kite whose 1-3 diagonal is shorter: split along it.
  const TriangleMesh kite = parseObj("v 0 0 0\nv 1 -0.2 0\nv 3 0 0\nv 1 0.2 0\nf 1 2 3 4\n", "m.obj");
  REQUIRE(kite.triangles.size() == 2);
  CHECK(kite.positions[kite.triangles[0].z] == Point3(1.0f, 0.2f, 0.0f));  // corners 0, 1, 3
  CHECK(area(kite) == doctest::Approx(0.6).epsilon(1e-5));

  // A star of 10 points (concave) and an L shape: ear clipping; the
  // triangles' areas sum to the polygon's (shoelace) area, none flipped.
  std::vector<glm::vec2> star;
  for (int k = 0; k < 20; ++k) {
    const float a = float(k) * kPi / 10.0f, r = k % 2 ? 0.4f : 1.0f;
    star.emplace_back(r * std::cos(a), r * std::sin(a));
  }
  const std::vector<glm::vec2> ell{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  for (const auto& polygon : {star, ell}) {
    double shoelace = 0.0;
    for (size_t k = 0; k < polygon.size(); ++k) {
      const glm::vec2 p = polygon[k], q = polygon[(k + 1) % polygon.size()];
      shoelace += 0.5 * double(p.x * q.y - q.x * p.y);
    }
    const TriangleMesh mesh = parseObj(polygonObj(polygon), "m.obj");
    CHECK(mesh.triangles.size() == polygon.size() - 2);
    CHECK(area(mesh) == doctest::Approx(shoelace).epsilon(1e-4));
    for (const glm::uvec3& t : mesh.triangles) {  // every triangle faces +z, as the polygon does
      CHECK(glm::cross(mesh.positions[t.y] - mesh.positions[t.x], mesh.positions[t.z] - mesh.positions[t.x]).z >= 0.0f);
    }
  }
}

TEST_CASE("OBJ: a convex polygon of 150,000 vertices is a fan; a concave one that large is refused") {
  std::vector<glm::vec2> circle, star;
  const int n = 150000;
  for (int k = 0; k < n; ++k) {
    const float a = 2.0f * kPi * float(k) / float(n);
    circle.emplace_back(std::cos(a), std::sin(a));
    star.emplace_back((k % 2 ? 0.5f : 1.0f) * std::cos(a), (k % 2 ? 0.5f : 1.0f) * std::sin(a));
  }
  const TriangleMesh disc = parseObj(polygonObj(circle), "m.obj");
  CHECK(disc.triangles.size() == size_t(n - 2));
  CHECK(area(disc) == doctest::Approx(kPi).epsilon(1e-3));
  CHECK(objError(polygonObj(star)).find("a non-convex polygon of 150000 vertices") != std::string::npos);
}

TEST_CASE("JSON: nesting past 64 levels and a key given twice are errors, not a crash or a silent choice") {
  const std::string deep = "{\"camera\": " + std::string(100000, '[') + std::string(100000, ']') + "}";
  CHECK(sceneError(deep) == "s.json: nesting deeper than 64 levels (a scene needs 5)");
  CHECK(sceneError("{\n\"render\": {\"spp\": 4},\n\n\"render\": {\"spp\": 8}\n}") ==
        "s.json:4: key \"render\" is given twice in one object (first on line 2)");
  CHECK(sceneError(R"({"materials": {"a": {"albedo": [0.5, 0.5, 0.5], "albedo": [0.1, 0.1, 0.1]}}})")
            .find("key \"albedo\" is given twice") != std::string::npos);
  CHECK(sceneError(R"({"spheres": [{"radius": 1}, {"radius": 1}]})") == "");  // same keys, different objects
}

TEST_CASE("scene limits: geometry beyond 1e12, an overflowing camera, and a huge image are refused by name") {
  CHECK(sceneError(R"({"spheres": [{"center": [2e38, 0, 0], "radius": 2e38}]})").find("sphere 0") != std::string::npos);
  CHECK(sceneError(R"({"spheres": [{"radius": 1e30}]})").find("out of range") != std::string::npos);
  CHECK(sceneError(R"({"spheres": [{"radius": 1e11}]})") == "");  // a sky dome is fine
  CHECK(sceneError(R"({"meshes": [{"name": "far", "positions": [[3e38,0,0],[3e38,1,0],[3e38,0,1]], "triangles": [[0,1,2]]}]})")
            .find("mesh far: vertex 0 at (3e+38, 0, 0) is out of range") != std::string::npos);
  CHECK(sceneError(R"({"meshes": [{"quad": {"corner": [0,0,0], "edge_u": [1,0,0], "edge_v": [0,1,0]}, "transform": {"scale": 1e30}}]})")
            .find("out of range") != std::string::npos);
  CHECK(sceneError(R"({"camera": {"position": [3e38, 0, 0], "look_at": [-3e38, 0, 0]}})").find("camera position") !=
        std::string::npos);
  CHECK(sceneError(R"({"camera": {"position": [0, 0, 0], "look_at": [0, 5, 0]}})").find("parallel") != std::string::npos);
  CHECK(sceneError(R"({"render": {"width": 16384, "height": 16384}})").find("out of range") != std::string::npos);
}

TEST_CASE("camera up: only its direction counts, however long or short the vector") {
  auto upOf = [](const std::string& up) {
    return loadSceneFromJson(R"({ "camera": { "position": [0, 1, 4], "look_at": [0, 1, 0], "up": )" + up + " } }",
                             "up", ".")
        .camera.up;
  };
  const Vec3 expected = glm::normalize(Vec3(1, 1, 0));
  for (const char* up : {"[1e30, 1e30, 0]", "[1e-30, 1e-30, 0]", "[3, 3, 0]"}) {
    CAPTURE(up);
    CHECK(glm::length(upOf(up) - expected) < 1e-6f);
  }
  CHECK_THROWS_AS(upOf("[0, 0, 0]"), Error);
}

TEST_CASE("messages: user text is escaped and capped, so one error is one short line") {
  CHECK(shown("a\nb\x1b[31m") == "a\\x0ab\\x1b[31m");
  CHECK(shown(std::string(1000, 'k')) == std::string(80, 'k') + "…");
  CHECK(inQuotes("caf\xc3\xa9") == "\"caf\xc3\xa9\"");  // UTF-8 passes through
  CHECK(shown("\xe2\x80\xae") == "\\xe2\\x80\\xae");     // a bidirectional override does not
  CHECK(printableLine(std::string(5000, 'x')).size() < 1010);
  const std::string e = sceneError("{\"" + std::string(1000000, 'k') + "\": 1}");
  CHECK(e.size() < 400);
  CHECK(e.find("…") != std::string::npos);
  CHECK(sceneError("{\"bad\\nkey\": 1}").find('\n') == std::string::npos);
}

TEST_CASE("files: only regular files are read, and a failed write leaves nothing behind") {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("pathlab-bad-input-" + std::to_string(currentProcessId()));
  std::filesystem::create_directories(dir);
  auto readError = [](const std::string& path) {
    try {
      readInputFile(path, "scene file", kMaxJsonSceneBytes);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  CHECK(readError(dir.string()).find("is a folder") != std::string::npos);
#if !defined(_WIN32)  // FIFOs, /dev and symbolic links as POSIX has them
  const std::string fifo = (dir / "pipe.json").string();
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  CHECK(readError(fifo).find("is a FIFO") != std::string::npos);  // and returns at once
  CHECK(readError("/dev/zero").find("is a device") != std::string::npos);
  const std::string loop = (dir / "loop.json").string();
  std::filesystem::create_symlink(loop, loop);
  CHECK(readError(loop).find("Too many levels of symbolic links") != std::string::npos);
#endif

  // Writing into a missing folder fails cleanly; a good write leaves exactly the file.
  CHECK_THROWS_AS(writeFileAtomically((dir / "no" / "such.png").string(), "bytes"), Error);
  const std::string target = (dir / "out.bin").string();
  writeFileAtomically(target, "bytes");
  CHECK(std::filesystem::file_size(target) == 5);
  CHECK(!std::filesystem::exists(partialPathFor(target)));
#if !defined(_WIN32)
  // A symbolic link planted at the temporary name is replaced, never written through.
  const std::string victim = (dir / "victim.txt").string();
  writeFileAtomically(victim, "keep me");
  std::filesystem::create_symlink(victim, partialPathFor(target));
  writeFileAtomically(target, "new bytes");
  CHECK(std::filesystem::file_size(target) == 9);
  CHECK(std::filesystem::file_size(victim) == 7);
  CHECK(!std::filesystem::is_symlink(target));
#endif
  std::filesystem::remove_all(dir);
}
