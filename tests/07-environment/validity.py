"""Task 7's seeded mutants and alternates (tests/mutants/generate.py says what they are)."""

MUTANTS = [
    ("pdf-without-sin-theta", "the solid-angle pdf without the sin(theta) Jacobian",
     [("  return EnvironmentSample{equirectToDirection(uv), pdfUv / (2.0f * kPi * kPi * sinTheta)};",
       "  return EnvironmentSample{equirectToDirection(uv), pdfUv / (2.0f * kPi * kPi)};"),
      ("  return pdfUv / (2.0f * kPi * kPi * sinTheta);\n}", "  return pdfUv / (2.0f * kPi * kPi);\n}")]),
    ("no-seam-wrap", "columns clamped instead of wrapped at the u seam",
     [("  const int x0 = (int(x0f) % map.width + map.width) % map.width;  // wraps at the u seam\n  const int x1 = (x0 + 1) % map.width;",
       "  const int x0 = std::clamp(int(x0f), 0, map.width - 1);\n  const int x1 = std::min(x0 + 1, map.width - 1);")]),
    ("cdf-off-by-one", "the row one past the one the CDF chose",
     [("  const int j = findInterval(d.marginalCdf.data(), d.height, u.y);", "  const int j = std::min(findInterval(d.marginalCdf.data(), d.height, u.y) + 1, d.height - 1);")]),
    ("lookup-half-pixel", "bilinear lookup without the half-pixel offset",
     [("const float x = uv.x * float(map.width) - 0.5f, y = uv.y * float(map.height) - 0.5f;", "const float x = uv.x * float(map.width), y = uv.y * float(map.height);")]),
    ("distribution-ignores-map", "pixel weights sin(theta) alone, the map's luminance ignored: a distribution of "
     "the sphere's rows, not of the light (consistent with its own pdf, so a test of the samples against the "
     "candidate's own pdf passes it)",
     [("      const double weight = std::max(0.0, double(luminance(map.at(i, j)))) * sinTheta;",
       "      const double weight = sinTheta;")]),
    ("acos-theta", "theta = acos(y), as the handout once said: near a pole y rounds to 1, and a direction's pdf "
     "disagrees with its sample's (0 within 3.45e-4 rad)",
     [("  // Not acos(y): near a pole y = cos(theta) rounds to 1 and theta is lost.\n"
       "  const float theta = std::atan2(std::sqrt(direction.x * direction.x + direction.z * direction.z), direction.y);",
       "  const float theta = std::acos(std::clamp(direction.y, -1.0f, 1.0f));")]),
    ("hemisphere-not-sphere", "uniform 'sphere' samples only one hemisphere",
     [("  const float z = 1.0f - 2.0f * u.x;\n  const float r = std::sqrt(std::max(0.0f, 1.0f - z * z)), phi = 2.0f * kPi * u.y;\n  return {r * std::cos(phi), r * std::sin(phi), z};",
       "  const float z = u.x;\n  const float r = std::sqrt(std::max(0.0f, 1.0f - z * z)), phi = 2.0f * kPi * u.y;\n  return {r * std::cos(phi), r * std::sin(phi), z};")]),
]

ALTERNATES = [
    ("weights-without-sin-theta", "pixel weights without sin(theta): correct, only noisier (the handout says so)",
     [("    const double sinTheta = std::sin(std::numbers::pi * (j + 0.5) / map.height);", "    const double sinTheta = 1.0;")]),
    ("seam-wraps-to-zero", "a u that rounds to 1 at the seam wrapped to 0 (u is periodic: the same meridian)",
     [("  return {std::min(phi / (2.0f * kPi), 0x1.fffffep-1f), theta / kPi};",
       "  const float u = phi / (2.0f * kPi);\n  return {u < 1.0f ? u : 0.0f, theta / kPi};")]),
    ("linear-search", "CDF inversion by linear search",
     [("  const float* it = std::upper_bound(cdf, cdf + n + 1, x);\n  int i = std::clamp(int(it - cdf) - 1, 0, n - 1);",
       "  int i = 0;\n  while (i + 1 < n && cdf[i + 1] <= x) ++i;")]),
]
