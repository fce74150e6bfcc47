#include "embree_scene.h"

#include <embree3/rtcore.h>

#include <chrono>
#include <cstring>
#include <string>

#include "util/error.h"

namespace pathlab::bench {

namespace {
// A new geometry of `type`; an Embree built without it gives none.
RTCGeometry newGeometry(RTCDevice device, RTCGeometryType type, const char* what) {
  RTCGeometry geometry = rtcNewGeometry(device, type);
  if (!geometry) throw Error(std::string("Embree: this build of Embree has no ") + what);
  return geometry;
}
}  // namespace

struct EmbreeScene::Handles {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
};

EmbreeScene::EmbreeScene(const TriangleMesh& mesh, int buildThreads) : handles_(std::make_unique<Handles>()) {
  Scene scene;
  scene.meshes.push_back(mesh);
  build(scene, buildThreads);
}

EmbreeScene::EmbreeScene(const Scene& scene, int buildThreads) : handles_(std::make_unique<Handles>()) {
  build(scene, buildThreads);
}

void EmbreeScene::build(const Scene& scene, int buildThreads) {
  const std::string config = "threads=" + std::to_string(buildThreads);
  handles_->device = rtcNewDevice(config.c_str());
  if (!handles_->device) throw Error("Embree: cannot create a device");
  const auto start = std::chrono::steady_clock::now();
  handles_->scene = rtcNewScene(handles_->device);
  // Geometry IDs in attach order: the meshes, then the spheres, as the
  // scene numbers its primitives (all triangles, then all spheres).
  uint32_t primitive = 0;
  for (const TriangleMesh& mesh : scene.meshes) {
    if (mesh.triangles.empty()) continue;
    RTCGeometry geometry = newGeometry(handles_->device, RTC_GEOMETRY_TYPE_TRIANGLE, "triangles");
    // rtcSetNewGeometryBuffer pads the allocation as Embree's SIMD loads need.
    auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0,
                                                                  RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                                                  mesh.positions.size()));
    std::memcpy(vertices, mesh.positions.data(), mesh.positions.size() * 3 * sizeof(float));
    auto* indices = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0,
                                                                   RTC_FORMAT_UINT3, 3 * sizeof(uint32_t),
                                                                   mesh.triangles.size()));
    std::memcpy(indices, mesh.triangles.data(), mesh.triangles.size() * 3 * sizeof(uint32_t));
    rtcCommitGeometry(geometry);
    firstPrimitive_.push_back(primitive);
    rtcAttachGeometryByID(handles_->scene, geometry, uint32_t(firstPrimitive_.size() - 1));
    rtcReleaseGeometry(geometry);
    primitive += uint32_t(mesh.triangles.size());
  }
  if (!scene.spheres.empty()) {
    RTCGeometry geometry = newGeometry(handles_->device, RTC_GEOMETRY_TYPE_SPHERE_POINT, "sphere points");
    auto* points = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4,
                                                                4 * sizeof(float), scene.spheres.size()));
    for (size_t i = 0; i < scene.spheres.size(); ++i) {
      const Sphere& sphere = scene.spheres[i];
      points[4 * i] = sphere.center.x, points[4 * i + 1] = sphere.center.y, points[4 * i + 2] = sphere.center.z;
      points[4 * i + 3] = sphere.radius;
    }
    rtcCommitGeometry(geometry);
    sphereGeometry_ = uint32_t(firstPrimitive_.size());
    firstPrimitive_.push_back(primitive);
    rtcAttachGeometryByID(handles_->scene, geometry, sphereGeometry_);
    rtcReleaseGeometry(geometry);
  }
  rtcCommitScene(handles_->scene);
  buildSeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

EmbreeScene::~EmbreeScene() {
  if (handles_->scene) rtcReleaseScene(handles_->scene);
  if (handles_->device) rtcReleaseDevice(handles_->device);
}

std::optional<PrimitiveHit> EmbreeScene::intersect(const Ray& ray, Interval range) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rh{};
  rh.ray.org_x = ray.origin.x, rh.ray.org_y = ray.origin.y, rh.ray.org_z = ray.origin.z;
  rh.ray.dir_x = ray.direction.x, rh.ray.dir_y = ray.direction.y, rh.ray.dir_z = ray.direction.z;
  rh.ray.tnear = range.min;
  rh.ray.tfar = range.max;
  rh.ray.mask = 0xffffffffu;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(handles_->scene, &context, &rh);
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
  const uint32_t primitive = firstPrimitive_[rh.hit.geomID] + rh.hit.primID;
  if (rh.hit.geomID == sphereGeometry_) return PrimitiveHit{rh.ray.tfar, 0.0f, 0.0f, primitive};
  return PrimitiveHit{rh.ray.tfar, rh.hit.u, rh.hit.v, primitive};
}

bool EmbreeScene::occluded(const Ray& ray, Interval range) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay r{};
  r.org_x = ray.origin.x, r.org_y = ray.origin.y, r.org_z = ray.origin.z;
  r.dir_x = ray.direction.x, r.dir_y = ray.direction.y, r.dir_z = ray.direction.z;
  r.tnear = range.min;
  r.tfar = range.max;
  r.mask = 0xffffffffu;
  rtcOccluded1(handles_->scene, &context, &r);
  return r.tfar < 0.0f;  // Embree sets tfar to -inf on occlusion
}

}  // namespace pathlab::bench
