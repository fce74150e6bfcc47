"""Task 10's seeded mutants and alternates (tests/mutants/generate.py says what they are)."""

REF_DISK = """  const Vec2 offset = 2.0f * u - Vec2(1.0f);
  if (offset.x == 0.0f && offset.y == 0.0f) return Point2(0.0f);
  float r, phi;
  if (std::abs(offset.x) > std::abs(offset.y)) {
    r = offset.x;
    phi = 0.25f * kPi * (offset.y / offset.x);
  } else {
    r = offset.y;
    phi = 0.5f * kPi - 0.25f * kPi * (offset.x / offset.y);
  }
  return r * Point2(std::cos(phi), std::sin(phi));"""  # the reference's concentric map (task 10)

MUTANTS = [
    ("origin-moved-not-reaimed", "the ray starts on the lens but keeps the pinhole's direction",
     [("return Ray{origin, glm::normalize(focus - origin)};", "(void)focus;\n  return Ray{origin, pinholeRay.direction};")]),
    ("focus-along-ray", "the focal distance measured along each ray: a sphere of focus",
     [("const float t = camera.focalDistance / glm::dot(pinholeRay.direction, basis.forward);",
       "const float t = camera.focalDistance;")]),
    ("radius-uniform", "the polar map with r = u, not sqrt(u): lens points crowd the centre",
     [(REF_DISK, "  const float r = u.x, phi = 2.0f * kPi * u.y;\n  return r * Point2(std::cos(phi), std::sin(phi));")]),
    ("lens-in-camera-space", "the lens point (x, y, 0) added in the world's axes, not the camera's",
     [("const Point3 origin = camera.position + disk.x * basis.right + disk.y * basis.up;",
       "const Point3 origin = camera.position + Vec3(disk.x, disk.y, 0.0f);")]),
    ("aperture-as-diameter", "the aperture taken as the lens's diameter: half the blur",
     [("const Point2 disk = camera.apertureRadius * sampleUnitDisk(uLens);",
       "const Point2 disk = 0.5f * camera.apertureRadius * sampleUnitDisk(uLens);")]),
    ("aperture-ignored", "the unit disk used as the lens, whatever the aperture",
     [("const Point2 disk = camera.apertureRadius * sampleUnitDisk(uLens);", "const Point2 disk = sampleUnitDisk(uLens);")]),
    ("half-turn", "the polar map with phi = pi u: half the disk",
     [(REF_DISK, "  const float r = std::sqrt(u.x), phi = kPi * u.y;\n  return r * Point2(std::cos(phi), std::sin(phi));")]),
    ("no-centre-check", "the concentric map without its u = (0.5, 0.5) case: 0 / 0 at the centre",
     [("  if (offset.x == 0.0f && offset.y == 0.0f) return Point2(0.0f);\n", "")]),
    ("unnormalised-direction", "the direction to the point in focus not normalised",
     [("return Ray{origin, glm::normalize(focus - origin)};", "return Ray{origin, focus - origin};")]),
    ("lens-along-forward", "the lens spanned by right and forward: tilted into the view",
     [("const Point3 origin = camera.position + disk.x * basis.right + disk.y * basis.up;",
       "const Point3 origin = camera.position + disk.x * basis.right + disk.y * basis.forward;")]),
    ("focus-from-lens-point", "the point in focus found along the pinhole's direction from the lens point",
     [("  const Point3 focus = pinholeRay.origin + t * pinholeRay.direction;\n", ""),
      ("return Ray{origin, glm::normalize(focus - origin)};",
       "const Point3 focus = origin + t * pinholeRay.direction;\n  return Ray{origin, glm::normalize(focus - origin)};")]),
]

ALTERNATES = [
    ("polar-disk", "the polar map r = sqrt(u.x), phi = 2 pi u.y",
     [(REF_DISK, "  const float r = std::sqrt(u.x), phi = 2.0f * kPi * u.y;\n  return r * Point2(std::cos(phi), std::sin(phi));")]),
    ("polar-swapped-lens-flipped", "the polar map with u.y as the radius, the disk laid on (up, -right)",
     [(REF_DISK, "  const float r = std::sqrt(u.y), phi = 2.0f * kPi * u.x;\n  return r * Point2(std::cos(phi), std::sin(phi));"),
      ("const Point3 origin = camera.position + disk.x * basis.right + disk.y * basis.up;",
       "const Point3 origin = camera.position + disk.x * basis.up - disk.y * basis.right;")]),
    ("camera-space-lens", "the ray built in the camera's frame (x right, y up, z forward), then turned into the world's",
     [("  const float t = camera.focalDistance / glm::dot(pinholeRay.direction, basis.forward);\n"
       "  const Point3 focus = pinholeRay.origin + t * pinholeRay.direction;\n", ""),
      ("  const Point3 origin = camera.position + disk.x * basis.right + disk.y * basis.up;\n"
       "  return Ray{origin, glm::normalize(focus - origin)};",
       "  const glm::mat3 worldFromCamera(basis.right, basis.up, basis.forward);\n"
       "  const Vec3 d = glm::transpose(worldFromCamera) * pinholeRay.direction;\n"
       "  const Vec3 focus = d * (camera.focalDistance / d.z), lens(disk.x, disk.y, 0.0f);\n"
       "  return Ray{camera.position + worldFromCamera * lens, glm::normalize(worldFromCamera * (focus - lens))};")]),
]
