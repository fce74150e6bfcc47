// Pictures of a failed statistical test, the way pbrt writes its chi-square
// tables and Mitsuba its observed/expected images: a number like "p = 1e-39"
// says that a sampler is wrong, a picture says where. Written to
// $PATHLAB_IMAGE_FAILURES_DIR (tools/grade sets it next to results.json),
// default ./image-failures; PATHLAB_IMAGE_PICTURES=always writes them for
// passing tests too.
#pragma once

#include <string>
#include <vector>

#include "util/image.h"

namespace pathlab::test {

// The folder pictures go to (created if missing).
std::string failurePicturesDir();
// True when PATHLAB_IMAGE_PICTURES=always.
bool picturesAlways();
// `image` scaled up `factor` times, each pixel a factor x factor square.
Image enlarged(const Image& image, int factor);

// A histogram over a grid of `columns` x `rows` cells (cell (i, j) at
// observed[j * columns + i], row j = 0 drawn at the bottom) against the
// counts expected there: writes NAME-observed.png, NAME-expected.png (one
// exposure), NAME-difference.png ((observed - expected) / sqrt(expected):
// red where too many samples landed, blue where too few, full colour at 4
// standard deviations) and NAME-cells.csv (every cell, largest deviation
// first). Returns one line naming them and the worst cell, for the test's output.
std::string writeHistogramPictures(const std::string& name, const std::vector<double>& observed,
                                   const std::vector<double>& expected, int columns, int rows,
                                   const std::string& columnAxis, const std::string& rowAxis);

}  // namespace pathlab::test
