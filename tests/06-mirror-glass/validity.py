"""Task 6's seeded mutants and alternates (tests/mutants/generate.py says what they are)."""

MUTANTS = [
    ("no-eta-flip", "the index ratio not flipped when leaving the glass",
     [("const float eta = entering ? 1.0f / ior : ior;", "const float eta = 1.0f / ior;\n  (void)entering;")]),
    ("tir-ignored", "no total internal reflection check",
     [("  if (sin2T >= 1.0f) return std::nullopt;  // total internal reflection\n", "")]),
    ("r0-not-squared", "Schlick's R0 not squared",
     [("  const float f0 = r0 * r0;", "  const float f0 = std::abs(r0);")]),
    ("ignores-transmittance", "glass transmits white whatever its transmittance colour",
     [("  s.f = transmittance * ((1.0f - fresnel) * (nFrom * nFrom) / (nTo * nTo)) / std::abs(s.wi.z);",
       "  s.f = Color(1.0f) * ((1.0f - fresnel) * (nFrom * nFrom) / (nTo * nTo)) / std::abs(s.wi.z);\n  (void)transmittance;")]),
    ("fresnel-weight", "the reflected choice weighted by F instead of F / F",
     [("    s.f = reflectance * fresnel / std::abs(s.wi.z);  // weight f |cos| / pdf = reflectance",
       "    s.f = reflectance * fresnel * fresnel / std::abs(s.wi.z);")]),
    ("mirror-not-delta", "the mirror sample not marked delta",
     [("  s.pdf = 1.0f;\n  s.isDelta = true;\n  return s;\n}\n\nBsdfSample sampleGlass", "  s.pdf = 1.0f;\n  s.isDelta = false;\n  return s;\n}\n\nBsdfSample sampleGlass")]),
    ("delta-f-without-cosine", "the mirror's f is the reflectance, without 1 / |cos theta| (weight R cos)",
     [("  s.f = reflectance / std::abs(s.wi.z);\n  s.pdf = 1.0f;\n  s.isDelta = true;", "  s.f = reflectance;\n  s.pdf = 1.0f;\n  s.isDelta = true;")]),
    ("inverted-radiance-scaling", "(n_t / n_o)^2 instead of (n_o / n_t)^2 across the boundary",
     [("s.f = transmittance * ((1.0f - fresnel) * (nFrom * nFrom) / (nTo * nTo))", "s.f = transmittance * ((1.0f - fresnel) * (nTo * nTo) / (nFrom * nFrom))")]),
]

ALTERNATES = [
    ("exact-fresnel", "the exact dielectric Fresnel equations instead of Schlick (the handout allows it)",
     [("  const float fresnel = ior == 1.0f ? 0.0f : schlickFresnel(cosOutside, ior);",
       "  const float cosInside = std::sqrt(std::max(0.0f, 1.0f - (1.0f - cosOutside * cosOutside) / (ior * ior)));\n"
       "  const float rs = (cosOutside - ior * cosInside) / (cosOutside + ior * cosInside);\n"
       "  const float rp = (cosInside - ior * cosOutside) / (cosInside + ior * cosOutside);\n"
       "  const float fresnel = 0.5f * (rs * rs + rp * rp);")]),
    ("ior-one-in-schlick", "F = 0 for ior = 1 inside schlickFresnel rather than in sampleGlass",
     [("  const float r0 = (1.0f - ior) / (1.0f + ior);", "  if (ior == 1.0f) return 0.0f;  // no interface\n  const float r0 = (1.0f - ior) / (1.0f + ior);"),
      ("  const float fresnel = ior == 1.0f ? 0.0f : schlickFresnel(cosOutside, ior);", "  const float fresnel = schlickFresnel(cosOutside, ior);")]),
]
