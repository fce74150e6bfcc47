"""Task @N@'s seeded mutants and alternates (tests/mutants/generate.py says what they are)."""

MUTANTS = [
    ("slices-uniform", "s = u.x, not sqrt(u.x): every slice of the triangle gets the same share",
     [("const float s = std::sqrt(u.x);", "const float s = u.x;")]),
]

ALTERNATES = [
    ("folded-square", "u itself, folded back across the diagonal when u.x + u.y > 1",
     [("  // Slices x = 1 - s of length s: s has density 2s, so s = sqrt(u.x).\n"
       "  const float s = std::sqrt(u.x);\n"
       "  return Point2(1.0f - s, s * u.y);",
       "  // The square folded along its diagonal: each half maps onto the triangle once.\n"
       "  return u.x + u.y > 1.0f ? Point2(1.0f - u.x, 1.0f - u.y) : Point2(u.x, u.y);")]),
]
