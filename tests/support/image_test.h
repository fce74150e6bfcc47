// End-to-end image tests, the way Mitsuba tests its renders: the candidate
// renders a small scene with the student's task (the reference for every
// other task), and each 4x4 block of pixels and the whole image are compared
// per channel with the stored reference image by Welch's t statistic, which
// uses both images' sample variances. The threshold is Bonferroni-corrected
// over every block and channel so that a correct render fails an image with
// probability at most kImageFalseFailure (measured: docs/test-power.md).
//
// Reference images live in tests/NN-name/images/<name>.exr (each pixel's
// mean, 16x the test's samples per pixel) and <name>.variance.exr (the
// variance of that mean); tools/make-reference-images writes them with the
// reference solutions. On failure the test writes the student's image, the
// reference and a z-score map (PNG) to $PATHLAB_IMAGE_FAILURES_DIR (tools/grade
// sets it next to results.json), default ./image-failures, and names them;
// PATHLAB_IMAGE_PICTURES=always writes them for passing images too.
#pragma once

#include <string>

#include "render_moments.h"

namespace pathlab::test {

// The chance that a correct render fails one image (nominal, before the
// tails of path-traced samples; measured over many seeds).
constexpr double kImageFalseFailure = 1e-5;
// The reference takes this many times the test's samples per pixel.
constexpr int kReferenceSppFactor = 16;

struct ImageCase {
  std::string suite;  // "04-direct-lighting": where the reference image lives
  std::string name;   // file name stem, also shown on failure
  Scene scene;        // scene.render: size, samples per pixel, -m, -l (the seed is the test's)
  ImageOptions options;
};

// The reference image of suite SUITE named NAME, plus suffix (".exr": the reference's mean, ".variance.exr": its variance).
std::string referenceImagePath(const std::string& suite, const std::string& name, const char* suffix);

// CHECKs that the candidate's render of `c` matches the reference image;
// returns that render.
PixelMoments checkImage(ImageCase c);

}  // namespace pathlab::test
