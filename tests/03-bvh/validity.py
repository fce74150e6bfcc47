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
    ("edge-sum-cost", "SAH that costs boxes by the sum of their edges, not their surface area: a valid tree, "
     "worse where long thin boxes compete with compact ones",
     [("    const float parentArea = node.bounds.surfaceArea();",
       "    const auto edgeSum = [](const Aabb& b) { const Vec3 e = b.extent(); return e.x + e.y + e.z; };\n"
       "    const float parentArea = edgeSum(node.bounds);"),
      ("        rightArea[b] = box.surfaceArea();", "        rightArea[b] = edgeSum(box);"),
      ("(box.surfaceArea() * float(n) + rightArea[b + 1]", "(edgeSum(box) * float(n) + rightArea[b + 1]")]),
    ("x-axis-only", "SAH along x alone, whatever the mesh's shape: a valid tree, good when the mesh lies along x",
     [("      if (!(extent[axis] > 0.0f)) continue;  // all centroids equal along this axis",
       "      if (!(extent[axis] > 0.0f) || axis != 0) continue;  // x alone")]),
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
    ("box-tested-when-reached", "both traversals test a node's box when they reach it, children going on the stack "
     "untested, and count every node reached as visited, its box missed or not: the other way to count, as correct",
     [("  if (stats) ++stats->boxTests;\n  if (!intersectBox(bvh.nodes[0].bounds, ray, inverseDirection, range)) return std::nullopt;\n"
       "  // A child's entry t, +inf for a miss: one number to compare and to stack.\n"
       "  auto entry = [&](uint32_t child) {\n"
       "    return intersectBox(bvh.nodes[child].bounds, ray, inverseDirection, range).value_or(kInfinity);\n  };\n", ""),
      ("    if (stats) ++stats->nodesVisited;\n    if (node.isLeaf()) {\n"
       "      for (uint32_t slot = node.leftOrFirst; slot < node.leftOrFirst + node.count; ++slot) {\n"
       "        if (stats) ++stats->primitiveTests;\n        if (auto hit",
       "    if (stats) ++stats->nodesVisited, ++stats->boxTests;  // every node reached, its box tested now\n"
       "    if (!intersectBox(node.bounds, ray, inverseDirection, range)) {\n      // missed: on to the next pending node\n"
       "    } else if (node.isLeaf()) {\n"
       "      for (uint32_t slot = node.leftOrFirst; slot < node.leftOrFirst + node.count; ++slot) {\n"
       "        if (stats) ++stats->primitiveTests;\n        if (auto hit"),
      ("      // Test both children; go to the nearer, keep the farther for later.\n"
       "      uint32_t near = node.leftOrFirst, far = near + 1;\n"
       "      float tNear = entry(near), tFar = entry(far);\n"
       "      if (stats) stats->boxTests += 2;\n"
       "      if (tFar < tNear) std::swap(near, far), std::swap(tNear, tFar);\n"
       "      if (tNear != kInfinity) {\n"
       "        if (tFar != kInfinity) stack[size++] = {far, tFar};\n"
       "        index = near;\n        continue;\n      }\n",
       "      // Both children untested: the right one kept for later (its box tested when popped), the left one next.\n"
       "      stack[size++] = {node.leftOrFirst + 1, range.min};\n"
       "      index = node.leftOrFirst;\n      continue;\n"),
      ("  if (stats) ++stats->boxTests;\n  if (!intersectBox(bvh.nodes[0].bounds, ray, inverseDirection, range)) return false;\n", ""),
      ("    if (stats) ++stats->nodesVisited;\n    if (node.isLeaf()) {\n",
       "    if (stats) ++stats->nodesVisited, ++stats->boxTests;  // every node reached, its box tested now\n"
       "    if (!intersectBox(node.bounds, ray, inverseDirection, range)) {\n      // missed: on to the next pending node\n"
       "    } else if (node.isLeaf()) {\n"),
      ("      const uint32_t left = node.leftOrFirst;\n"
       "      const bool hitLeft = intersectBox(bvh.nodes[left].bounds, ray, inverseDirection, range).has_value();\n"
       "      const bool hitRight = intersectBox(bvh.nodes[left + 1].bounds, ray, inverseDirection, range).has_value();\n"
       "      if (stats) stats->boxTests += 2;\n"
       "      if (hitLeft) {\n        if (hitRight) stack[size++] = left + 1;\n        index = left;\n        continue;\n      }\n"
       "      if (hitRight) {\n        index = left + 1;\n        continue;\n      }\n",
       "      // Both children untested: the right one kept for later (its box tested when popped), the left one next.\n"
       "      stack[size++] = node.leftOrFirst + 1;\n"
       "      index = node.leftOrFirst;\n      continue;\n")]),
]
