"""Task 5's seeded mutants and alternates (tests/mutants/generate.py says what they are)."""

MUTANTS = [
    ("plus-minus-1e10", "returns +1e10 and -1e10 in turn, tracing nothing: a mean near 0 bought with noise",
     [("  constexpr int kRouletteFromBounce = 3;\n",
       "  static thread_local unsigned flip = 0;\n  if (flip < ~0u) return Color((flip++ & 1) ? 1e10f : -1e10f);\n"
       "  constexpr int kRouletteFromBounce = 3;\n")]),
    ("emission-counted-twice", "emission added after diffuse bounces too",
     [("    countEmission = sample->isDelta;", "    countEmission = true;")]),
    ("roulette-not-rescaled", "Russian roulette without dividing by q",
     [("      throughput /= q;", "      (void)q;")]),
    ("roulette-rescaled-twice", "Russian roulette divides by q twice",
     [("      throughput /= q;", "      throughput /= q * q;")]),
    ("no-pdf-division", "throughput not divided by the pdf",
     [("throughput *= sample->f * (cosine / sample->pdf);", "throughput *= sample->f * cosine;")]),
    ("missing-cosine", "throughput without the cosine",
     [("throughput *= sample->f * (cosine / sample->pdf);", "(void)cosine;\n    throughput *= sample->f / sample->pdf;")]),
    ("pdf-mismatch", "a uniform pdf for a cosine-weighted sampler",
     [("float diffuseDirectionPdf(const Vec3& wi) { return wi.z > 0.0f ? wi.z * kInvPi : 0.0f; }",
       "float diffuseDirectionPdf(const Vec3& wi) { return wi.z > 0.0f ? 0.5f * kInvPi : 0.0f; }")]),
    ("horizon-never-sampled", "cosine sampling that never goes below 18 degrees over the horizon, with the pdf "
     "that matches it (0 there): consistent with itself, and a tenth of the light lost",
     [("  const float r = std::sqrt(u.x), phi = 2.0f * kPi * u.y;\n  return {r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0f, 1.0f - u.x))};",
       "  const float r = std::sqrt(0.9f * u.x), phi = 2.0f * kPi * u.y;\n  return {r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0f, 1.0f - 0.9f * u.x))};"),
      ("float diffuseDirectionPdf(const Vec3& wi) { return wi.z > 0.0f ? wi.z * kInvPi : 0.0f; }",
       "float diffuseDirectionPdf(const Vec3& wi) { return wi.z > 0.31622777f ? wi.z * kInvPi / 0.9f : 0.0f; }")]),
    ("sampler-returns-the-normal", "every diffuse direction the normal itself, with the cosine pdf: f cos / pdf "
     "is the albedo on every sample, so the energy test's mean alone passes it",
     [("  const float r = std::sqrt(u.x), phi = 2.0f * kPi * u.y;\n  return {r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0f, 1.0f - u.x))};",
       "  (void)u;\n  return {0.0f, 0.0f, 1.0f};")]),
    ("bounce-range-epsilon", "each bounce leaves from the hit point itself, its range starting at t = 1e-4 instead "
     "of an offset origin: right at scale 1, walls skipped in a small scene and acne in a large one",
     [("    const std::optional<Hit> hit = context.intersect(ray, Interval{0.0f, kInfinity});",
       "    const std::optional<Hit> hit = context.intersect(ray, Interval{1e-4f, kInfinity});"),
      ("    ray = Ray{offsetRayOrigin(hit->point, hit->geometricNormal, sample->wi), sample->wi};",
       "    ray = Ray{hit->point, sample->wi};")]),
    ("depth-off-by-one", "one bounce more than -m allows",
     [("    if (bounce >= context.settings.maxDepth) break;", "    if (bounce > context.settings.maxDepth) break;")]),
    ("direct-light-only-at-first-hit", "next-event estimation only at the camera hit",
     [("    radiance += throughput * estimateDirectLighting(context, *hit, bsdf, wo, sampler);",
       "    if (bounce == 0) radiance += throughput * estimateDirectLighting(context, *hit, bsdf, wo, sampler);")]),
    ("environment-counted-twice", "escaped rays add the environment after diffuse bounces too",
     [("      if (countEmission) radiance += throughput * context.background(ray.direction);",
       "      radiance += throughput * context.background(ray.direction);")]),
    ("sky-lost-after-mirror", "the environment counted for camera rays only, not after mirror or glass bounces",
     [("      if (countEmission) radiance += throughput * context.background(ray.direction);",
       "      if (bounce == 0) radiance += throughput * context.background(ray.direction);")]),
    ("flat-grey", "returns 0.5 for every path, tracing nothing: finite, never negative and sometimes bright, all "
     "that the Cornell box's NaN test asked before it knew exact values",
     [("  constexpr int kRouletteFromBounce = 3;\n",
       "  if (ray.direction.x == ray.direction.x) return Color(0.5f);  // every ray\n"
       "  constexpr int kRouletteFromBounce = 3;\n")]),
    ("ambient-without-sky", "a ray that leaves a scene with no sky sees a dim grey ambient instead of black",
     [("      if (countEmission) radiance += throughput * context.background(ray.direction);",
       "      if (countEmission) {\n        radiance += throughput * (context.lights.environment ? context.background(ray.direction) : Color(0.02f));\n      }")]),
]

ALTERNATES = [
    ("uniform-hemisphere", "uniform hemisphere sampling, p = 1 / (2 pi)",
     [("  const float r = std::sqrt(u.x), phi = 2.0f * kPi * u.y;\n  return {r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0f, 1.0f - u.x))};",
       "  const float z = u.x, r = std::sqrt(std::max(0.0f, 1.0f - z * z)), phi = 2.0f * kPi * u.y;\n  return {r * std::cos(phi), r * std::sin(phi), z};"),
      ("float diffuseDirectionPdf(const Vec3& wi) { return wi.z > 0.0f ? wi.z * kInvPi : 0.0f; }",
       "float diffuseDirectionPdf(const Vec3& wi) { return wi.z > 0.0f ? 0.5f * kInvPi : 0.0f; }")]),
    ("concentric-disk", "Shirley-Chiu concentric disk mapping, lifted onto the hemisphere",
     [("  const float r = std::sqrt(u.x), phi = 2.0f * kPi * u.y;\n  return {r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0f, 1.0f - u.x))};",
       "  const float a = 2.0f * u.x - 1.0f, b = 2.0f * u.y - 1.0f;\n"
       "  if (a == 0.0f && b == 0.0f) return {0.0f, 0.0f, 1.0f};\n"
       "  float r, phi;\n"
       "  if (std::abs(a) > std::abs(b)) r = a, phi = (kPi / 4.0f) * (b / a);\n"
       "  else r = b, phi = kPi / 2.0f - (kPi / 4.0f) * (a / b);\n"
       "  const float x = r * std::cos(phi), y = r * std::sin(phi);\n"
       "  return {x, y, std::sqrt(std::max(0.0f, 1.0f - x * x - y * y))};")]),
    ("fixed-roulette", "Russian roulette with a fixed q = 0.8 from the second bounce",
     [("      const float q = std::min(0.95f, maxComponent(throughput));", "      const float q = 0.8f;"),
      ("  constexpr int kRouletteFromBounce = 3;", "  constexpr int kRouletteFromBounce = 2;")]),
    ("roulette-from-first-vertex", "Russian roulette from the camera hit on (unbiased, noisier)",
     [("  constexpr int kRouletteFromBounce = 3;", "  constexpr int kRouletteFromBounce = 0;")]),
]
