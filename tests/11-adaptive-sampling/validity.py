"""Task 11's seeded mutants and alternates (tests/mutants/generate.py says what they are)."""

MUTANTS = [
    ("spread-epsilon", "a half-width below 1e-6 taken as no spread at all, so the pixel stops: right for pixels "
     "of ordinary brightness, every dark pixel stops at its minimum",
     [("  return halfWidth <= settings.tolerance * stats.mean;",
       "  return halfWidth < 1e-6 || halfWidth <= settings.tolerance * stats.mean;")]),
    ("no-spread-never-stops", "a half-width of 0 taken as not measured yet: a pixel with no spread never stops",
     [("  return halfWidth <= settings.tolerance * stats.mean;",
       "  return halfWidth > 0.0 && halfWidth <= settings.tolerance * stats.mean;")]),
    ("nominal-spp-divisor", "the colour sum divided by the maximum, not by the samples the pixel took",
     [("if (stats.n > 0) pixel.estimate = Color(sum / double(stats.n));",
       "if (stats.n > 0) pixel.estimate = Color(sum / double(settings.maxSpp));")]),
    ("estimate-of-every-sample", "the estimate the mean of all maxSpp samples, not of the n the rule stopped at "
     "(unbiased, and not adaptive: the count says n, the colour is the maximum's)",
     [("  if (stats.n > 0) pixel.estimate = Color(sum / double(stats.n));",
       "  glm::dvec3 all(0.0);\n  for (uint32_t i = 0; i < settings.maxSpp; ++i) all += glm::dvec3(sample(i));\n"
       "  if (settings.maxSpp > 0) pixel.estimate = Color(all / double(settings.maxSpp));")]),
    ("population-variance", "M2 / n: the population variance, biased low",
     [("return stats.n > 1 ? stats.m2 / double(stats.n - 1) : 0.0;", "return stats.n > 1 ? stats.m2 / double(stats.n) : 0.0;")]),
    ("checked-every-sample", "the rule checked after every sample, not after each batch",
     [("      addSample(stats, double(luminance(c)));\n    }\n    pixel.confident = confidentEnough(stats, settings);",
       "      addSample(stats, double(luminance(c)));\n      pixel.confident = confidentEnough(stats, settings);\n"
       "      if (pixel.confident) break;\n    }")]),
    ("no-maximum", "no maximum: a pixel that never meets the rule never stops",
     [("while (stats.n < settings.maxSpp && !pixel.confident) {", "while (!pixel.confident) {"),
      ("for (uint32_t k = 0; k < settings.batch && stats.n < settings.maxSpp; ++k) {", "for (uint32_t k = 0; k < settings.batch; ++k) {")]),
    ("no-minimum", "the rule allowed before the minimum",
     [("  if (stats.n < settings.minSpp) return false;\n", "")]),
    ("sum-of-squares", "M2 kept as the sum of squares, the variance as (sum x^2 - n mean^2) / (n - 1): cancellation",
     [("  const double delta = x - stats.mean;\n  stats.mean += delta / double(stats.n);\n  stats.m2 += delta * (x - stats.mean);",
       "  stats.mean += (x - stats.mean) / double(stats.n);\n  stats.m2 += x * x;"),
      ("return stats.n > 1 ? stats.m2 / double(stats.n - 1) : 0.0;",
       "return stats.n > 1 ? (stats.m2 - double(stats.n) * stats.mean * stats.mean) / double(stats.n - 1) : 0.0;")]),
    ("no-sqrt-n", "the interval 1.96 sigma, without the 1 / sqrt(n) of a mean",
     [("const double halfWidth = 1.96 * std::sqrt(sampleVariance(stats) / double(stats.n));",
       "const double halfWidth = 1.96 * std::sqrt(sampleVariance(stats));")]),
    ("variance-for-sigma", "the variance used where the standard deviation belongs",
     [("const double halfWidth = 1.96 * std::sqrt(sampleVariance(stats) / double(stats.n));",
       "const double halfWidth = 1.96 * sampleVariance(stats) / std::sqrt(double(stats.n));")]),
    ("red-channel", "the statistics of the red channel, not of the luminance",
     [("addSample(stats, double(luminance(c)));", "addSample(stats, double(c.x));")]),
    ("old-mean-twice", "Welford's M2 grown by delta^2, the old mean's deviation twice",
     [("stats.m2 += delta * (x - stats.mean);", "stats.m2 += delta * delta;")]),
]

ALTERNATES = [
    ("float-colour-sum", "the colour sum kept in float, the type of AdaptivePixel::estimate (rounding far below the noise)",
     [("  glm::dvec3 sum(0.0);", "  Color sum(0.0f);"),
      ("      sum += glm::dvec3(c);", "      sum += c;"),
      ("  if (stats.n > 0) pixel.estimate = Color(sum / double(stats.n));", "  if (stats.n > 0) pixel.estimate = sum / float(stats.n);")]),
    ("squared-rule", "the rule compared squared: (1.96)^2 s^2 / n <= (tolerance mean)^2 for a positive mean",
     [("  const double halfWidth = 1.96 * std::sqrt(sampleVariance(stats) / double(stats.n));\n"
       "  return halfWidth <= settings.tolerance * stats.mean;",
       "  const double bound = settings.tolerance * stats.mean;\n"
       "  return bound >= 0.0 && 1.96 * 1.96 * sampleVariance(stats) / double(stats.n) <= bound * bound;")]),
    ("other-welford-form", "Welford's update in its other form: M2 += (n - 1) / n delta^2, then the mean",
     [("  const double delta = x - stats.mean;\n  stats.mean += delta / double(stats.n);\n  stats.m2 += delta * (x - stats.mean);",
       "  const double delta = x - stats.mean;\n  stats.m2 += double(stats.n - 1) / double(stats.n) * delta * delta;\n"
       "  stats.mean += delta / double(stats.n);")]),
    ("colour-by-welford", "the colour's mean kept by a running mean per channel instead of a sum",
     [("      sum += glm::dvec3(c);", "      sum += (glm::dvec3(c) - sum) / double(stats.n + 1);"),
      ("if (stats.n > 0) pixel.estimate = Color(sum / double(stats.n));", "if (stats.n > 0) pixel.estimate = Color(sum);")]),
]
