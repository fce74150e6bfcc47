// pathlab-envmap: writes the project's environment maps (linear float EXR,
// equirectangular, +y up; conventions in framework/tasks/environment.h).
//   pathlab-envmap OUT_DIR
//     sky-sun.exr    Preetham et al.'s daylight sky (turbidity 3) with a small, very bright sun
//     studio.exr     a dark studio with two large soft boxes: low contrast, smooth
//     hot-pixel.exr  black with a single bright pixel: all light from one direction
//     constant.exr   radiance 1 everywhere: the white furnace
//     black.exr      no light at all
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <string>

#include "tasks/environment.h"
#include "util/error.h"
#include "util/image.h"
#include "util/input_file.h"

using namespace pathlab;

namespace {

// Direction of pixel (i, j)'s centre.
Vec3 pixelDirection(const Image& image, int i, int j) {
  const float u = (float(i) + 0.5f) / float(image.width), v = (float(j) + 0.5f) / float(image.height);
  const float phi = 2.0f * kPi * u, theta = kPi * v;
  return {std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)};
}

// ---- Preetham, Shirley and Smits, "A Practical Analytic Model for Daylight" (1999)

struct Perez {
  double a, b, c, d, e;
  double operator()(double theta, double gamma) const {
    return (1.0 + a * std::exp(b / std::max(std::cos(theta), 0.01))) *
           (1.0 + c * std::exp(d * gamma) + e * std::cos(gamma) * std::cos(gamma));
  }
};

Color xyYToLinearSrgb(double x, double y, double Y) {
  const double X = x / y * Y, Z = (1.0 - x - y) / y * Y;
  return Color(float(3.2406 * X - 1.5372 * Y - 0.4986 * Z), float(-0.9689 * X + 1.8758 * Y + 0.0415 * Z),
               float(0.0557 * X - 0.2040 * Y + 1.0570 * Z));
}

Image skyWithSun(int width, int height) {
  const double T = 3.0;                       // turbidity: a clear day
  const Vec3 sun = glm::normalize(Vec3(0.6f, 0.45f, -0.45f));  // about 27 degrees above the horizon
  const double thetaS = std::acos(double(sun.y));
  const double chi = (4.0 / 9.0 - T / 120.0) * (std::numbers::pi - 2.0 * thetaS);
  const double zenithY = (4.0453 * T - 4.9710) * std::tan(chi) - 0.2155 * T + 2.4192;
  const double t3 = thetaS * thetaS * thetaS, t2 = thetaS * thetaS;
  const double zenithX = T * T * (0.00166 * t3 - 0.00375 * t2 + 0.00209 * thetaS) +
                         T * (-0.02903 * t3 + 0.06377 * t2 - 0.03202 * thetaS + 0.00394) +
                         (0.11693 * t3 - 0.21196 * t2 + 0.06052 * thetaS + 0.25886);
  const double zenithYc = T * T * (0.00275 * t3 - 0.00610 * t2 + 0.00317 * thetaS) +
                          T * (-0.04214 * t3 + 0.08970 * t2 - 0.04153 * thetaS + 0.00516) +
                          (0.15346 * t3 - 0.26756 * t2 + 0.06670 * thetaS + 0.26688);
  const Perez perezY{0.1787 * T - 1.4630, -0.3554 * T + 0.4275, -0.0227 * T + 5.3251, 0.1206 * T - 2.5771,
                     -0.0670 * T + 0.3703};
  const Perez perezX{-0.0193 * T - 0.2592, -0.0665 * T + 0.0008, -0.0004 * T + 0.2125, -0.0641 * T - 0.8989,
                     -0.0033 * T + 0.0452};
  const Perez perezYc{-0.0167 * T - 0.2608, -0.0950 * T + 0.0092, -0.0079 * T + 0.2102, -0.0441 * T - 1.6537,
                      -0.0109 * T + 0.0529};
  constexpr double kScale = 0.1;  // kcd/m^2 to render units: the zenith is about 1
  const double sunRadius = glm::radians(0.6), sunCos = std::cos(sunRadius);
  Image image(width, height);
  double skyIrradiance = 0.0;
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i) {
      const Vec3 w = pixelDirection(image, i, j);
      Color c;
      if (w.y > 0.0f) {
        const double theta = std::acos(double(w.y));
        const double gamma = std::acos(std::clamp(double(glm::dot(w, sun)), -1.0, 1.0));
        const double Y = zenithY * perezY(theta, gamma) / perezY(0.0, thetaS);
        const double x = zenithX * perezX(theta, gamma) / perezX(0.0, thetaS);
        const double y = zenithYc * perezYc(theta, gamma) / perezYc(0.0, thetaS);
        c = glm::max(xyYToLinearSrgb(x, y, Y * kScale), Color(0.0f));
        const double solidAngle = (2.0 * std::numbers::pi / width) * (std::numbers::pi / height) * std::sin(std::numbers::pi * (j + 0.5) / height);
        skyIrradiance += double(luminance(c)) * double(w.y) * solidAngle;
      } else {
        c = Color(0.09f, 0.08f, 0.07f);  // brownish ground below the horizon
      }
      image.at(i, j) = c;
    }
  // The sun: a disk of 0.6 degrees radius whose irradiance on the ground is
  // four times the whole sky's: small, and very bright.
  const double sunSolidAngle = 2.0 * std::numbers::pi * (1.0 - sunCos);
  const double sunRadiance = 4.0 * skyIrradiance / (sunSolidAngle * double(sun.y));
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i) {
      if (glm::dot(pixelDirection(image, i, j), sun) >= sunCos) {
        image.at(i, j) = Color(1.0f, 0.92f, 0.8f) * float(sunRadiance);
      }
    }
  std::printf("sky-sun: sky irradiance %.3f, sun radiance %.1f over %.2e sr\n", skyIrradiance, sunRadiance, sunSolidAngle);
  return image;
}

Image studio(int width, int height) {
  Image image(width, height);
  const Vec3 boxA = glm::normalize(Vec3(-0.6f, 0.6f, 0.5f)), boxB = glm::normalize(Vec3(0.7f, 0.4f, -0.3f));
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i) {
      const Vec3 w = pixelDirection(image, i, j);
      float v = 0.05f + 0.03f * w.y;  // dim walls, a little brighter above
      v += 3.0f * std::exp((glm::dot(w, boxA) - 1.0f) * 12.0f);
      v += 1.5f * std::exp((glm::dot(w, boxB) - 1.0f) * 20.0f);
      image.at(i, j) = Color(v, v * 0.97f, v * 0.92f);
    }
  return image;
}

void write(const Image& image, const std::filesystem::path& path) {
  writeImage(image, path.string());
  std::printf("%s: %dx%d, %ju bytes\n", path.string().c_str(), image.width, image.height,
              std::uintmax_t(std::filesystem::file_size(path)));
}

}  // namespace

int main(int argc, char** argv) {
  const std::string usage =
      "usage: pathlab-envmap OUT_DIR\n"
      "Writes sky-sun.exr, studio.exr, hot-pixel.exr, constant.exr and black.exr into OUT_DIR.\n";
  if (argc == 2 && (std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h")) {
    std::fputs(usage.c_str(), stdout);
    return 0;
  }
  // A folder named like an option is a typo, not a wish.
  if (argc != 2 || argv[1][0] == '-') {
    std::fputs(usage.c_str(), stderr);
    return 1;
  }
  try {
    const std::filesystem::path out = argv[1];
    createFolders(out.string());
    write(skyWithSun(800, 400), out / "sky-sun.exr");  // under 2 MB
    write(studio(512, 256), out / "studio.exr");
    Image hot(64, 32);
    hot.at(40, 9) = Color(500.0f);
    write(hot, out / "hot-pixel.exr");
    write(Image(64, 32, Color(1.0f)), out / "constant.exr");
    write(Image(64, 32), out / "black.exr");
  } catch (const Error& e) {
    printError("pathlab-envmap", e.what());
    return 1;
  }
  return 0;
}
