"""Task 2's seeded mutants and alternates: edits of its reference,
solutions/02-intersection/intersection.cpp, that tests/mutants/generate.py writes into
tests/mutants/02-intersection/ and tests/alternates/02-intersection/. A mutant is one
realistic mistake and must lose points in the task's suite; an alternate is
a correct solution written differently and must score full marks (CTest
label "validity"). Each entry: (name, description, [(old, new), ...]), old
a piece of the reference and new what replaces it. Not in the student
release: the pieces are the reference's own lines."""

MUTANTS = [
    ("absolute-det-epsilon", "|det| < 1e-6 rejected (an absolute epsilon)",
     [("if (det == 0.0f) return std::nullopt;", "if (std::abs(det) < 1e-6f) return std::nullopt;")]),
    ("non-watertight-edges", "edges with an edge function of exactly 0 rejected on both sides",
     [("if ((e0 < 0 || e1 < 0 || e2 < 0) && (e0 > 0 || e1 > 0 || e2 > 0)) return std::nullopt;",
       "if ((e0 <= 0 || e1 <= 0 || e2 <= 0) && (e0 >= 0 || e1 >= 0 || e2 >= 0)) return std::nullopt;")]),
    ("back-face-culling", "triangles seen from behind are not hit",
     [("if (det == 0.0f) return std::nullopt;", "if (det <= 0.0f) return std::nullopt;")]),
    ("swapped-barycentrics", "b1 and b2 swapped",
     [("return TriangleHit{tScaled * invDet, e1 * invDet, e2 * invDet};", "return TriangleHit{tScaled * invDet, e2 * invDet, e1 * invDet};")]),
    ("ignores-range-max", "hits beyond range.max accepted",
     [("if (det > 0.0f && (tScaled <= range.min * det || tScaled >= range.max * det)) return std::nullopt;",
       "if (det > 0.0f && tScaled <= range.min * det) return std::nullopt;"),
      ("if (det < 0.0f && (tScaled >= range.min * det || tScaled <= range.max * det)) return std::nullopt;",
       "if (det < 0.0f && tScaled >= range.min * det) return std::nullopt;")]),
    ("naive-discriminant", "b'^2 - a c' discriminant (cancellation for small far spheres)",
     [("const float discriminant = a * (radius * radius - glm::dot(perpendicular, perpendicular));",
       "(void)perpendicular;\n  const float discriminant = halfB * halfB - a * c;")]),
    ("negative-root", "the near root returned even when it is behind the origin",
     [("if (range.contains(t0)) return t0;", "if (t0 < range.max) return t0;")]),
    ("unnormalised-sphere-normal", "the sphere normal not normalised",
     [("const Vec3 outward = glm::normalize(ray.at(t) - center);", "const Vec3 outward = ray.at(t) - center;")]),
    ("sphere-not-reprojected", "the sphere's hit point left at o + t d, not re-projected (off the surface from afar)",
     [("s.point = center + radius * outward;  // re-project onto the sphere", "s.point = ray.at(t);\n  (void)radius;")]),
    ("flips-shading-normal", "the shading normal flipped instead of the geometric one",
     [("if (glm::dot(s.geometricNormal, s.shadingNormal) < 0.0f) s.geometricNormal = -s.geometricNormal;",
       "if (glm::dot(s.geometricNormal, s.shadingNormal) < 0.0f) s.shadingNormal = -s.shadingNormal;")]),
    ("normal-side-from-winding", "vertex normals interpolated, but the winding kept when they disagree",
     [("      if (glm::dot(s.geometricNormal, s.shadingNormal) < 0.0f) s.geometricNormal = -s.geometricNormal;",
       "      if (glm::dot(s.geometricNormal, s.shadingNormal) < 0.0f) s.shadingNormal = -s.shadingNormal;")]),
]

ALTERNATES = [
    ("moller-trumbore-double", "Moller-Trumbore in double precision with inclusive edges",
     [("namespace {\n\nint largestAxis(const Vec3& v) { return (v.x > v.y) ? (v.x > v.z ? 0 : 2) : (v.y > v.z ? 1 : 2); }\n\nVec3 permute(const Vec3& v, int x, int y, int z) { return {v[x], v[y], v[z]}; }\n\n}  // namespace\n", ""),
      ("  // Translate the vertices so the ray starts at the origin.\n  Vec3 a = p0 - ray.origin, b = p1 - ray.origin, c = p2 - ray.origin;\n\n  // Permute so the ray direction's largest component is z.\n  const int kz = largestAxis(glm::abs(ray.direction));\n  const int kx = (kz + 1) % 3, ky = (kx + 1) % 3;\n  const Vec3 d = permute(ray.direction, kx, ky, kz);\n  a = permute(a, kx, ky, kz);\n  b = permute(b, kx, ky, kz);\n  c = permute(c, kx, ky, kz);\n\n  // Shear x and y so the ray runs along +z; z is scaled later, only if needed.\n  const float shearX = -d.x / d.z, shearY = -d.y / d.z, shearZ = 1.0f / d.z;\n  a.x += shearX * a.z, a.y += shearY * a.z;\n  b.x += shearX * b.z, b.y += shearY * b.z;\n  c.x += shearX * c.z, c.y += shearY * c.z;\n\n  // 2D edge functions: twice the signed areas seen from the ray. A shared\n  // edge gives exactly opposite values in its two triangles.\n  float e0 = b.x * c.y - b.y * c.x;\n  float e1 = c.x * a.y - c.y * a.x;\n  float e2 = a.x * b.y - a.y * b.x;\n  if (e0 == 0.0f || e1 == 0.0f || e2 == 0.0f) {\n    // Exactly on an edge in float: decide in double so neighbours agree.\n    e0 = float(double(b.x) * c.y - double(b.y) * c.x);\n    e1 = float(double(c.x) * a.y - double(c.y) * a.x);\n    e2 = float(double(a.x) * b.y - double(a.y) * b.x);\n  }\n  if ((e0 < 0 || e1 < 0 || e2 < 0) && (e0 > 0 || e1 > 0 || e2 > 0)) return std::nullopt;\n  const float det = e0 + e1 + e2;\n  if (det == 0.0f) return std::nullopt;  // edge-on, or a degenerate projection\n\n  // Scaled hit distance, compared against the range without dividing.\n  a.z *= shearZ, b.z *= shearZ, c.z *= shearZ;\n  const float tScaled = e0 * a.z + e1 * b.z + e2 * c.z;\n  if (det < 0.0f && (tScaled >= range.min * det || tScaled <= range.max * det)) return std::nullopt;\n  if (det > 0.0f && (tScaled <= range.min * det || tScaled >= range.max * det)) return std::nullopt;\n\n  // A zero-area triangle has no normal: never report a hit on it.\n  const Vec3 n = glm::cross(p1 - p0, p2 - p0);\n  if (n.x == 0.0f && n.y == 0.0f && n.z == 0.0f) return std::nullopt;\n\n  const float invDet = 1.0f / det;\n  return TriangleHit{tScaled * invDet, e1 * invDet, e2 * invDet};\n",
       '  // Moller-Trumbore in double precision, edges inclusive, no epsilon.\n  using D = glm::dvec3;\n  const D o(ray.origin), d(ray.direction), v0(p0), e1 = D(p1) - v0, e2 = D(p2) - v0;\n  if (glm::length(glm::cross(e1, e2)) == 0.0) return std::nullopt;  // zero area\n  const D pv = glm::cross(d, e2);\n  const double det = glm::dot(e1, pv);\n  if (det == 0.0) return std::nullopt;\n  const D s = o - v0, qv = glm::cross(s, e1);\n  const double u = glm::dot(s, pv) / det, v = glm::dot(d, qv) / det;\n  if (u < 0.0 || v < 0.0 || u + v > 1.0) return std::nullopt;\n  const double t = glm::dot(e2, qv) / det;\n  if (!(t > range.min && t < range.max)) return std::nullopt;\n  return TriangleHit{float(t), float(u), float(v)};\n')]),
    ("double-precision-edges", "the edge functions always in double",
     [("  if (e0 == 0.0f || e1 == 0.0f || e2 == 0.0f) {", "  if (true) {")]),
    ("quadratic-in-double", "the ray-sphere quadratic solved in double precision",
     [("  const Vec3 f = ray.origin - center;\n  const Vec3& d = ray.direction;\n  const float a = glm::dot(d, d);\n  const float halfB = glm::dot(f, d);\n  const float c = glm::dot(f, f) - radius * radius;",
       "  const glm::dvec3 fd = glm::dvec3(ray.origin) - glm::dvec3(center), dd(ray.direction);\n  const double ad = glm::dot(dd, dd), hb = glm::dot(fd, dd), cd = glm::dot(fd, fd) - double(radius) * radius;\n  const Vec3 f(fd);\n  const Vec3& d = ray.direction;\n  const float a = float(ad), halfB = float(hb), c = float(cd);")]),
    ("point-from-edges", "the hit point as p0 + b1 (p1 - p0) + b2 (p2 - p0): the same precision class (within 3.2 ulps)",
     [("  s.point = b0 * p0 + hit.b1 * p1 + hit.b2 * p2;", "  s.point = p0 + hit.b1 * (p1 - p0) + hit.b2 * (p2 - p0);")]),
]
