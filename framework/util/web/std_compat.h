// What the web build's C++ library lacks, included first in every file it
// compiles (cmake/PathLabWeb.cmake): Debian's Emscripten 3.1.6 ships libc++
// 14, which has no std::bit_cast; its compiler has the builtin it is made of.
#pragma once

#include <version>

#if !defined(__cpp_lib_bit_cast)
namespace std {

template <class To, class From>
constexpr To bit_cast(const From& from) noexcept {
  static_assert(sizeof(To) == sizeof(From), "bit_cast: the two types' sizes differ");
  return __builtin_bit_cast(To, from);  // which also requires both trivially copyable
}

}  // namespace std
#endif
