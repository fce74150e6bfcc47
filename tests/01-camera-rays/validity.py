"""Task 1's seeded mutants and alternates (tests/mutants/generate.py says what they are)."""

def matrix_camera(view):
    """The edits that unproject NDC points through inverse(projection * view), as OpenGL does."""
    return [("#include <cmath>\n", "#include <cmath>\n\n#include <glm/gtc/matrix_transform.hpp>\n"),
            ("  // Image plane at distance 1: half-height tan(vfov/2), half-width aspect times that.\n"
             "  const float halfHeight = std::tan(glm::radians(camera.vfovDegrees) * 0.5f);\n"
             "  const float halfWidth = halfHeight * float(resolution.x) / float(resolution.y);\n"
             "  const Vec3 direction = basis.forward + (ndcX * halfWidth) * basis.right + (ndcY * halfHeight) * basis.up;\n",
             "  const float aspect = float(resolution.x) / float(resolution.y);\n"
             "  const glm::mat4 projection = glm::perspective(glm::radians(camera.vfovDegrees), aspect, 0.1f, 100.0f);\n"
             f"  const glm::mat4 view = {view};\n"
             "  const glm::mat4 inverse = glm::inverse(projection * view);\n"
             "  const glm::vec4 nearPoint = inverse * glm::vec4(ndcX, ndcY, -1.0f, 1.0f);\n"
             "  const glm::vec4 farPoint = inverse * glm::vec4(ndcX, ndcY, 1.0f, 1.0f);\n"
             "  const Vec3 direction = Vec3(farPoint) / farPoint.w - Vec3(nearPoint) / nearPoint.w;\n")]


MUTANTS = [
    ("half-pixel-offset", "samples shifted by half a pixel",
     [("return Point2(pixel) + u;", "return Point2(pixel) + u - Vec2(0.5f);")]),
    ("no-jitter", "every sample at the pixel centre",
     [("return Point2(pixel) + u;", "(void)u;\n  return Point2(pixel) + Vec2(0.5f);")]),
    ("swapped-aspect", "aspect ratio height / width",
     [("halfHeight * float(resolution.x) / float(resolution.y)", "halfHeight * float(resolution.y) / float(resolution.x)")]),
    ("y-not-flipped", "raster y not flipped: the image upside down",
     [("1.0f - 2.0f * raster.y / float(resolution.y)", "2.0f * raster.y / float(resolution.y) - 1.0f")]),
    ("full-fov-tangent", "tan(vfov) instead of tan(vfov / 2)",
     [("std::tan(glm::radians(camera.vfovDegrees) * 0.5f)", "std::tan(glm::radians(camera.vfovDegrees))")]),
    ("degrees-as-radians", "the field of view in degrees passed to tan",
     [("std::tan(glm::radians(camera.vfovDegrees) * 0.5f)", "std::tan(camera.vfovDegrees * 0.5f)")]),
    ("no-up-fallback", "no fallback when up is parallel to the view: NaN",
     [("if (glm::length(right) < 1e-4f) {", "if (false) {")]),
    ("matrix-camera-translated", "the ray from inverse(projection * view) with the view's translation and a near plane 0.1 away: right near the origin, directions off by 5e-3 rad (pixels) 5,000 units from it",
     matrix_camera('glm::lookAt(camera.position, camera.position + basis.forward, basis.up)')),
]

ALTERNATES = [
    ("mirrored-jitter", "pixel + (1 - u): another uniform map onto the pixel",
     [("return Point2(pixel) + u;", "return Point2(pixel) + (Vec2(1.0f) - u);")]),
    ("duff-fallback-frame", "the up fallback from Duff et al.'s orthonormal basis",
     [("    Vec3 a = glm::abs(basis.forward);\n    Vec3 axis = (a.x <= a.y && a.x <= a.z) ? Vec3(1, 0, 0) : (a.y <= a.z ? Vec3(0, 1, 0) : Vec3(0, 0, 1));\n    right = glm::cross(basis.forward, axis);",
       "    const Vec3& n = basis.forward;\n    const float sign = std::copysign(1.0f, n.z), a = -1.0f / (sign + n.z), b = n.x * n.y * a;\n    right = Vec3(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);")]),
    ("matrix-camera", "the ray from inverse(projection * view) applied to NDC points, as in OpenGL, the view turned but not moved (the ray starts at camera.position): its digits do not depend on where the camera is",
     matrix_camera('glm::lookAt(Vec3(0.0f), basis.forward, basis.up)')),
]
