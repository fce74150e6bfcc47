// The wire schema: what a type looks like on the wire (wire.h), as JSON, so
// that tools outside the C++ (tools/adversary, which makes hostile answers
// of every call's exact shape) read the one definition the judge and the
// candidate compile. `candidate-NN-name --wire-schema` prints every call its
// server answers (server.cpp).
//
//   {"t": "f32" | "f64" | "i8" .. "i64" | "u8" .. "u64" | "bool"}  a number
//   {"t": "tuple", "of": [...], "names": [...]}                   fields in order (names: a struct's)
//   {"t": "optional", "of": X}                                    a 0/1 byte, then X when 1
//   {"t": "vector", "of": X}                                      a u64 count, then that many X
//   {"t": "string"}                                               a u64 count, then bytes
#pragma once

#include <string>
#include <type_traits>

#include "wire.h"

namespace pathlab::wire {

template <class T>
std::string schemaOf();

template <class T>
std::string numberSchema() {
  if constexpr (std::is_same_v<T, bool>) {
    return "bool";
  } else {
    const char kind = std::is_floating_point_v<T> ? 'f' : std::is_signed_v<T> ? 'i' : 'u';
    return std::string(1, kind) + std::to_string(8 * sizeof(T));
  }
}

template <class... E>
std::string tupleSchema(const char* names = nullptr) {
  std::string of;
  ((of += (of.empty() ? "" : ",") + schemaOf<E>()), ...);
  std::string json = "{\"t\":\"tuple\",\"of\":[" + of + "]";
  if (names) {  // "s.width, s.height" as a PATHLAB_WIRE_FIELDS list names them
    std::string list, name;
    for (const char* c = names;; ++c) {
      if (*c == ',' || *c == '\0') {
        if (name.rfind("s.", 0) == 0) name = name.substr(2);
        list += (list.empty() ? "\"" : ",\"") + name + "\"";
        name.clear();
        if (*c == '\0') break;
      } else if (*c != ' ') {
        name += *c;
      }
    }
    json += ",\"names\":[" + list + "]";
  }
  return json + "}";
}

template <class T>
concept NamedFields = requires {
  Fields<T>::names;
};

template <class T>
std::string schemaOf() {
  if constexpr (Plain<T> || std::is_same_v<T, bool>) {
    return "{\"t\":\"" + numberSchema<T>() + "\"}";
  } else if constexpr (std::is_enum_v<T>) {
    return schemaOf<std::underlying_type_t<T>>();
  } else if constexpr (IsGlmVector<T>::value) {
    return [&]<size_t... I>(std::index_sequence<I...>) {
      return tupleSchema<std::enable_if_t<I >= 0, typename T::value_type>...>();
    }
    (std::make_index_sequence<size_t(T::length())>{});
  } else if constexpr (IsOptional<T>::value) {
    return "{\"t\":\"optional\",\"of\":" + schemaOf<typename T::value_type>() + "}";
  } else if constexpr (IsTuple<T>::value) {
    return overTupleTypes<T>([]<class... E>() { return tupleSchema<E...>(); });
  } else if constexpr (std::is_same_v<T, std::string>) {
    return "{\"t\":\"string\"}";
  } else if constexpr (std::is_same_v<T, Image>) {
    return tupleSchema<int, int, std::vector<Color>>("s.width, s.height, s.pixels");
  } else if constexpr (HasFields<T>) {
    const char* names = nullptr;
    if constexpr (NamedFields<T>) names = Fields<T>::names;
    return overTupleTypes<FieldTypes<T>>([&]<class... E>() { return tupleSchema<E...>(names); });
  } else {
    return "{\"t\":\"vector\",\"of\":" + schemaOf<typename T::value_type>() + "}";
  }
}

}  // namespace pathlab::wire
