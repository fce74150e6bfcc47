// The bytes that cross between the judge and the candidate: every argument
// and result of a remote call, written field by field in native byte order
// (both processes run on the same machine).
//
// The judge decodes what a hostile candidate sends, so decoding never
// trusts a size: a count is checked against the bytes that are really there,
// at the least size each element takes on the wire, before anything is
// allocated; booleans must be 0 or 1, an image's pixel count must match its
// size, and a message must be consumed exactly. What an answer must hold to
// match its request (its lengths, its image size) is checked as it is read,
// by the call's shape (shape.h).
#pragma once

#include <cstdint>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include "core/bsdf.h"
#include "core/camera.h"
#include "core/hit.h"
#include "core/lights.h"
#include "core/scene.h"
#include "tasks/adaptive_sampling.h"
#include "tasks/bvh.h"
#include "tasks/camera_rays.h"
#include "tasks/environment.h"
#include "util/image.h"

namespace pathlab::wire {

// A message that does not decode: the other side sent something malformed.
class WireError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class Writer {
 public:
  void raw(const void* data, size_t size) { bytes_.append(static_cast<const char*>(data), size); }
  template <class T>
  void put(const T& value);
  std::string& bytes() { return bytes_; }

 private:
  std::string bytes_;
};

class Reader {
 public:
  Reader(const char* data, size_t size) : at_(data), end_(data + size) {}
  explicit Reader(const std::string& bytes) : Reader(bytes.data(), bytes.size()) {}

  void raw(void* out, size_t size) {
    if (size > remaining()) throw WireError("message ends early");
    if (size == 0) return;  // an empty vector's data() may be null, which memcpy must not see
    std::memcpy(out, at_, size);
    at_ += size;
  }
  // A count of elements that each take at least `minimumSize` bytes: larger
  // than what is left of the message means the message lies.
  size_t count(size_t minimumSize) {
    uint64_t n = 0;
    raw(&n, sizeof n);
    if (minimumSize > 0 && n > remaining() / minimumSize) throw WireError("count larger than the message");
    return size_t(n);
  }
  // A count that must be exactly `expected` (the request says how many).
  void expectCount(size_t expected, const char* what) {
    uint64_t n = 0;
    raw(&n, sizeof n);
    if (n != expected) {
      throw WireError(std::string(what) + ": " + std::to_string(n) + " elements, the request asked for " +
                      std::to_string(expected));
    }
  }
  size_t remaining() const { return size_t(end_ - at_); }
  void expectEnd() const {
    if (at_ != end_) throw WireError("message has " + std::to_string(remaining()) + " bytes too many");
  }
  template <class T>
  T get() {
    T value{};
    read(*this, value);
    return value;
  }

 private:
  const char* at_;
  const char* end_;
};

// ---------------------------------------------------------------- codecs

// Structs are written as the tuple of their fields: Fields<T>::tie(s).
template <class T>
struct Fields;

template <class T>
concept HasFields = requires(T& t) {
  Fields<T>::tie(t);
};

template <class T>
concept Plain = std::is_arithmetic_v<T> && !std::is_same_v<T, bool>;

template <class T>
struct IsGlmVector : std::false_type {};
template <glm::length_t N, class T, glm::qualifier Q>
struct IsGlmVector<glm::vec<N, T, Q>> : std::true_type {};

// Types whose bytes are their value (no padding, every bit pattern valid).
template <class T>
concept Bulk = Plain<T> ||(IsGlmVector<T>::value&& Plain<typename T::value_type>);

// ---------------------------------------------------------------- sizes

template <class T>
struct IsOptional : std::false_type {};
template <class T>
struct IsOptional<std::optional<T>> : std::true_type {};
template <class T>
struct IsTuple : std::false_type {};
template <class... T>
struct IsTuple<std::tuple<T...>> : std::true_type {};

// The tuple of a struct's field types (Fields<T>::tie gives references).
template <class T>
using FieldTypes = decltype(std::apply([](auto&... f) { return std::tuple<std::decay_t<decltype(f)>...>{}; },
                                       Fields<T>::tie(std::declval<T&>())));

template <class Tuple, class F>
constexpr auto overTupleTypes(F f) {
  return [&]<size_t... I>(std::index_sequence<I...>) {
    return f.template operator()<std::tuple_element_t<I, Tuple>...>();
  }
  (std::make_index_sequence<std::tuple_size_v<Tuple>>{});
}

// Whether every value of T takes the same bytes, or at most a known number:
// no part whose length the writer chooses (no string, vector or image).
template <class T>
constexpr bool fixedSize() {
  if constexpr (Bulk<T> || std::is_same_v<T, bool> || std::is_enum_v<T>) {
    return true;
  } else if constexpr (IsOptional<T>::value) {
    return fixedSize<typename T::value_type>();
  } else if constexpr (IsTuple<T>::value) {
    return overTupleTypes<T>([]<class... E>() { return (fixedSize<E>() && ...); });
  } else if constexpr (HasFields<T>) {
    return fixedSize<FieldTypes<T>>();
  } else {
    return false;
  }
}
template <class T>
concept FixedSize = fixedSize<T>();

// The fewest (Most = false) or the most (Most = true) bytes a T takes on
// the wire. The fewest bound a count of T before anything is allocated (a
// count larger than what is left over this is a lie); the most exist for
// FixedSize types only.
template <class T, bool Most>
constexpr size_t wireSizeBound() {
  if constexpr (Bulk<T>) {
    return sizeof(T);
  } else if constexpr (std::is_same_v<T, bool>) {
    return 1;
  } else if constexpr (std::is_enum_v<T>) {
    return sizeof(std::underlying_type_t<T>);
  } else if constexpr (IsOptional<T>::value) {
    return Most ? 1 + wireSizeBound<typename T::value_type, Most>() : 1;
  } else if constexpr (IsTuple<T>::value) {
    return overTupleTypes<T>([]<class... E>() { return (size_t(0) + ... + wireSizeBound<E, Most>()); });
  } else if constexpr (HasFields<T>) {
    return wireSizeBound<FieldTypes<T>, Most>();
  } else {
    static_assert(!Most, "a string, a vector or an image has no most size");
    return sizeof(uint64_t);  // their counts at least
  }
}
template <class T>
constexpr size_t minWireSize() {
  return wireSizeBound<T, false>();
}
template <FixedSize T>
constexpr size_t maxWireSize() {
  return wireSizeBound<T, true>();
}

// ---------------------------------------------------------------- values

template <Bulk T>
void write(Writer& w, const T& value) {
  w.raw(&value, sizeof value);
}
template <Bulk T>
void read(Reader& r, T& value) {
  r.raw(&value, sizeof value);
}

inline void write(Writer& w, bool value) { w.put(uint8_t(value ? 1 : 0)); }
inline void read(Reader& r, bool& value) {
  uint8_t b = r.get<uint8_t>();
  if (b > 1) throw WireError("boolean is not 0 or 1");
  value = b == 1;
}

template <class E>
requires std::is_enum_v<E>
void write(Writer& w, E value) { w.put(static_cast<std::underlying_type_t<E>>(value)); }
template <class E>
requires std::is_enum_v<E>
void read(Reader& r, E& value) { value = static_cast<E>(r.get<std::underlying_type_t<E>>()); }

inline void write(Writer& w, const std::string& s) {
  w.put(uint64_t(s.size()));
  w.raw(s.data(), s.size());
}
inline void read(Reader& r, std::string& s) {
  s.resize(r.count(1));
  r.raw(s.data(), s.size());
}

template <class T>
void write(Writer& w, const std::vector<T>& v) {
  w.put(uint64_t(v.size()));
  if constexpr (Bulk<T>) {
    w.raw(v.data(), v.size() * sizeof(T));
  } else {
    for (const T& x : v) w.put(x);
  }
}
template <class T>
void readElements(Reader& r, std::vector<T>& v, size_t n) {
  if constexpr (Bulk<T>) {
    v.resize(n);
    r.raw(v.data(), v.size() * sizeof(T));
  } else {
    v.clear();
    v.resize(n);
    for (T& x : v) read(r, x);
  }
}
template <class T>
void read(Reader& r, std::vector<T>& v) {
  readElements(r, v, r.count(minWireSize<T>()));
}

template <class T>
void write(Writer& w, const std::optional<T>& o) {
  write(w, o.has_value());
  if (o) w.put(*o);
}
template <class T>
void read(Reader& r, std::optional<T>& o) {
  if (r.get<bool>()) {
    o.emplace();
    read(r, *o);
  } else {
    o.reset();
  }
}

template <class... T>
void write(Writer& w, const std::tuple<T...>& t) {
  std::apply([&](const auto&... x) { (write(w, x), ...); }, t);
}
template <class... T>
void read(Reader& r, std::tuple<T...>& t) {
  std::apply([&](auto&... x) { (read(r, x), ...); }, t);
}

template <HasFields T>
void write(Writer& w, const T& s) {
  write(w, Fields<T>::tie(const_cast<T&>(s)));
}
template <HasFields T>
void read(Reader& r, T& s) {
  auto fields = Fields<T>::tie(s);
  read(r, fields);
}

template <class T>
void Writer::put(const T& value) {
  write(*this, value);
}

// Field lists of the framework's value types, and of the task types the
// framework's own calls carry (image_calls.h: the camera, the tree, the
// adaptive settings). A task's other value types are its own: its calls.h
// lists their fields with the same macro, in namespace pathlab::wire (task 2's
// SurfacePoint, task 3's TraversalStats, task 4's LightDirection).
#define PATHLAB_WIRE_FIELDS(Type, ...)                         \
  template <>                                                  \
  struct Fields<Type> {                                        \
    static auto tie(Type& s) { return std::tie(__VA_ARGS__); } \
    static constexpr const char* names = #__VA_ARGS__;         \
  }

PATHLAB_WIRE_FIELDS(Interval, s.min, s.max);
PATHLAB_WIRE_FIELDS(Ray, s.origin, s.direction);
PATHLAB_WIRE_FIELDS(Camera, s.position, s.lookAt, s.up, s.vfovDegrees, s.apertureRadius, s.focalDistance);
PATHLAB_WIRE_FIELDS(CameraBasis, s.forward, s.right, s.up);
PATHLAB_WIRE_FIELDS(AdaptiveSettings, s.tolerance, s.batch, s.minSpp, s.maxSpp);
PATHLAB_WIRE_FIELDS(TriangleHit, s.t, s.b1, s.b2);
PATHLAB_WIRE_FIELDS(Aabb, s.min, s.max);
PATHLAB_WIRE_FIELDS(BvhNode, s.bounds, s.leftOrFirst, s.count);
PATHLAB_WIRE_FIELDS(Bvh, s.nodes, s.primitives);
PATHLAB_WIRE_FIELDS(PrimitiveHit, s.t, s.b1, s.b2, s.primitive);
PATHLAB_WIRE_FIELDS(Hit, s.t, s.point, s.geometricNormal, s.shadingNormal, s.primitive, s.material);
PATHLAB_WIRE_FIELDS(AreaSample, s.point, s.normal, s.radiance, s.pdfArea);
PATHLAB_WIRE_FIELDS(BsdfSample, s.wi, s.f, s.pdf, s.isDelta);
PATHLAB_WIRE_FIELDS(EnvironmentDistribution, s.width, s.height, s.marginalCdf, s.conditionalCdf, s.totalWeight);
PATHLAB_WIRE_FIELDS(EnvironmentSample, s.direction, s.pdfSolidAngle);
PATHLAB_WIRE_FIELDS(Material, s.name, s.type, s.albedo, s.transmittance, s.ior, s.emission, s.roughness, s.exactFresnel,
                    s.eta, s.k, s.interior);
PATHLAB_WIRE_FIELDS(Medium, s.name, s.sigmaT, s.albedo, s.g);
PATHLAB_WIRE_FIELDS(RoughConductor, s.roughness, s.f0, s.exactFresnel, s.eta, s.k);
PATHLAB_WIRE_FIELDS(RoughPlastic, s.roughness, s.diffuse, s.ior);
PATHLAB_WIRE_FIELDS(TriangleMesh, s.name, s.positions, s.normals, s.triangles, s.material);
PATHLAB_WIRE_FIELDS(Sphere, s.center, s.radius, s.material);
PATHLAB_WIRE_FIELDS(PointLight, s.position, s.intensity);
PATHLAB_WIRE_FIELDS(RenderSettings, s.width, s.height, s.samplesPerPixel, s.lightSamples, s.maxDepth, s.seed);

// An image: its pixel count must match its size.
inline void write(Writer& w, const Image& image) {
  w.put(image.width);
  w.put(image.height);
  w.put(image.pixels);
}
inline void read(Reader& r, Image& image) {
  r.raw(&image.width, sizeof image.width);
  r.raw(&image.height, sizeof image.height);
  read(r, image.pixels);
  if (image.width < 0 || image.height < 0 || image.pixels.size() != size_t(image.width) * size_t(image.height)) {
    throw WireError("image size does not match its pixels");
  }
}

template <>
struct Fields<Environment> {
  static auto tie(Environment& s) { return std::tie(s.color, s.imagePath, s.image, s.scale); }
};

// A scene without its primitive index, which the receiver rebuilds.
template <>
struct Fields<Scene> {
  static auto tie(Scene& s) {
    return std::tie(s.source, s.camera, s.render, s.materials, s.meshes, s.spheres, s.pointLights, s.environment,
                    s.media, s.medium);
  }
};
inline void read(Reader& r, Scene& s) {
  auto fields = Fields<Scene>::tie(s);
  read(r, fields);
  s.indexPrimitives();
}

}  // namespace pathlab::wire
