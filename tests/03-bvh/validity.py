"""Task 3's seeded mutants and alternates (tests/mutants/generate.py says what they are)."""

MUTANTS = [
    ("first-hit-not-closest", "the traversal returns the first hit found",
     [("          closest = hit;\n          range.max = hit->t;  // from now on only closer hits count", "          return hit;")]),
    ("nan-unsafe-slab", "min/max that let a NaN through (rays on slab planes with -0)",
     [("const float near = (t0 < t1 || t0 != t0) ? t0 : t1;", "const float near = t0 < t1 ? t0 : t1;"),
      ("const float far = ((t0 > t1 || t0 != t0) ? t0 : t1) * kWidenExit;", "const float far = (t0 > t1 ? t0 : t1) * kWidenExit;")]),
    ("one-big-leaf", "no split: the root is one leaf",
     [("    if (count == 1) return false;", "    return false;")]),
    ("median-split", "object median split instead of SAH",
     [("const Split split = depth < kMedianSplitDepth ? bestSplit(node, centroidBounds, first, count) : Split{};",
       "const Split split{};\n    (void)&Builder::bestSplit;")]),
    ("any-hit-ignores-range", "shadow rays count hits beyond the light",
     [("        if (geometry.intersect(slot, ray, range)) return true;", "        if (geometry.intersect(slot, ray, Interval{range.min, kInfinity})) return true;")]),
    ("no-stats", "traversal statistics not counted",
     [("        if (stats) ++stats->primitiveTests;\n        if (geometry.intersect(slot, ray, range)) return true;",
       "        if (geometry.intersect(slot, ray, range)) return true;")]),
]

ALTERNATES = [
    ("eight-bins", "SAH with 8 bins", [("constexpr int kBins = 16;", "constexpr int kBins = 8;")]),
    ("thirty-two-bins", "SAH with 32 bins", [("constexpr int kBins = 16;", "constexpr int kBins = 32;")]),
    ("longest-axis-only", "SAH along the centroids' longest axis only (Wald 2007 bins one axis)",
     [("      if (!(extent[axis] > 0.0f)) continue;  // all centroids equal along this axis",
       "      if (!(extent[axis] > 0.0f) || axis != centroidBounds.largestAxis()) continue;  // the longest axis only")]),
    ("unordered-traversal", "closest hit without visiting the nearer child first",
     [("        if (*tFar < *tNear) std::swap(near, far), std::swap(tNear, tFar);", "")]
     if False else [("      if (tFar < tNear) std::swap(near, far), std::swap(tNear, tFar);\n", "      if (tNear == kInfinity) std::swap(near, far), std::swap(tNear, tFar);\n")]),
    ("range-not-shrunk", "closest hit keeps the nearer hit without shrinking range.max: correct, only slower (the handout says so)",
     [("        if (auto hit = geometry.intersect(slot, ray, range)) {\n          closest = hit;\n          range.max = hit->t;  // from now on only closer hits count\n        }",
       "        if (auto hit = geometry.intersect(slot, ray, range); hit && (!closest || hit->t < closest->t)) closest = hit;")]),
]
