"""Task @N@'s seeded mutants and alternates (tests/mutants/generate.py says what they are)."""

MUTANTS = [
    ("sine-not-cosine", "radius / d is sin(theta_max): its square root of 1 - ... left out",
     [("  return std::sqrt(1.0f - sin2ThetaMax);", "  return std::sqrt(sin2ThetaMax);")]),
    ("inside-is-zero", "a point inside the sphere gets a cone of half-angle 90 degrees, not the whole sphere",
     [("if (!(sin2ThetaMax < 1.0f)) return -1.0f;", "if (!(sin2ThetaMax < 1.0f)) return 0.0f;")]),
    ("theta-uniform", "theta uniform on [0, theta_max], not cos(theta): the directions crowd the axis",
     [("  const float cosTheta = 1.0f - u.x * (1.0f - cosThetaMax);",
       "  const float cosTheta = std::cos(u.x * std::acos(cosThetaMax));")]),
    ("pdf-without-two", "the cone's solid angle taken as pi (1 - cos theta_max)",
     [("Frame::fromNormal(axis).toWorld(local)), 1.0f / (2.0f * kPi * (1.0f - cosThetaMax))}",
       "Frame::fromNormal(axis).toWorld(local)), 1.0f / (kPi * (1.0f - cosThetaMax))}")]),
    ("axis-reversed", "the frame built around -axis: every cone points away from the light",
     [("  return {glm::normalize(Frame::fromNormal(axis).toWorld(local)),",
       "  return {glm::normalize(Frame::fromNormal(-axis).toWorld(local)),")]),
    ("pdf-outside-the-cone", "conePdf's test turned round: the density outside the cone, 0 inside",
     [("  return glm::dot(w, axis) >= cosThetaMax ? 1.0f / (2.0f * kPi * (1.0f - cosThetaMax)) : 0.0f;",
       "  return glm::dot(w, axis) <= cosThetaMax ? 1.0f / (2.0f * kPi * (1.0f - cosThetaMax)) : 0.0f;")]),
]

ALTERNATES = [
    ("cos-from-the-edge", "cos(theta) = cos theta_max + u.x (1 - cos theta_max): the other end of the same interval",
     [("  const float cosTheta = 1.0f - u.x * (1.0f - cosThetaMax);",
       "  const float cosTheta = cosThetaMax + u.x * (1.0f - cosThetaMax);")]),
    ("own-frame", "a frame of its own around the axis (a helper vector and two cross products)",
     [("  return {glm::normalize(Frame::fromNormal(axis).toWorld(local)),",
       "  const Vec3 helper = std::abs(axis.x) > 0.5f ? Vec3(0.0f, 1.0f, 0.0f) : Vec3(1.0f, 0.0f, 0.0f);\n"
       "  const Vec3 s = glm::normalize(glm::cross(helper, axis)), t = glm::cross(axis, s);\n"
       "  return {glm::normalize(s * local.x + t * local.y + axis * local.z),")]),
    ("distance-first", "the distance d first, then sin(theta_max) = radius / d",
     [("  const Vec3 toCenter = center - x;\n"
       "  const float sin2ThetaMax = radius * radius / glm::dot(toCenter, toCenter);",
       "  const float sinThetaMax = radius / glm::length(center - x);\n"
       "  const float sin2ThetaMax = sinThetaMax * sinThetaMax;")]),
]
