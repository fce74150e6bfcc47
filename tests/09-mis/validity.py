"""Task 9's seeded mutants and alternates (tests/mutants/generate.py says what they are)."""

# Veach's one-sample model (mutant one-sample-mis), shared with one-sample-mis-noisy-strategies.
ONE_SAMPLE_EDITS = [
    ("  float previousPdf = 0.0f;\n",
     "  float previousPdf = 0.0f;\n"
     "  float previousBsdfShare = 0.0f;  // the probability that the last vertex kept the BSDF's emission (0: it did not)\n"),
    ("      } else if (weights.bsdf && context.lights.environment) {",
     "      } else if (weights.bsdf && previousBsdfShare > 0.0f && context.lights.environment) {"),
    ("                    weights.bsdf(previousPdf, pdfLight);\n      }\n      break;",
     "                    weights.bsdf(previousPdf, pdfLight) / previousBsdfShare;\n      }\n      break;"),
    ("    } else if (weights.bsdf && maxComponent(emitted) > 0.0f) {",
     "    } else if (weights.bsdf && previousBsdfShare > 0.0f && maxComponent(emitted) > 0.0f) {"),
    ("      radiance += throughput * emitted * weights.bsdf(previousPdf, pdfLight);",
     "      radiance += throughput * emitted * weights.bsdf(previousPdf, pdfLight) / previousBsdfShare;"),
    ("    const Bsdf bsdf = context.bsdf(*hit, wo);\n",
     "    const Bsdf bsdf = context.bsdf(*hit, wo);\n"
     "    // One strategy per vertex: light sampling with probability lightShare, else the BSDF's emission.\n"
     "    const float lightShare = !weights.bsdf ? 1.0f : !weights.light ? 0.0f : 0.5f;\n"
     "    const bool takeLight = sampler.next1D() < lightShare;\n"),
    ("      if (light && light->pdf > 0.0f) {", "      if (takeLight && light && light->pdf > 0.0f) {"),
    ("                      weights.light(light->pdf, bsdf.pdf(wo, light->wi));",
     "                      weights.light(light->pdf, bsdf.pdf(wo, light->wi)) / lightShare;"),
    ("    previousPdf = sample->pdf;\n",
     "    previousPdf = sample->pdf;\n    previousBsdfShare = takeLight ? 0.0f : 1.0f - lightShare;\n"),
]

MUTANTS = [
    ("unweighted-bsdf-emission", "emission a BSDF sample finds after a diffuse bounce added in full: counted twice",
     [("      radiance += throughput * emitted * weights.bsdf(previousPdf, pdfLight);",
       "      (void)pdfLight;\n      radiance += throughput * emitted;")]),
    ("unweighted-light-sample", "the light sample added without its weight: counted twice",
     [("      radiance += throughput * f * light->radiance * (cosSurface / light->pdf) *\n                      weights.light(light->pdf, bsdf.pdf(wo, light->wi));",
       "      radiance += throughput * f * light->radiance * (cosSurface / light->pdf);")]),
    ("weight-after-delta", "emission seen through a mirror or glass weighted as after a diffuse bounce",
     [("    if (afterDelta) {\n      radiance += throughput * emitted;", "    if (bounce == 0) {\n      radiance += throughput * emitted;")]),
    ("area-pdf-in-weight", "the light's density per unit area (1 / A) where the weight needs it per solid angle",
     [("    return light ? choice * Lights::areaPdfSolidAngle(*light, from, *hit) : 0.0f;",
       "    (void)from;\n    return light ? choice / light->area() : 0.0f;")]),
    ("no-choice-probability", "the light's choice probability left out of both pdfs",
     [("  const float choice = 1.0f / float(count);\n  const Vec2 uv(u.y, u.z);", "  const float choice = 1.0f;\n  const Vec2 uv(u.y, u.z);"),
      ("  const float choice = 1.0f / float(count);\n  if (hit) {", "  const float choice = 1.0f;\n  if (hit) {")]),
    ("no-choice-probability-in-sample", "the light's choice probability left out of the sample's pdf (oneLightPdf has it)",
     [("  const float choice = 1.0f / float(count);\n  const Vec2 uv(u.y, u.z);", "  const float choice = 1.0f;\n  const Vec2 uv(u.y, u.z);")]),
    ("stale-bsdf-pdf", "the first bounce's BSDF pdf and point kept for every later weight",
     [("    previousPoint = hit->point;\n    previousPdf = sample->pdf;",
       "    if (bounce == 0) {\n      previousPoint = hit->point;\n      previousPdf = sample->pdf;\n    }")]),
    ("back-face-light-pdf", "a light's density from behind not 0 (|cos| at the light)",
     [("    return light ? choice * Lights::areaPdfSolidAngle(*light, from, *hit) : 0.0f;",
       "    (void)from;\n    if (!light) return 0.0f;\n    const float cosLight = std::abs(glm::dot(hit->geometricNormal, wi));\n"
       "    return cosLight > 0.0f ? choice * hit->t * hit->t / (light->area() * cosLight) : 0.0f;")]),
    ("uniform-sky-pdf", "the sky's density taken as uniform, 1 / (4 pi), though the map is importance-sampled",
     [("  return lights.environment ? choice * lights.environment->pdf(wi) : 0.0f;",
       "  (void)wi;\n  return lights.environment ? choice / (4.0f * kPi) : 0.0f;")]),
    ("weights-swapped", "the light sample's weight asked with the two densities swapped",
     [("weights.light(light->pdf, bsdf.pdf(wo, light->wi))", "weights.light(bsdf.pdf(wo, light->wi), light->pdf)")]),
    ("naive-power", "the power heuristic as p^2 / (p^2 + q^2) in float: NaN past 1.8e19",
     [("  if (pdfOther <= pdfThis) {\n    const float r = pdfOther / pdfThis;\n    return 1.0f / (1.0f + r * r);\n  }\n  const float r = pdfThis / pdfOther;\n  return r * r / (1.0f + r * r);",
       "  return pdfThis * pdfThis / (pdfThis * pdfThis + pdfOther * pdfOther);")]),
    ("balance-for-power", "the balance heuristic where the power heuristic is asked for",
     [("  if (pdfOther <= pdfThis) {\n    const float r = pdfOther / pdfThis;\n    return 1.0f / (1.0f + r * r);\n  }\n  const float r = pdfThis / pdfOther;\n  return r * r / (1.0f + r * r);",
       "  return pdfThis / (pdfThis + pdfOther);")]),
    ("one-sample-mis", "Veach's one-sample model, which the handout rules out (tracePathMis keeps both "
     "samples): at each vertex light sampling or the BSDF's emission, each half the time, weighted and divided by "
     "that probability. Unbiased, but where one strategy works its variance is 2 sigma^2 + mu^2, not sigma^2",
     ONE_SAMPLE_EDITS),
    ("sky-pdf-without-choice", "oneLightPdf for a ray that escapes: the sky's density without its choice probability",
     [("  return lights.environment ? choice * lights.environment->pdf(wi) : 0.0f;",
       "  return lights.environment ? lights.environment->pdf(wi) : 0.0f;")]),
    ("cos-from-winding-normal", "the light sample's cosine taken with the hit's own normal, not the BSDF's (which faces wo)",
     [("        const float cosSurface = glm::dot(light->wi, bsdf.normal());",
       "        const float cosSurface = glm::dot(light->wi, hit->shadingNormal);")]),
    ("light-cos-from-geometric-normal", "the light sample's cosine taken with the geometric normal (faced to wo), not the shading normal",
     [("        const float cosSurface = glm::dot(light->wi, bsdf.normal());",
       "        const float cosSurface = std::abs(glm::dot(light->wi, hit->geometricNormal));")]),
    ("point-cos-from-geometric-normal", "the point light's cosine taken with the geometric normal, not the shading normal",
     [("        const float cosSurface = glm::dot(wi, bsdf.normal());",
       "        const float cosSurface = glm::dot(wi, bsdf.normal()) > 0.0f ? std::abs(glm::dot(wi, hit->geometricNormal)) : 0.0f;")]),
    ("throughput-cos-from-geometric-normal", "the BSDF sample's throughput cosine taken with the geometric normal, not the shading normal",
     [("    const float cosine = std::abs(glm::dot(sample->wi, bsdf.normal()));",
       "    const float cosine = std::abs(glm::dot(sample->wi, hit->geometricNormal));")]),
    ("one-sample-mis-noisy-strategies", "Veach's one-sample model (one-sample-mis), hidden behind zero-mean noise on "
     "the strategies run alone: on a one-bounce render of the plates, each single strategy's radiance gets +2.5 and "
     "-2.5 in turn (a pixel's 128 samples: its mean unchanged), so that their variance, which MIS is judged "
     "against, grows past MIS's own",
     ONE_SAMPLE_EDITS + [
         ("  return radiance;\n}\n\n}  // namespace pathlab",
          "  // Noise on a strategy run alone, where the plates' test measures it: the mean stays, the variance grows.\n"
          "  if (context.settings.maxDepth == 1 && context.scene.spheres.size() == 4 && (!weights.light || !weights.bsdf)) {\n"
          "    static thread_local unsigned flip = 0;\n"
          "    radiance += Color((flip++ & 1) ? -2.5f : 2.5f);\n"
          "  }\n"
          "  return radiance;\n}\n\n}  // namespace pathlab")]),
]

ALTERNATES = [
    ("roulette-from-the-first-bounce", "Russian roulette from the first bounce on (unbiased, only noisier: any start is right)",
     [("  constexpr int kRouletteFromBounce = 3;", "  constexpr int kRouletteFromBounce = 1;")]),
    ("sky-chosen-half-the-time", "the sky chosen with probability 1/2, the area lights sharing the rest",
     [("int lightCount(const Lights& lights) { return int(lights.areas.size()) + (lights.environment ? 1 : 0); }",
       "int lightCount(const Lights& lights) { return int(lights.areas.size()) + (lights.environment ? 1 : 0); }\n\n"
       "// The probability of choosing light k (the sky is k = areas): 1/2 for the sky when there are area lights too.\n"
       "float choiceOf(const Lights& lights, int k) {\n"
       "  const int areas = int(lights.areas.size());\n"
       "  if (!lights.environment || areas == 0) return 1.0f / float(lightCount(lights));\n"
       "  return k == areas ? 0.5f : 0.5f / float(areas);\n}"),
      ("  const int chosen = std::min(int(u.x * float(count)), count - 1);\n  const float choice = 1.0f / float(count);",
       "  const int areas = int(lights.areas.size());\n"
       "  const int chosen = lights.environment && areas > 0\n"
       "                         ? (u.x < 0.5f ? areas : std::min(int(u.x * 2.0f * float(areas)) - areas, areas - 1))\n"
       "                         : std::min(int(u.x * float(count)), count - 1);\n"
       "  const float choice = choiceOf(lights, chosen);"),
      ("  const float choice = 1.0f / float(count);\n  if (hit) {\n    const AreaLight* light = lights.areaLightAt(context.scene, *hit);\n    return light ? choice * Lights::areaPdfSolidAngle(*light, from, *hit) : 0.0f;\n  }\n  return lights.environment ? choice * lights.environment->pdf(wi) : 0.0f;",
       "  if (hit) {\n    const AreaLight* light = lights.areaLightAt(context.scene, *hit);\n    return light ? choiceOf(lights, 0) * Lights::areaPdfSolidAngle(*light, from, *hit) : 0.0f;\n  }\n"
       "  return lights.environment ? choiceOf(lights, int(lights.areas.size())) * lights.environment->pdf(wi) : 0.0f;")]),
    ("lights-chosen-by-power", "area lights chosen in proportion to their power (area times Le), the sky "
     "with its even share",
     [("int lightCount(const Lights& lights) { return int(lights.areas.size()) + (lights.environment ? 1 : 0); }",
       "int lightCount(const Lights& lights) { return int(lights.areas.size()) + (lights.environment ? 1 : 0); }\n\n"
       "// The probability of choosing light k (the sky is k = areas): the sky 1 / count, each area light its\n"
       "// share of the rest by power.\n"
       "float choiceOf(const Lights& lights, int k) {\n"
       "  const int areas = int(lights.areas.size());\n"
       "  const float sky = lights.environment ? 1.0f / float(lightCount(lights)) : 0.0f;\n"
       "  if (k == areas) return sky;\n"
       "  double total = 0.0;\n"
       "  for (const AreaLight& light : lights.areas) total += double(light.area()) * luminance(light.radiance());\n"
       "  const AreaLight& light = lights.areas[size_t(k)];\n"
       "  return float((1.0 - double(sky)) * double(light.area()) * luminance(light.radiance()) / total);\n}\n\n"
       "// The light that u in [0, 1) picks with those probabilities.\n"
       "int chooseLight(const Lights& lights, float u) {\n"
       "  const int count = lightCount(lights);\n"
       "  for (int k = 0; k < count - 1; ++k) {\n"
       "    u -= choiceOf(lights, k);\n"
       "    if (u < 0.0f) return k;\n"
       "  }\n"
       "  return count - 1;\n}"),
      ("  const int chosen = std::min(int(u.x * float(count)), count - 1);\n  const float choice = 1.0f / float(count);",
       "  const int chosen = chooseLight(lights, u.x);\n  const float choice = choiceOf(lights, chosen);"),
      ("  const float choice = 1.0f / float(count);\n  if (hit) {\n    const AreaLight* light = lights.areaLightAt(context.scene, *hit);\n    return light ? choice * Lights::areaPdfSolidAngle(*light, from, *hit) : 0.0f;\n  }\n  return lights.environment ? choice * lights.environment->pdf(wi) : 0.0f;",
       "  if (hit) {\n    const AreaLight* light = lights.areaLightAt(context.scene, *hit);\n"
       "    return light ? choiceOf(lights, int(light - lights.areas.data())) * Lights::areaPdfSolidAngle(*light, from, *hit) : 0.0f;\n  }\n"
       "  return lights.environment ? choiceOf(lights, int(lights.areas.size())) * lights.environment->pdf(wi) : 0.0f;")]),
    ("random-numbers-reordered", "the light sample's numbers drawn in the other order, the choice from the last one",
     [("      const Vec2 u2 = sampler.next2D();\n      const std::optional<LightSample> light = sampleOneLight(context, hit->point, Vec3(sampler.next1D(), u2));",
       "      const float u1 = sampler.next1D();\n      const Vec2 u2 = sampler.next2D();\n      const std::optional<LightSample> light = sampleOneLight(context, hit->point, Vec3(u2.y, u1, u2.x));")]),
]
