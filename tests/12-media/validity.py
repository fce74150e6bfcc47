"""Task 12's seeded mutants and alternates: edits of its reference,
solutions/12-media/media.cpp, that tests/mutants/generate.py writes into
tests/mutants/12-media/ and tests/alternates/12-media/. A mutant is one
realistic mistake and must lose points in the task's suite; an alternate is
a correct solution written differently and must score full marks (CTest
label "validity"). Each entry: (name, description, [(old, new), ...]), old
a piece of the reference and new what replaces it. Not in the student
release: the pieces are the reference's own lines."""

MUTANTS = [
    ("interface-exits-to-vacuum", "an interface crossed by hand: its interior going in, a vacuum going out (not the scene's medium)",
     [("      medium = scene.mediumAcross(*hit, ray.direction, medium);",
       "      medium = glm::dot(ray.direction, hit->geometricNormal) < 0.0f ? scene.materials[hit->material].interior : kVacuum;")]),
    ("flight-rate-inverted", "t = -ln(1 - u) sigmaT: the mean free path taken for the extinction",
     [("const float t = -std::log1p(-u) / sigmaT;", "const float t = -std::log1p(-u) * sigmaT;")]),
    ("flight-ignores-surface", "every flight scatters, even past the surface",
     [("  if (t < tMax) return {t, true, sigmaT * std::exp(-sigmaT * t)};",
       "  if (t < kInfinity) return {t, true, sigmaT * std::exp(-sigmaT * t)};")]),
    ("pass-pdf-as-density", "the surface's probability given as the density sigmaT exp(-sigmaT tMax)",
     [("  return {tMax, false, std::exp(-sigmaT * tMax)};", "  return {tMax, false, sigmaT * std::exp(-sigmaT * tMax)};")]),
    ("flight-with-sigma-s", "the free flight drawn with sigmaS instead of sigmaT: absorption never happens",
     [("sampleFreeFlight(m.sigmaT, hit ? hit->t : kInfinity, sampler.next1D());",
       "sampleFreeFlight(maxComponent(m.sigmaS()), hit ? hit->t : kInfinity, sampler.next1D());")]),
    ("pass-weight-without-probability", "the surface weighted by the transmittance, not divided by P(pass)",
     [("      // Passed: transmittance over its probability, exp(-sigmaT t) / exp(-sigmaT t) = 1.\n",
       "      throughput *= std::exp(-m.sigmaT * flight.t);\n")]),
    ("scattering-as-absorption", "the scattering event weighted by sigmaA / sigmaT: scattering counted as absorption",
     [("        throughput *= m.albedo;", "        throughput *= m.sigmaA() / m.sigmaT;")]),
    ("scattering-ends-path", "a scattering event ends the path, as if it were absorbed",
     [("        throughput *= m.albedo;", "        break;")]),
    ("hg-sign-flipped", "the phase function with the cosine against the direction back (pbrt's): g flipped",
     [("const float denominator = 1.0f + g * g - 2.0f * g * cosTheta;",
       "const float denominator = 1.0f + g * g + 2.0f * g * cosTheta;")]),
    ("hg-sampling-sign-flipped", "directions sampled with g flipped: mostly back for g > 0",
     [("    cosTheta = (1.0f + g * g - s * s) / (2.0f * g);", "    cosTheta = -(1.0f + g * g - s * s) / (2.0f * g);")]),
    ("hg-no-normalisation", "the phase function without its 1 / 4 pi",
     [("return (1.0f - g * g) / (4.0f * kPi * denominator * std::sqrt(denominator));",
       "return (1.0f - g * g) / (denominator * std::sqrt(denominator));")]),
    ("hg-cos-uniform", "cos theta uniform whatever g (the isotropic sampler kept)",
     [("  if (std::abs(g) >= 1e-3f) {", "  if (false) {")]),
    ("shadow-ignores-medium", "shadow rays ignore the medium: transmittance 1 through fog",
     [("    if (medium != kVacuum) fraction *= std::exp(-scene.media[medium].sigmaT * travelled);\n",
       "    (void)travelled;\n")]),
    ("shadow-blocked-by-interface", "an interface blocks shadow rays like any surface",
     [("    if (scene.materials[hit->material].type != MaterialType::Interface) return 0.0f;", "    return 0.0f;")]),
    ("shadow-medium-not-switched", "the shadow ray keeps its first medium past an interface",
     [("    medium = scene.mediumAcross(*hit, ray.direction, medium);\n    const Point3 origin", "    const Point3 origin")]),
    ("phase-with-cosine", "the phase function multiplied by a cosine, as a BSDF is",
     [("    if (!bsdf) return Color(henyeyGreenstein(glm::dot(-vertex.wo, wi), vertex.g));",
       "    if (!bsdf) return Color(henyeyGreenstein(glm::dot(-vertex.wo, wi), vertex.g) * std::abs(glm::dot(wi, vertex.wo)));")]),
    ("phase-against-wo", "the phase function of dot(wo, wi): the direction back taken for the one travelled",
     [("    if (!bsdf) return Color(henyeyGreenstein(glm::dot(-vertex.wo, wi), vertex.g));",
       "    if (!bsdf) return Color(henyeyGreenstein(glm::dot(vertex.wo, wi), vertex.g));")]),
    ("medium-not-switched-through-glass", "after a BSDF sample through glass the path stays in its medium",
     [("    medium = scene.mediumAcross(*hit, sample->wi, medium);\n", "")]),
    ("interface-ends-emission", "emission not counted after an interface",
     [("      medium = scene.mediumAcross(*hit, ray.direction, medium);\n      ray.origin",
       "      medium = scene.mediumAcross(*hit, ray.direction, medium);\n      countEmission = false;\n      ray.origin")]),
    ("no-direct-light-in-medium", "no direct lighting at points in a medium",
     [("        radiance += throughput * estimateDirectLightingInMedia(context, vertex, medium, sampler);\n",
       "        (void)vertex;\n")]),
    ("plus-minus-1e10", "returns +1e10 and -1e10 in turn, tracing nothing: a mean near 0 bought with noise",
     [("  constexpr int kRouletteFromBounce = 3;\n",
       "  static thread_local unsigned flip = 0;\n  if (flip < ~0u) return Color((flip++ & 1) ? 1e10f : -1e10f);\n"
       "  constexpr int kRouletteFromBounce = 3;\n")]),
]

ALTERNATES = [
    ("log-u", "t = -ln(u) / sigmaT: u for 1 - u",
     [("const float t = -std::log1p(-u) / sigmaT;", "const float t = -std::log(u) / sigmaT;")]),
    ("hg-other-end", "the Henyey-Greenstein CDF inverted from the other end of u",
     [("const float s = (1.0f - g * g) / (1.0f - g + 2.0f * g * u.x);", "const float s = (1.0f - g * g) / (1.0f + g - 2.0f * g * u.x);")]),
    ("hg-other-frame", "the sampled direction built in another frame (a cross product with an axis), phi from 1 - u.y",
     [("  const float phi = 2.0f * kPi * u.y;\n  const Frame frame = Frame::fromNormal(direction);\n"
       "  return glm::normalize(frame.toWorld({sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta}));",
       "  const float phi = 2.0f * kPi * (1.0f - u.y);\n"
       "  const Vec3 axis = std::abs(direction.x) < 0.5f ? Vec3(1, 0, 0) : Vec3(0, 1, 0);\n"
       "  const Vec3 b1 = glm::normalize(glm::cross(direction, axis)), b2 = glm::cross(direction, b1);\n"
       "  return glm::normalize(sinTheta * (std::sin(phi) * b1 + std::cos(phi) * b2) + cosTheta * direction);")]),
    ("track-length-transmittance", "transmittance estimated by a free flight per stretch: 1 if it passes, else 0",
     [("float transmittance(TraceContext& context, Ray ray, float distance, MediumIndex medium, Sampler& /*sampler*/) {",
       "float transmittance(TraceContext& context, Ray ray, float distance, MediumIndex medium, Sampler& sampler) {"),
      ("    if (medium != kVacuum) fraction *= std::exp(-scene.media[medium].sigmaT * travelled);\n",
       "    if (medium != kVacuum && sampleFreeFlight(scene.media[medium].sigmaT, travelled, sampler.next1D()).scattered) {\n"
       "      return 0.0f;\n    }\n")]),
]
