"""Task 8's seeded mutants and alternates (tests/mutants/generate.py says what they are)."""

MUTANTS = [
    ("missing-jacobian", "the conductor's pdf without the 1 / (4 |wo.m|) of the reflection",
     [("  return visibleNormalPdf(wo, h, alphaFromRoughness(conductor.roughness)) / (4.0f * std::abs(glm::dot(wo, h)));",
       "  return visibleNormalPdf(wo, h, alphaFromRoughness(conductor.roughness));")]),
    ("dcos-pdf-with-visible-normals", "visible normals sampled, but the pdf of D cos theta sampling returned",
     [("  return visibleNormalPdf(wo, h, alphaFromRoughness(conductor.roughness)) / (4.0f * std::abs(glm::dot(wo, h)));",
       "  const float alpha = alphaFromRoughness(conductor.roughness);\n  return ggxD(h, alpha) * h.z / (4.0f * std::abs(glm::dot(wo, h)));")]),
    ("g1-for-g2", "G1(wi) where the BRDF needs G2(wo, wi)",
     [("  const float coat = ggxD(h, alpha) * smithG2(wo, wi, h, alpha) *",
       "  const float coat = ggxD(h, alpha) * smithG1(wi, h, alpha) *"),
      ("  return fresnel * (ggxD(h, alpha) * smithG2(wo, wi, h, alpha) / (4.0f * wo.z * wi.z));",
       "  return fresnel * (ggxD(h, alpha) * smithG1(wi, h, alpha) / (4.0f * wo.z * wi.z));")]),
    ("alpha-is-roughness", "alpha = roughness, not roughness squared",
     [("float alphaFromRoughness(float roughness) { return std::max(roughness * roughness, 1e-3f); }",
       "float alphaFromRoughness(float roughness) { return std::max(roughness, 1e-3f); }")]),
    ("half-vector-below", "the half vector taken on the lower side, -(wo + wi)",
     [("  const Vec3 h = glm::normalize(sum);\n  const float alpha = alphaFromRoughness(conductor.roughness);",
       "  const Vec3 h = -glm::normalize(sum);\n  const float alpha = alphaFromRoughness(conductor.roughness);")]),
    ("chosen-lobe-pdf", "the plastic's pdf of the lobe that drew wi, not the mixture's",
     [("  s.pdf = plasticPdf(wo, wi, plastic);",
       "  const Vec3 h = glm::normalize(wo + wi);\n  s.pdf = u.x < coatChance ? visibleNormalPdf(wo, h, alphaFromRoughness(plastic.roughness)) / (4.0f * std::abs(glm::dot(wo, h)))\n                           : diffuseDirectionPdf(wi);")]),
    ("lambda-without-half", "Lambda without the 1/2: (sqrt(1 + alpha^2 tan^2) - 1)",
     [("  return 0.5f * (std::sqrt(1.0f + alpha * alpha * tan2) - 1.0f);", "  return std::sqrt(1.0f + alpha * alpha * tan2) - 1.0f;")]),
    ("d-without-pi", "D without the 1/pi: not normalised",
     [("  return a2 / (kPi * t * t);", "  return a2 / (t * t);")]),
    # Blender 3.4's Cycles uses this form (docs/microfacet-validation.md); the
    # handout asks for the height-correlated G2 and says why.
    ("separable-g2", "the separable G1(wo) G1(wi) where the handout asks for the height-correlated G2",
     [("  return 1.0f / (1.0f + smithLambda(wo, alpha) + smithLambda(wi, alpha));",
       "  return 1.0f / ((1.0f + smithLambda(wo, alpha)) * (1.0f + smithLambda(wi, alpha)));")]),
]

ALTERNATES = [
    ("uniform-base", "the plastic's base sampled uniformly over the hemisphere, with the mixture pdf that matches",
     [("    wi = sampleDiffuseDirection(Vec2((u.x - coatChance) / (1.0f - coatChance), u.y));",
       "    const float z = (u.x - coatChance) / (1.0f - coatChance), r = std::sqrt(std::max(0.0f, 1.0f - z * z));\n"
       "    wi = Vec3(r * std::cos(2.0f * kPi * u.y), r * std::sin(2.0f * kPi * u.y), z);"),
      ("  return coatChance * coat + (1.0f - coatChance) * diffuseDirectionPdf(wi);",
       "  return coatChance * coat + (1.0f - coatChance) * (0.5f * kInvPi);")]),
    ("dcos-sampling", "the conductor sampled by D cos theta (not the visible normals), with its own pdf",
     [("  const Vec3 m = sampleVisibleNormal(wo, u, alphaFromRoughness(conductor.roughness));",
       "  const Vec3 m = sampleGgxNormal(u, alphaFromRoughness(conductor.roughness));"),
      ("  return visibleNormalPdf(wo, h, alphaFromRoughness(conductor.roughness)) / (4.0f * std::abs(glm::dot(wo, h)));",
       "  const float alpha = alphaFromRoughness(conductor.roughness);\n  return ggxD(h, alpha) * h.z / (4.0f * std::abs(glm::dot(wo, h)));")]),
    ("spherical-caps", "visible normals by spherical caps (Dupuy and Benyoub 2023)",
     [("  // An orthonormal basis around v.\n  const float length2 = v.x * v.x + v.y * v.y;\n  const Vec3 t1 = length2 > 0.0f ? Vec3(-v.y, v.x, 0.0f) / std::sqrt(length2) : Vec3(1.0f, 0.0f, 0.0f);\n  const Vec3 t2 = glm::cross(v, t1);\n  // A point on the disk, squeezed onto the half of it v sees.\n  const float r = std::sqrt(u.x), phi = 2.0f * kPi * u.y;\n  const float p1 = r * std::cos(phi);\n  const float s = 0.5f * (1.0f + v.z);\n  const float p2 = (1.0f - s) * std::sqrt(std::max(0.0f, 1.0f - p1 * p1)) + s * r * std::sin(phi);\n  // Onto the hemisphere, then back to the ellipsoid configuration.\n  const Vec3 n = p1 * t1 + p2 * t2 + std::sqrt(std::max(0.0f, 1.0f - p1 * p1 - p2 * p2)) * v;",
       "  // A direction on the spherical cap below v, added to v.\n  const float phi = 2.0f * kPi * u.x;\n  const float z = (1.0f - u.y) * (1.0f + v.z) - v.z;\n  const float sinTheta = std::sqrt(std::clamp(1.0f - z * z, 0.0f, 1.0f));\n  const Vec3 n = Vec3(sinTheta * std::cos(phi), sinTheta * std::sin(phi), z) + v;")]),
    ("even-mixture", "the plastic's two lobes each sampled half the time",
     [("  return std::clamp(coat / (coat + base), 0.1f, 0.9f);", "  (void)coat, (void)base;\n  return 0.5f;")]),
]
