// Autograder suite for task 1 — camera rays. Tests run from basic to
// advanced; the first failure is usually the root cause. candidate::f(...)
// is the student's f, computed in the candidate process (calls.h).
#include "suite/doctest_strings.h"

#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "check.h"
#include "metamorphic.h"
#include "image_scenes.h"
#include "image_test.h"
#include "suite/grading.h"
#include "calls.h"

using namespace pathlab;
using namespace pathlab::test;

namespace {

Camera makeCamera(Point3 position, Point3 lookAt, Vec3 up, float vfov) {
  Camera c;
  c.position = position;
  c.lookAt = lookAt;
  c.up = up;
  c.vfovDegrees = vfov;
  return c;
}

// The expected direction through a raster point, in double precision, from
// the frame the camera must have when `up` is not parallel to the view.
DVec3 expectedDirection(const Camera& camera, Point2 raster, IVec2 resolution) {
  DVec3 forward = glm::normalize(DVec3(camera.lookAt) - DVec3(camera.position));
  DVec3 right = glm::normalize(glm::cross(forward, DVec3(camera.up)));
  DVec3 up = glm::cross(right, forward);
  double halfHeight = std::tan(double(camera.vfovDegrees) * std::numbers::pi / 360.0);
  double halfWidth = halfHeight * double(resolution.x) / double(resolution.y);
  double ndcX = 2.0 * raster.x / resolution.x - 1.0, ndcY = 1.0 - 2.0 * raster.y / resolution.y;
  return glm::normalize(forward + ndcX * halfWidth * right + ndcY * halfHeight * up);
}

// Tolerance: any reasonable float method lands within ~3e-6 of the exact
// direction (a basis and a sum: ~1e-7; inverse(projection * view) on a 4x4
// matrix: measured 2.2e-6); the smallest wrong answer the tests look for,
// half a pixel at 800 pixels across, is 7e-4. 1e-5 sits between with room.
void checkRay(const Camera& camera, Point2 raster, IVec2 resolution, double tolerance = 1e-5) {
  CameraBasis basis = candidate::cameraBasis(camera);
  Ray ray = candidate::generateCameraRay(camera, basis, raster, resolution);
  DVec3 expected = expectedDirection(camera, raster, resolution);
  CAPTURE(raster.x);
  CAPTURE(raster.y);
  CAPTURE(resolution.x);
  CAPTURE(resolution.y);
  CAPTURE(camera.vfovDegrees);
  INFO("expected direction " << str(Vec3(expected)) << ", got " << str(ray.direction));
  {
    HINT("the ray must start exactly at camera.position: an origin on the image plane, at the world origin, or "
         "moved along the direction fails here");
    CHECK(near(ray.origin, camera.position, 0.0f));
  }
  CHECK(glm::length(DVec3(ray.direction) - expected) <= tolerance);
}

std::array<Camera, 4> someCameras() {
  return {makeCamera({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 45),
          makeCamera({1, 2, 3}, {-2, 0.5f, 1}, {0, 1, 0}, 60),
          makeCamera({-5, 1, 0.5f}, {3, -1, 2}, {0.2f, 1, -0.1f}, 30),   // up not perpendicular
          makeCamera({0, 10, 0}, {0.3f, 0, 0.2f}, {0, 0, 1}, 90)};
}

void checkOrthonormal(const CameraBasis& b) {
  INFO("forward " << str(b.forward) << " right " << str(b.right) << " up " << str(b.up));
  REQUIRE(finite(b.forward));
  REQUIRE(finite(b.right));
  REQUIRE(finite(b.up));
  HINT("forward, right and up must each be unit length: normalise lookAt - position and the cross product that "
       "gives right (the fallback's too); a missing normalize(), or camera.up kept as the frame's up, fails here");
  CHECK(std::abs(glm::length(b.forward) - 1.0f) < 1e-5f);
  CHECK(std::abs(glm::length(b.right) - 1.0f) < 1e-5f);
  CHECK(std::abs(glm::length(b.up) - 1.0f) < 1e-5f);
  HINT("forward, right and up must be mutually perpendicular: camera.up need not be perpendicular to the view, so "
       "rebuild up' = right x forward instead of keeping it, and take right from a cross product with forward (a "
       "fixed axis as the fallback right is not perpendicular)");
  CHECK(std::abs(glm::dot(b.forward, b.right)) < 1e-5f);
  CHECK(std::abs(glm::dot(b.forward, b.up)) < 1e-5f);
  CHECK(std::abs(glm::dot(b.right, b.up)) < 1e-5f);
  // right = forward x up: a right-handed frame looking down its -z axis.
  HINT("the frame must be right-handed, right = forward x up': up' = cross(right, forward) in that order; up' = "
       "cross(forward, right), whatever order gave right, mirrors the frame and fails here");
  CHECK(near(glm::cross(b.forward, b.up), b.right, 1e-5f));
}

}  // namespace

TEST_CASE("T1.1 pixel sample: u = (0.5, 0.5) is the pixel centre (half-pixel offset)" *
          grading(2, "pixel (i, j) covers [i, i+1) x [j, j+1): its centre is (i + 0.5, j + 0.5); "
                     "return pixel + u")) {
  for (IVec2 pixel : {IVec2(0, 0), IVec2(3, 7), IVec2(799, 599), IVec2(1023, 0)}) {
    Point2 p = candidate::pixelSamplePosition(pixel, Vec2(0.5f));
    CAPTURE(pixel.x);
    CAPTURE(pixel.y);
    HINT("u = (0.5, 0.5) must land on the pixel centre (i + 0.5, j + 0.5), i the column and j the row: returning the "
         "corner (i, j), adding another 0.5 to pixel + u, or swapping x and y fails here");
    CHECK(p.x == doctest::Approx(pixel.x + 0.5f).epsilon(1e-7));
    CHECK(p.y == doctest::Approx(pixel.y + 0.5f).epsilon(1e-7));
  }
}

TEST_CASE("T1.1 pixel sample: u spreads samples uniformly over the whole pixel" *
          grading(3, "every u in [0,1)^2 must land inside the pixel, and equal areas of u must cover equal "
                     "areas of the pixel (no fixed centre, no scaling by 0.5)")) {
  // A 16 x 16 grid of u values must put exactly 16 samples in each of the
  // pixel's 4 x 4 sub-squares: deterministic, so no false failures.
  const IVec2 pixel{12, 34};
  int counts[4][4] = {};
  for (int i = 0; i < 16; ++i) {
    for (int j = 0; j < 16; ++j) {
      Vec2 u((float(i) + 0.5f) / 16.0f, (float(j) + 0.5f) / 16.0f);
      Point2 p = candidate::pixelSamplePosition(pixel, u) - Point2(pixel);
      CAPTURE(u.x);
      CAPTURE(u.y);
      HINT("every u in [0,1)^2 must land inside the pixel's square [i, i+1] x [j, j+1]: an offset added to pixel + u "
           "(such as another 0.5), or u scaled by more than 1, puts samples outside");
      REQUIRE(p.x >= 0.0f);
      REQUIRE(p.x <= 1.0f);
      REQUIRE(p.y >= 0.0f);
      REQUIRE(p.y <= 1.0f);
      counts[std::min(3, int(p.y * 4.0f))][std::min(3, int(p.x * 4.0f))]++;
    }
  }
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) {
      CAPTURE(r);
      CAPTURE(c);
      HINT("equal areas of u must cover equal areas of the pixel: a 16 x 16 grid of u must put 16 samples in each of "
           "the pixel's 4 x 4 sub-squares; a fixed centre, u scaled by 0.5, or a non-linear map of u (such as u * u) "
           "fails here");
      CHECK(counts[r][c] == 16);
    }
  // The extremes of u stay inside the pixel.
  for (Vec2 u : {Vec2(0.0f), Vec2(0.99999994f), Vec2(0.0f, 0.99999994f)}) {
    Point2 p = candidate::pixelSamplePosition(pixel, u);
    HINT("the extremes u = 0 and u just below 1 must stay inside pixel (12, 34), i.e. in [12, 13] x [34, 35]: an "
         "offset added to pixel + u, or a map of u that overshoots at its ends, fails here");
    CHECK(p.x >= 12.0f);
    CHECK(p.x <= 13.0f);
    CHECK(p.y >= 34.0f);
    CHECK(p.y <= 35.0f);
  }
}

TEST_CASE("T1.2 camera basis: orthonormal, right-handed, forward points at lookAt" *
          grading(3, "forward = normalize(lookAt - position); right = normalize(cross(forward, up)); "
                     "up = cross(right, forward) — normalise, and mind the order of the cross products; camera.up "
                     "may have any length: normalise it before judging the cross product's size")) {
  for (const Camera& camera : someCameras()) {
    CameraBasis b = candidate::cameraBasis(camera);
    HINT("forward, right and up must be finite (no NaN or inf) for ordinary cameras, with up not parallel to the "
         "view: a NaN comes from normalize() of a zero vector or from dividing by a zero length");
    checkOrthonormal(b);
    Vec3 forward = glm::normalize(camera.lookAt - camera.position);
    INFO("expected forward " << str(forward) << ", got " << str(b.forward));
    HINT("forward must be normalize(lookAt - position): the unit vector from the camera towards lookAt, not the "
         "reverse, not unnormalised");
    CHECK(near(b.forward, forward, 1e-5f));
    // The image's up agrees with the requested up, and the horizon is level.
    HINT("the frame's up must point the same way as camera.up: right = forward x up, then up' = right x forward; "
         "one of these cross products in the wrong order turns up' (and the image) upside down");
    CHECK(glm::dot(b.up, camera.up) > 0.0f);
    HINT("right must be perpendicular to camera.up (a level horizon): right = normalize(forward x up) with the "
         "camera's up; a fixed world up instead of camera.up, or the fallback taken when up is not parallel to the "
         "view, tilts it");
    CHECK(std::abs(glm::dot(b.right, glm::normalize(camera.up))) < 1e-5f);
    // up gives a direction, whatever its length.
    for (float length : {1e-6f, 1e6f}) {
      Camera scaled = camera;
      scaled.up = camera.up * length;
      CAPTURE(length);
      const CameraBasis s = candidate::cameraBasis(scaled);
      INFO("up scaled by " << length << ": right " << str(s.right) << " up " << str(s.up) << "; at length 1: right "
                           << str(b.right) << " up " << str(b.up));
      HINT("camera.up 1e-6 or 1e6 long must give the same right and up as at length 1: judge the cross product's "
           "size with up normalised first; a fixed threshold on |forward x up| with the raw up takes the fallback "
           "for a short up and changes the frame");
      CHECK(near(s.right, b.right, 1e-5f));
      CHECK(near(s.up, b.up, 1e-5f));
    }
  }
}

TEST_CASE("T1.2 camera basis: up parallel to the view direction still gives a finite orthonormal frame" *
          grading(2, "cross(forward, up) is zero when up is parallel to forward, and normalize() of it is "
                     "NaN: detect a tiny cross product and pick another vector perpendicular to forward")) {
  const Camera cameras[] = {
      makeCamera({0, 5, 0}, {0, 0, 0}, {0, 1, 0}, 45),    // looking straight down, up = -forward
      makeCamera({0, 0, 0}, {0, 3, 0}, {0, 1, 0}, 45),    // looking straight up, up = forward
      makeCamera({1, 1, 1}, {2, 2, 2}, {1, 1, 1}, 60),    // diagonal, up = forward
      makeCamera({0, 0, 0}, {0, 0, -1}, {0, 1e-9f, -1}, 45),  // parallel to within rounding
  };
  for (const Camera& camera : cameras) {
    CameraBasis b = candidate::cameraBasis(camera);
    HINT("with up parallel to the view, forward, right and up must still be finite: cross(forward, up) is zero "
         "there and normalize() of it is NaN, so detect a tiny cross product and use another vector perpendicular "
         "to forward");
    checkOrthonormal(b);
    HINT("forward must stay normalize(lookAt - position) when up is parallel to it: the fallback replaces the "
         "vector crossed with forward, never forward itself");
    CHECK(near(b.forward, glm::normalize(camera.lookAt - camera.position), 1e-5f));
    Ray ray = candidate::generateCameraRay(camera, b, Point2(0.0f), IVec2(64, 48));
    HINT("the ray through an image corner must be finite with this frame: a NaN comes from a basis whose vectors "
         "are not unit and perpendicular, or from generateCameraRay itself (normalize() of a zero vector, a "
         "division by zero)");
    CHECK(finite(ray.direction));
  }
}

TEST_CASE("T1.2 camera basis: the fallback works along every axis, near every axis, and when the cross product "
          "underflows" *
          grading(2, "when cross(forward, up) is tiny, cross forward with a vector that is never parallel to it "
                     "(the world axis least aligned with forward, or Duff et al.'s basis); test the length of the "
                     "cross product against a small threshold, not against exactly 0: a cross product of "
                     "1e-25 is not 0, but its squared length is, and normalize() of it is NaN")) {
  // Any perpendicular is right when up is parallel to the view (the roll is
  // then free): check only that the frame is finite, orthonormal,
  // right-handed and looks at lookAt.
  std::vector<Vec3> forwards;
  for (int axis = 0; axis < 3; ++axis)
    for (float sign : {1.0f, -1.0f}) {
      Vec3 f(0.0f);
      f[axis] = sign;
      forwards.push_back(f);
      // Slightly off the axis, towards the other two in either order: so
      // close (1e-30) that a fallback vector parallel to the axis gives a
      // cross product whose squared length underflows.
      for (float off : {1e-3f, 1e-30f})
        for (int order = 0; order < 2; ++order) {
          Vec3 near = f;
          near[(axis + 1 + order) % 3] = off;
          near[(axis + 2 - order) % 3] = -2.0f * off;
          forwards.push_back(near);
        }
    }
  Random random(11);
  for (int i = 0; i < 40; ++i) forwards.push_back(Vec3(random.unitVector()));
  for (Vec3 forward : forwards) {
    for (float scale : {1.0f, -3.0f, 1e-3f}) {  // up = forward, up = -forward, at other lengths
      // At the origin, so lookAt - position keeps the 1e-30 components.
      Camera camera = makeCamera({0, 0, 0}, 2.0f * forward, forward * scale, 50);
      CAPTURE(str(forward));
      CAPTURE(scale);
      CameraBasis b = candidate::cameraBasis(camera);
      HINT("with up = +-forward on or within 1e-30 of an axis, forward, right and up must be finite: the vector "
           "the fallback crosses with forward must never be (nearly) parallel to it, such as a fixed axis; take "
           "the world axis least aligned with forward, or Duff et al.'s basis");
      checkOrthonormal(b);
      HINT("forward must stay normalize(lookAt - position) when up is parallel to it: the fallback replaces the "
           "vector crossed with forward, never forward itself");
      CHECK(near(b.forward, glm::normalize(camera.lookAt - camera.position), 1e-5f));
    }
  }
  // Parallel but for a component of 1e-25: cross(forward, up) is about 1e-25
  // long, and its squared length underflows to 0.
  for (int axis = 0; axis < 3; ++axis) {
    Vec3 forward(0.0f), up(0.0f);
    forward[axis] = -1.0f;
    up[axis] = -1.0f;
    up[(axis + 1) % 3] = 1e-25f;
    Camera camera = makeCamera({0, 0, 0}, forward, up, 45);
    CAPTURE(axis);
    CameraBasis b = candidate::cameraBasis(camera);
    HINT("with up off forward by 1e-25, forward x up is about 1e-25 long and its squared length underflows to 0: "
         "test its length against a small threshold, not the vector against exactly 0, so the fallback is taken and "
         "the frame stays finite");
    checkOrthonormal(b);
    HINT("forward must stay normalize(lookAt - position) when up is parallel to it: the fallback replaces the "
         "vector crossed with forward, never forward itself");
    CHECK(near(b.forward, forward, 1e-6f));
    Ray ray = candidate::generateCameraRay(camera, b, Point2(3.0f, 5.0f), IVec2(64, 48));
    HINT("the ray through raster (3, 5) must be finite with this frame: a NaN comes from a basis whose vectors are "
         "not unit and perpendicular, or from generateCameraRay itself (normalize() of a zero vector, a division "
         "by zero)");
    CHECK(finite(ray.direction));
  }
}

TEST_CASE("T1.3 camera ray: the image centre looks straight along forward, from the camera position" *
          grading(2, "the ray starts at camera.position; NDC (0, 0) must give direction = forward")) {
  for (const Camera& camera : someCameras()) {
    for (IVec2 resolution : {IVec2(64, 64), IVec2(800, 600), IVec2(101, 37)}) {
      HINT("the image centre (W/2, H/2) must look exactly along forward: ndcX = 2x/W - 1 and ndcY = 1 - 2y/H are "
           "both 0 there; a missing -1, an extra half pixel, integer division, or a wrong forward from cameraBasis "
           "fails here");
      checkRay(camera, Point2(resolution) * 0.5f, resolution);
    }
  }
}

TEST_CASE("T1.3 camera ray: corners and edges of the image sit at the field of view's edges" *
          grading(3, "half-height = tan(vfov/2) with vfov in degrees (glm::radians), half-width = "
                     "aspect * half-height, ndcY = 1 - 2 y / height (raster y grows downwards)")) {
  const IVec2 resolution{320, 240};
  for (const Camera& camera : someCameras()) {
    for (Point2 raster : {Point2(0, 0), Point2(320, 0), Point2(0, 240), Point2(320, 240), Point2(160, 0),
                          Point2(0, 120), Point2(80.25f, 200.5f)}) {
      HINT("the corners and edges must look along the field of view's edges: half-height = tan(radians(vfov)/2), "
           "half-width = aspect * half-height, ndcY = 1 - 2y/H; vfov in degrees inside tan, vfov taken as the half "
           "angle, an unflipped y, a wrong right or up, or an unnormalised direction fails here");
      checkRay(camera, raster, resolution);
    }
  }
}

TEST_CASE("T1.3 camera ray: raster row 0 is the top of the image and column 0 the left" *
          grading(2, "raster y grows downwards: flip it (ndcY = 1 - 2 y / height); x grows to the right")) {
  Camera camera = makeCamera({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 50);
  CameraBasis basis = candidate::cameraBasis(camera);
  Ray top = candidate::generateCameraRay(camera, basis, {50.0f, 0.5f}, {100, 80});
  Ray bottom = candidate::generateCameraRay(camera, basis, {50.0f, 79.5f}, {100, 80});
  Ray left = candidate::generateCameraRay(camera, basis, {0.5f, 40.0f}, {100, 80});
  Ray right = candidate::generateCameraRay(camera, basis, {99.5f, 40.0f}, {100, 80});
  INFO("top " << str(top.direction) << " bottom " << str(bottom.direction));
  HINT("raster row 0 must look up (+y) and the last row down: raster y grows downwards, so ndcY = 1 - 2y/H; an "
       "unflipped y, or an up' pointing against camera.up, fails here");
  CHECK(top.direction.y > 0.1f);
  CHECK(bottom.direction.y < -0.1f);
  INFO("left " << str(left.direction) << " right " << str(right.direction));
  HINT("column 0 must look left (-x) and the last column right (+x): ndcX = 2x/W - 1 and right = forward x up; a "
       "flipped x, or right = up x forward, mirrors the image and fails here");
  CHECK(left.direction.x < -0.1f);
  CHECK(right.direction.x > 0.1f);
}

TEST_CASE("T1.3 camera ray: non-square images keep square pixels (aspect = width / height)" *
          grading(3, "scale the horizontal extent by aspect = width / height (as floats), never the "
                     "vertical one; vfov is the vertical field of view")) {
  Camera camera = makeCamera({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 40);
  for (IVec2 resolution : {IVec2(400, 100), IVec2(100, 400), IVec2(641, 479), IVec2(3, 2)}) {
    HINT("on non-square images the edge directions must match: half-width = aspect * half-height with aspect = "
         "W / H computed in floats, and vfov the vertical angle; integer division, aspect = H / W, or the aspect "
         "applied to the vertical extent fails here");
    for (Point2 raster : {Point2(0, 0), Point2(float(resolution.x), float(resolution.y) * 0.5f),
                          Point2(float(resolution.x) * 0.5f, float(resolution.y))}) {
      checkRay(camera, raster, resolution);
    }
    // One pixel step subtends the same angle across and down at the centre.
    CameraBasis basis = candidate::cameraBasis(camera);
    Point2 c = Point2(resolution) * 0.5f;
    Vec3 d0 = candidate::generateCameraRay(camera, basis, c, resolution).direction;
    Vec3 dx = candidate::generateCameraRay(camera, basis, c + Point2(1, 0), resolution).direction;
    Vec3 dy = candidate::generateCameraRay(camera, basis, c + Point2(0, 1), resolution).direction;
    CAPTURE(resolution.x);
    CAPTURE(resolution.y);
    HINT("one pixel step across and one step down from the centre must turn the ray by the same angle (square "
         "pixels): scale only the horizontal extent by aspect = W / H as floats; integer division or the aspect on "
         "the vertical extent fails here");
    CHECK(std::acos(std::min(1.0f, glm::dot(d0, dx))) ==
          doctest::Approx(std::acos(std::min(1.0f, glm::dot(d0, dy)))).epsilon(1e-2));
  }
}

TEST_CASE("T1.3 camera ray: extreme fields of view (0.001 and 179.9 degrees) stay finite and exact" *
          grading(2, "use tan(radians(vfov) / 2); keep the image plane at distance 1 and normalise the "
                     "direction last, so huge and tiny tangents both work")) {
  for (float vfov : {0.001f, 1.0f, 120.0f, 179.9f}) {
    Camera camera = makeCamera({1, 2, 3}, {1, 2, 0}, {0, 1, 0}, vfov);
    for (Point2 raster : {Point2(0, 0), Point2(200, 150), Point2(400, 300), Point2(37.5f, 280)}) {
      HINT("at vfov 0.001, 1, 120 and 179.9 degrees the direction must still match to 1e-5: half-height = "
           "tan(radians(vfov)/2) on an image plane at distance 1, normalised last; vfov in degrees inside tan, vfov "
           "as the half angle, or a method that loses float precision at tiny or huge tangents fails here");
      checkRay(camera, raster, {400, 300}, 1e-5);
    }
  }
}

TEST_CASE("T1.3 camera ray: half-pixel offset — pixel centres, not corners, are sampled at u = (0.5, 0.5)" *
          grading(2, "raster position = pixel + u already includes the half pixel: do not add 0.5 again "
                     "in generateCameraRay, and do not subtract it")) {
  // With an odd resolution the middle pixel's centre is the image centre.
  Camera camera = makeCamera({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 60);
  CameraBasis basis = candidate::cameraBasis(camera);
  Ray centre = candidate::generateCameraRay(camera, basis, candidate::pixelSamplePosition({2, 1}, Vec2(0.5f)), {5, 3});
  INFO("direction " << str(centre.direction));
  HINT("at u = (0.5, 0.5) the middle pixel of a 5 x 3 image must look straight along forward, and pixels (0, 0) "
       "and (3, 1) of a 4 x 2 image in mirrored directions: raster = pixel + u already holds the half pixel, so "
       "adding 0.5 again in generateCameraRay, or subtracting it, fails here");
  CHECK(near(centre.direction, Vec3(0, 0, -1), 1e-6f));
  // Symmetric pixels look symmetrically.
  Ray a = candidate::generateCameraRay(camera, basis, candidate::pixelSamplePosition({0, 0}, Vec2(0.5f)), {4, 2});
  Ray b = candidate::generateCameraRay(camera, basis, candidate::pixelSamplePosition({3, 1}, Vec2(0.5f)), {4, 2});
  INFO("pixel (0,0) " << str(a.direction) << " pixel (3,1) " << str(b.direction));
  CHECK(near(a.direction, Vec3(-b.direction.x, -b.direction.y, b.direction.z), 1e-6f));
  HINT("the ray through pixel (0, 0)'s centre, raster (0.5, 0.5), of a 4 x 2 image must match the expected "
       "direction: an extra or missing half pixel, or an error in the field of view or the aspect, fails here");
  checkRay(camera, candidate::pixelSamplePosition({0, 0}, Vec2(0.5f)), {4, 2});
}

// ---------------------------------------------------------------- images

namespace {

// A wide image of a scene that is different in every direction (colours
// left, right, up, down), from a camera rolled by its up vector: a flipped,
// stretched or rotated view changes the picture.
Scene asymmetricScene() {
  return sceneFromJson(R"({
    "camera": { "position": [0.3, 1.2, 4], "look_at": [0, 0.6, 0], "up": [0.25, 1, 0], "vfov": 35 },
    "render": { "width": 64, "height": 32, "spp": 32 },
    "materials": {
      "floor": { "albedo": [0.6, 0.6, 0.6] },
      "red":   { "albedo": [0.9, 0.2, 0.1] },
      "green": { "albedo": [0.2, 0.8, 0.2] },
      "blue":  { "albedo": [0.2, 0.3, 0.9] }
    },
    "meshes": [
      { "name": "floor", "material": "floor", "quad": { "corner": [-3, 0, 3], "edge_u": [6, 0, 0], "edge_v": [0, 0, -6] } },
      { "name": "green wall", "material": "green", "quad": { "corner": [0.4, 0.2, -1], "edge_u": [1.4, 0, 0], "edge_v": [0, 1.2, 0] } }
    ],
    "spheres": [ { "center": [-1.2, 1.1, -0.5], "radius": 0.45, "material": "red" },
                 { "center": [-0.3, 0.25, 0.8], "radius": 0.25, "material": "blue" } ],
    "environment": { "color": [0.4, 0.45, 0.5] }
  })", "asymmetric");
}

}  // namespace

TEST_CASE("T1.3 metamorphic: the camera moved, turned, resized or mirrored with its scene gives the moved rays" *
          grading(1, "a camera's rays depend on its own frame alone: nothing in them may assume the world's y is up, "
                     "the origin is near, or the scene has a size")) {
  // The relations (docs/metamorphic.md): a camera moved, turned and resized
  // gives each raster point the ray moved and turned alike (the origin
  // scaled and moved, the direction turned); a camera mirrored in x is a
  // left-handed view of the mirrored world, so raster x = W - x gives the
  // mirrored ray. Beside them, the truth: the unmoved rays (checkRay).
  const IVec2 resolution(64, 48);
  const std::vector<Point2> rasters = {{0.5f, 0.5f}, {63.5f, 0.5f}, {10.25f, 40.75f}, {32.0f, 24.0f}, {60.0f, 5.0f}};
  const std::vector<Similarity> relations = {
      {"1000 times smaller", 1e-3},
      {"turned and 1000 times larger", 1e3, rotationAbout({1, -2, 0.5}, 133)},
      {"turned and moved 1000 units away", 1.0, rotationAbout({0, 0, 1}, 90), {1e3, -400, 250}},
      {"mirrored in x", 1.0, mirrorX()}};
  for (const Camera& camera : someCameras()) {
    HINT("the relations below compare your rays with themselves, so they must first be right: each raster "
         "point's ray from camera.position through the image plane at distance 1");
    for (const Point2& raster : rasters) checkRay(camera, raster, resolution);
    const CameraBasis basis = candidate::cameraBasis(camera);
    for (const Similarity& t : relations) {
      Scene moved;
      moved.camera = camera;
      moved = transformed(moved, t);
      const CameraBasis movedBasis = candidate::cameraBasis(moved.camera);
      int differing = 0;
      for (const Point2& raster : rasters) {
        const Ray ray = candidate::generateCameraRay(camera, basis, raster, resolution);
        const Point2 seen = t.mirrors() ? Point2(float(resolution.x) - raster.x, raster.y) : raster;
        const Ray after = candidate::generateCameraRay(moved.camera, movedBasis, seen, resolution);
        const Ray expected = t.ray(ray);
        const float origin = 1e-6f * glm::length(expected.origin) + 1e-7f * float(t.scale);
        if (!near(after.origin, expected.origin, origin) || !near(after.direction, expected.direction, 2e-5f)) ++differing;
      }
      CAPTURE(t.name);
      INFO("camera at " << str(camera.position) << ": " << differing << " of " << rasters.size()
                        << " rays are not the moved rays");
      HINT("the rays change when the camera and its world are moved, turned, resized or mirrored together: the frame "
           "must come from lookAt - position and camera.up alone (right = forward x up), never from the world's axes, "
           "and the ray starts at camera.position whatever its size");
      CHECK(differing == 0);
    }
  }
}

TEST_CASE("T1.3 image: a wide, rolled view of an asymmetric scene matches the reference" *
          grading(3, "compare your picture with the reference (files named above): upside down means raster y is not "
                     "flipped, mirrored means right points the wrong way, squeezed means the aspect ratio; a "
                     "zoomed view means the field of view (vfov is in degrees, the full vertical angle)")) {
  checkImage({"01-camera-rays", "asymmetric", asymmetricScene(), {.integrator = Integrator::Preview}});
}
