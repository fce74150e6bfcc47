// How much noisier than a correct estimator a candidate may be.
//
// "The mean is within 5 standard errors of the expected value" is a fair
// test only if the standard error is one a correct estimator could have. An
// estimator that returns +1e10 and -1e10 in turn has a mean near 0 and an
// enormous standard error: judged by its own variance it passes any such
// check. So each mean a suite checks carries a ceiling on its variance per
// sample: kNoiseFactor times the largest variance that the reference and the
// suite's correct alternates (tests/NN-name/validity.py: uniform instead of
// cosine sampling, other Russian roulettes, ...) have on the same estimate,
// stored in tests/NN-name/reference-variances.txt by
// tools/make-reference-images. The mean is judged with the candidate's own
// variance up to that ceiling and with the ceiling above it: noise can widen
// a check's tolerance by at most sqrt(kNoiseFactor). (A hard limit would fail
// correct estimators: one rare, large sample can lift a sample variance 7x.)
#pragma once

#include <string>

#include "statistics.h"

namespace pathlab::test {

// The margin over the stored variance, for the sampling error of both
// variances: over seeds 1..30 the reference and the alternates stay within
// 1.9x of it, with one outlier at 6.7x (docs/grader-validity.md).
inline constexpr double kNoiseFactor = 8.0;

// Gives `m` its ceiling, for the estimate this is: the k-th call in the
// current test case of `suite`. With PATHLAB_WRITE_REFERENCE_VARIANCES=1 it
// stores m's variance instead, or keeps the one stored if that is larger
// (tools/make-reference-images runs the reference, then each alternate).
void limitNoise(MeanEstimate& m, const std::string& suite);

}  // namespace pathlab::test
