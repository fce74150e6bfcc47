// The course's Cornell boxes (CBspheres.dae, CBspheres_lambertian.dae),
// written in code the way the course's Blender 2.72 exporter writes them:
// Z-up, polylists with VERTEX/NORMAL/TEXCOORD inputs, node matrices, an
// <area> light in an <extra> block, analytic spheres that are geometries
// with no mesh. `profile` is "CMU462" (Scotty3D) or "CGL" (CS184).
// The other options write the variants the course's viewers accept and
// PathLab repairs with a warning; their defaults write the files as shipped.
#pragma once

#include <sstream>
#include <string>
#include <vector>

namespace pathlab::test {

struct CourseBoxOptions {
  std::string profile = "CMU462";
  bool mirrorAndGlass = true;  // CBspheres.dae; false: CBspheres_lambertian.dae
  // The camera node's <matrix>: fewer numbers write only the first ones (a
  // Cornell box the course ships has 15), more append 0s.
  int cameraMatrixNumbers = 16;
  int backWallMatrixNumbers = 16;  // the same for the back wall's node
  // CS184 hw3-2: the second sphere (chrome, or the second diffuse one) is a
  // gold <microfacet> (gold's eta and k), of roughness `microfacetAlpha`.
  bool microfacet = false;
  float microfacetAlpha = 0.5f;
  // CS184: the first sphere (glass, or the first diffuse one) is a
  // <refraction> material (RefractionBSDF: refraction only).
  bool refraction = false;
};

inline std::string courseCornellBox(const CourseBoxOptions& options = {}) {
  std::ostringstream dae;
  auto extra = [&](const std::string& body) {
    return "<extra><technique profile=\"" + options.profile + "\">" + body + "</technique></extra>";
  };
  auto effect = [&](const std::string& id, const std::string& diffuse, const std::string& course = "") {
    dae << "<effect id=\"" << id << "-effect\"><profile_COMMON><technique sid=\"common\"><phong>"
        << "<emission><color sid=\"emission\">0 0 0 1</color></emission>"
        << "<diffuse><color sid=\"diffuse\">" << diffuse << " 1</color></diffuse>"
        << "<specular><color sid=\"specular\">0 0 0 1</color></specular>"
        << "</phong></technique></profile_COMMON>" << (course.empty() ? "" : extra(course)) << "</effect>\n";
  };
  // Blender's node matrix for every wall: a rotation taking the walls' own
  // y-up coordinates to the file's z-up, with the exporter's rounding noise.
  const std::string wallMatrix =
      "-1 2.69452e-14 1.50996e-7 -2.62268e-8 1.50996e-7 1.62921e-7 1 0 2.34488e-15 1 -1.62921e-7 0 0 0 0 1";
  const std::string raisedWallMatrix =
      "-1 2.69452e-14 1.50996e-7 -2.62268e-8 1.50996e-7 1.62921e-7 1 0.004315853 2.34488e-15 1 -1.62921e-7 0 0 0 0 1";
  auto firstNumbers = [](const std::string& matrix, int count) {
    std::istringstream numbers(matrix);
    std::vector<std::string> v;
    for (std::string n; numbers >> n;) v.push_back(n);
    v.resize(size_t(count), "0");
    std::string out;
    for (const std::string& n : v) out += (out.empty() ? "" : " ") + n;
    return out;
  };
  const std::string cameraMatrix = firstNumbers("-1 0 0 0 0 0 1 3 0 1 0 0 0 0 0 1", options.cameraMatrixNumbers);
  const std::string backWallMatrix = firstNumbers(raisedWallMatrix, options.backWallMatrixNumbers);
  struct Wall {
    const char* name;
    const char* positions;
    const char* normal;
    const char* matrix;
  };
  const Wall walls[] = {
      {"ceiling", "1 1.5 -1 1 1.5 1 -1 1.5 1 -1 1.5 -1", "0 -1 0", wallMatrix.c_str()},
      {"light", "0.4 1.49 -0.3 0.4 1.49 0.3 -0.4 1.49 0.3 -0.4 1.49 -0.3", "0 -1 0", raisedWallMatrix.c_str()},
      {"floor", "1 0 -1 -1 0 -1 -1 0 1 1 0 1", "0 1 0", wallMatrix.c_str()},
      {"leftWall", "-1 1.5 -1 -1 1.5 1 -1 0 1 -1 0 -1", "1 0 0", wallMatrix.c_str()},
      {"rightWall", "1 1.5 1 1 1.5 -1 1 0 -1 1 0 1", "-1 0 0", wallMatrix.c_str()},
      {"backWall", "1 1.5 -1 -1 1.5 -1 -1 0 -1 1 0 -1", "0 0 1", backWallMatrix.c_str()},
  };

  dae << "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n"
      << "<COLLADA xmlns=\"http://www.collada.org/2005/11/COLLADASchema\" version=\"1.4.1\">\n"
      << "<asset><unit name=\"meter\" meter=\"1\"/><up_axis>Z_UP</up_axis></asset>\n";
  dae << "<library_lights><light id=\"Area-light\" name=\"Light\"><technique_common><point>"
      << "<color sid=\"color\">10 10 10</color></point></technique_common>"
      << extra("<area><color sid=\"color\">10 10 10</color></area>") << "</light></library_lights>\n";
  dae << "<library_cameras><camera id=\"Camera-camera\" name=\"Camera\"><optics><technique_common><perspective>"
      << "<xfov sid=\"xfov\">49.13434</xfov><aspect_ratio>1.333333</aspect_ratio>"
      << "<znear sid=\"znear\">0.1</znear><zfar sid=\"zfar\">100</zfar>"
      << "</perspective></technique_common></optics></camera></library_cameras>\n";

  dae << "<library_effects>\n";
  if (options.mirrorAndGlass) {
    effect("chrome", "0.64 0.64 0.64", "<mirror><reflectance>1 1 1</reflectance></mirror>");
    effect("glass", "0.64 0.64 0.64",
           "<glass><reflectance>1 1 1</reflectance><transmittance>1 1 1</transmittance>"
           "<roughness>0</roughness><ior>1.45</ior></glass>");
  } else {
    effect("sphereA", "0.6 0.6 0.6");
    effect("sphereB", "0.6 0.6 0.6");
  }
  effect("ceiling", "0.6 0.6 0.6");
  effect("light", "0.8 0.8 0.8", "<emission><radiance>10 10 10</radiance></emission>");
  effect("floor", "0.6 0.6 0.6");
  effect("leftWall", "0.6 0.2 0.2");
  effect("rightWall", "0.2 0.2 0.6");
  effect("backWall", "0.6 0.6 0.6");
  dae << "</library_effects>\n<library_materials>\n";
  if (options.refraction) {
    effect("refraction", "0.64 0.64 0.64",
           "<refraction><transmittance>1 1 1</transmittance><roughness>0</roughness><ior>1.45</ior></refraction>");
  }
  if (options.microfacet) {
    effect("gold", "0.64 0.64 0.64",
           "<microfacet><alpha>" + std::to_string(options.microfacetAlpha) +
               "</alpha><eta>0.21646 0.42833 1.3284</eta><k>3.2390 2.4599 1.8661</k></microfacet>");
  }
  const std::string sphereEffects[2] = {
      options.refraction ? "refraction" : options.mirrorAndGlass ? "glass" : "sphereA",
      options.microfacet ? "gold" : options.mirrorAndGlass ? "chrome" : "sphereB"};
  for (const std::string& name : sphereEffects) {
    dae << "<material id=\"" << name << "\" name=\"" << name << "\"><instance_effect url=\"#" << name
        << "-effect\"/></material>\n";
  }
  for (const Wall& wall : walls) {
    dae << "<material id=\"" << wall.name << "-material\" name=\"" << wall.name << "\"><instance_effect url=\"#"
        << wall.name << "-effect\"/></material>\n";
  }
  dae << "</library_materials>\n<library_geometries>\n";
  dae << "<geometry id=\"Sphere1-data\" name=\"Sphere1\">" << extra("<sphere><radius>.3</radius></sphere>")
      << "</geometry>\n";
  for (const Wall& wall : walls) {
    const std::string id = std::string(wall.name) + "-mesh";
    auto source = [&](const std::string& kind, int count, const std::string& values, int stride) {
      dae << "<source id=\"" << id << "-" << kind << "\"><float_array id=\"" << id << "-" << kind
          << "-array\" count=\"" << count * stride << "\">" << values << "</float_array><technique_common>"
          << "<accessor source=\"#" << id << "-" << kind << "-array\" count=\"" << count << "\" stride=\""
          << stride << "\"/></technique_common></source>\n";
    };
    dae << "<geometry id=\"" << id << "\" name=\"" << wall.name << "\"><mesh>\n";
    source("positions", 4, wall.positions, 3);
    source("normals", 2, std::string(wall.normal) + " " + wall.normal, 3);
    source("map-0", 6, "0 1 0 1 0 1 0 1 0 1 0 1", 2);
    dae << "<vertices id=\"" << id << "-vertices\"><input semantic=\"POSITION\" source=\"#" << id
        << "-positions\"/></vertices>\n"
        << "<polylist material=\"" << wall.name << "-material\" count=\"2\">"
        << "<input semantic=\"VERTEX\" source=\"#" << id << "-vertices\" offset=\"0\"/>"
        << "<input semantic=\"NORMAL\" source=\"#" << id << "-normals\" offset=\"1\"/>"
        << "<input semantic=\"TEXCOORD\" source=\"#" << id << "-map-0\" offset=\"2\" set=\"0\"/>"
        << "<vcount>3 3 </vcount><p>0 0 0 1 0 1 2 0 2 3 1 3 0 1 4 2 1 5</p></polylist>\n"
        << "</mesh></geometry>\n";
  }
  dae << "</library_geometries>\n";

  auto instance = [&](const std::string& geometry, const std::string& material) {
    return "<instance_geometry url=\"#" + geometry + "\"><bind_material><technique_common><instance_material symbol=\"" +
           material + "\" target=\"#" + material + "\"/></technique_common></bind_material></instance_geometry>";
  };
  dae << "<library_visual_scenes><visual_scene id=\"Scene\" name=\"Scene\">\n"
      << "<node id=\"Area\" name=\"Area\" type=\"NODE\"><matrix sid=\"transform\">0.6 0 0 0 0 0.8 0 0 0 0 1 1.49 0 0 0 1"
      << "</matrix><instance_light url=\"#Area-light\"/></node>\n"
      << "<node id=\"Sphere1\" name=\"Sphere1\" type=\"NODE\"><matrix sid=\"transform\">1 0 0 -0.4 0 1 0 0.3 0 0 1 0.3 0 0 0 1"
      << "</matrix>" << instance("Sphere1-data", sphereEffects[0]) << "</node>\n"
      << "<node id=\"Sphere2\" name=\"Sphere2\" type=\"NODE\"><matrix sid=\"transform\">1 0 0 0.4 0 1 0 -0.3 0 0 1 0.3 0 0 0 1"
      << "</matrix>" << instance("Sphere1-data", sphereEffects[1]) << "</node>\n"
      << "<node id=\"Camera\" name=\"Camera\" type=\"NODE\"><matrix sid=\"transform\">" << cameraMatrix
      << "</matrix><instance_camera url=\"#Camera-camera\"/></node>\n";
  for (const Wall& wall : walls) {
    dae << "<node id=\"" << wall.name << "\" name=\"" << wall.name << "\" type=\"NODE\"><matrix sid=\"transform\">"
        << wall.matrix << "</matrix>" << instance(std::string(wall.name) + "-mesh", std::string(wall.name) + "-material")
        << "</node>\n";
  }
  dae << "</visual_scene></library_visual_scenes>\n"
      << "<scene><instance_visual_scene url=\"#Scene\"/></scene>\n</COLLADA>\n";
  return dae.str();
}

}  // namespace pathlab::test
