"""Task 4's seeded mutants and alternates (tests/mutants/generate.py says what they are)."""

MUTANTS = [
    ("missing-inv-pi", "the Lambertian BRDF without 1/pi",
     [("Color lambertianBrdf(const Color& albedo) { return albedo * kInvPi; }", "Color lambertianBrdf(const Color& albedo) { return albedo; }")]),
    ("missing-light-cosine", "pdfSolidAngle without the light's cosine",
     [("sample.pdfArea * distanceSquared / cosLight", "sample.pdfArea * distanceSquared")]),
    ("missing-surface-cosine", "no cos(theta) at the surface",
     [("sum += f * sample.radiance * (cosSurface / direction->pdfSolidAngle);", "sum += f * sample.radiance * (1.0f / direction->pdfSolidAngle);")]),
    ("no-pdf-division", "area samples not divided by their pdf",
     [("sum += f * sample.radiance * (cosSurface / direction->pdfSolidAngle);", "sum += f * sample.radiance * (cosSurface);")]),
    ("shadow-ray-reaches-light", "shadow rays run the full distance to the light",
     [("Interval{0.0f, remaining * (1.0f - kShadowShortening)}", "Interval{0.0f, remaining * 1.0001f}")]),
    ("shadow-ray-fixed-shortening", "shadow rays end a fixed 1e-4 short of the light, not a fraction of the "
     "distance: right at scale 1, wrong in a scene 1000 times smaller or with the lights thousands of units away",
     [("Interval{0.0f, remaining * (1.0f - kShadowShortening)}", "Interval{0.0f, remaining - 1e-4f}")]),
    ("one-sky-sample", "the sky sampled once whatever -l says: unbiased, but the handout asks for as many samples "
     "as an area light gets",
     [("    for (int i = 0; i < context.settings.lightSamples; ++i) {\n      const std::optional<EnvironmentLightSample>",
       "    for (int i = 0; i < 1; ++i) {\n      const std::optional<EnvironmentLightSample>"),
      ("      sum += f * sample->radiance * (cosSurface / sample->pdfSolidAngle);\n    }\n    radiance += sum / float(context.settings.lightSamples);",
       "      sum += f * sample->radiance * (cosSurface / sample->pdfSolidAngle);\n    }\n    radiance += sum;")]),
    ("fixed-epsilon-offset", "ray origins moved by a fixed 1e-4",
     [("    result[a] = std::abs(p[a]) < kOrigin ? p[a] + kFloatScale * n[a] : moved;", "    (void)moved, (void)kOrigin, (void)kFloatScale;\n    result[a] = p[a] + 1e-4f * n[a];")]),
    ("relative-epsilon-offset", "ray origins moved by 1e-4 of the coordinates' size: too little near the origin of a large triangle",
     [("    result[a] = std::abs(p[a]) < kOrigin ? p[a] + kFloatScale * n[a] : moved;",
       "    (void)moved, (void)kFloatScale, (void)kOrigin;\n    result[a] = p[a] + 1e-4f * std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z), 1e-3f}) * n[a];")]),
    ("no-offset", "shadow rays start exactly on the surface",
     [("  const Point3 origin = offsetRayOrigin(hit.point, hit.geometricNormal, wi);", "  const Point3 origin = hit.point;")]),
    ("no-shadows", "occlusion never tested",
     [("  return !context.occluded(Ray{origin, toLight / remaining}, Interval{0.0f, remaining * (1.0f - kShadowShortening)});",
       "  (void)remaining;\n  return true;")]),
    ("two-sided-lights", "lights seen from behind still emit",
     [("const float cosLight = -glm::dot(sample.normal, wi);", "const float cosLight = std::abs(glm::dot(sample.normal, wi));")]),
    ("light-samples-not-averaged", "-l samples summed, not averaged",
     [("    radiance += sum / float(context.settings.lightSamples);\n  }\n\n  // The environment", "    radiance += sum;\n  }\n\n  // The environment")]),
    ("skips-environment", "the environment is never sampled (recipe step 4 left out)",
     [("if (const std::optional<EnvironmentLight>& environment = context.lights.environment) {",
       "if (const std::optional<EnvironmentLight>& environment = context.lights.environment; false && environment) {")]),
    ("cosine-from-unflipped-normal", "cos(theta) from the shading normal as stored, not bsdf.normal()",
     [("const float cosSurface = glm::dot(wi, bsdf.normal());", "const float cosSurface = glm::dot(wi, hit.shadingNormal);"),
      ("const float cosSurface = glm::dot(direction->wi, bsdf.normal());",
       "const float cosSurface = glm::dot(direction->wi, hit.shadingNormal);"),
      ("const float cosSurface = glm::dot(sample->direction, bsdf.normal());",
       "const float cosSurface = glm::dot(sample->direction, hit.shadingNormal);")]),
    ("skips-point-lights", "point lights never sampled",
     [("  for (const PointLight& light : context.lights.points) {\n",
       "  for (const PointLight& light : context.lights.points) {\n    if (maxComponent(light.intensity) >= 0.0f) continue;\n")]),
    ("plus-minus-1e10", "returns +1e10 and -1e10 in turn, computing nothing: a mean near 0 bought with noise",
     [("  if (bsdf.isDelta()) return Color(0.0f);  // a perfect mirror or glass reflects no light source directly\n",
       "  static thread_local unsigned flip = 0;\n  if (flip < ~0u) return Color((flip++ & 1) ? 1e10f : -1e10f);\n"
       "  if (bsdf.isDelta()) return Color(0.0f);  // a perfect mirror or glass reflects no light source directly\n")]),
    ("forged-shadow-log", "occlusion tested with closest-hit queries, and the shadow rays the test looks for written "
     "into the trace context's public log by hand (context.log): every estimate right, the log invented",
     [("  if (distance == kInfinity) return !context.occluded(Ray{origin, wi}, Interval{0.0f, kInfinity});\n"
       "  const Vec3 toLight = hit.point + wi * distance - origin;\n"
       "  const float remaining = glm::length(toLight);\n"
       "  return !context.occluded(Ray{origin, toLight / remaining}, Interval{0.0f, remaining * (1.0f - kShadowShortening)});",
       "  const Vec3 toLight = hit.point + wi * distance - origin;\n"
       "  const float remaining = glm::length(toLight);\n"
       "  const Ray ray = distance == kInfinity ? Ray{origin, wi} : Ray{origin, toLight / remaining};\n"
       "  const Interval range{0.0f, distance == kInfinity ? kInfinity : remaining * (1.0f - kShadowShortening)};\n"
       "  std::vector<TracedRay>* const log = context.log;\n"
       "  context.log = nullptr;  // the closest-hit query unrecorded\n"
       "  const bool blocked = context.intersect(ray, range).has_value();\n"
       "  context.log = log;\n"
       "  if (log) log->push_back({ray, range, true, blocked, Hit{}});  // recorded as if it were an occlusion query\n"
       "  return !blocked;")]),
    ("grazing-cosine-floor", "a point light's cosine kept at 0.1 or more, so that grazing light does not fade to "
     "black (the light still 0 from below the horizon)",
     [("    radiance += f * light.intensity * (cosSurface / distanceSquared);",
       "    radiance += f * light.intensity * (std::max(cosSurface, 0.1f) / distanceSquared);")]),
]

ALTERNATES = [
    ("swapped-light-randoms", "the light sample's two random numbers in the other order",
     [("      const AreaSample sample = light.sample(sampler.next2D());", "      const Vec2 u = sampler.next2D();\n      const AreaSample sample = light.sample(Vec2(u.y, u.x));")]),
]
