#include "failure_pictures.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <sstream>

#include "suite/verdicts.h"
#include "util/error.h"

namespace pathlab::test {

std::string failurePicturesDir() {
  const char* variable = std::getenv(verdicts::kImageFailuresVariable);
  const std::string dir = variable && *variable ? variable : "image-failures";
  std::error_code error;
  std::filesystem::create_directories(dir, error);
  return dir;
}

bool picturesAlways() {
  const char* always = std::getenv("PATHLAB_IMAGE_PICTURES");
  return always && std::string(always) == "always";
}

Image enlarged(const Image& image, int factor) {
  Image out(image.width * factor, image.height * factor);
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x) out.at(x, y) = image.at(x / factor, y / factor);
  return out;
}

std::string writeHistogramPictures(const std::string& name, const std::vector<double>& observed,
                                   const std::vector<double>& expected, int columns, int rows,
                                   const std::string& columnAxis, const std::string& rowAxis) {
  const std::string stem = (std::filesystem::path(failurePicturesDir()) / name).string();
  const double peak = std::max({1.0, *std::max_element(expected.begin(), expected.end()),
                                *std::max_element(observed.begin(), observed.end())});
  auto z = [&](size_t k) { return (observed[k] - expected[k]) / std::sqrt(std::max(expected[k], 1.0)); };
  Image observedImage(columns, rows), expectedImage(columns, rows), difference(columns, rows);
  for (int j = 0; j < rows; ++j) {
    for (int i = 0; i < columns; ++i) {
      const size_t k = size_t(j) * size_t(columns) + size_t(i);
      const int y = rows - 1 - j;  // row 0 at the bottom
      // Display-encoded grey: linear counts / peak, through the PNG's sRGB curve.
      observedImage.at(i, y) = Color(float(observed[k] / peak));
      expectedImage.at(i, y) = Color(float(expected[k] / peak));
      const float strength = float(std::min(1.0, std::abs(z(k)) / 4.0));
      difference.at(i, y) = z(k) > 0 ? Color(strength, 0.0f, 0.0f) : Color(0.0f, 0.0f, strength);
    }
  }
  std::vector<size_t> order(observed.size());
  std::iota(order.begin(), order.end(), size_t(0));
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return std::abs(z(a)) > std::abs(z(b)); });
  std::ofstream table(stem + "-cells.csv");
  table << columnAxis << "," << rowAxis << ",observed,expected,deviations\n";
  for (size_t k : order) {
    table << k % size_t(columns) << "," << k / size_t(columns) << "," << observed[k] << "," << expected[k] << ","
          << z(k) << "\n";
  }
  const int factor = std::max(1, 600 / std::max(columns, rows));
  try {
    writeImage(enlarged(observedImage, factor), stem + "-observed.png");
    writeImage(enlarged(expectedImage, factor), stem + "-expected.png");
    writeImage(enlarged(difference, factor), stem + "-difference.png");
  } catch (const Error& e) {
    return std::string("(could not write the pictures: ") + e.what() + ")";
  }
  const size_t worst = order.front();
  std::ostringstream s;
  s.precision(4);
  s << "worst cell: " << columnAxis << " " << worst % size_t(columns) << ", " << rowAxis << " "
    << worst / size_t(columns) << ": observed " << observed[worst] << ", expected " << expected[worst] << " ("
    << z(worst) << " standard deviations); pictures: " << stem << "-observed.png, " << stem << "-expected.png, "
    << stem << "-difference.png (red: too many samples, blue: too few), table: " << stem << "-cells.csv";
  return s.str();
}

}  // namespace pathlab::test
