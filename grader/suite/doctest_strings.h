// doctest, with a C string in a message printed as its text.
//
// doctest prints a `const char*` as a pointer ("n = 304" << (ok ? " (yes)" :
// " (the maximum)") reads "n = 3040x559f48048232": a ternary of two string
// literals of different lengths is a pointer). Every file of the suites
// includes doctest through this header, so no message prints an address.
#pragma once

#include <doctest/doctest.h>

template <>
struct doctest::StringMaker<const char*> {
  static doctest::String convert(const char* text) { return text ? text : "(null)"; }
};
template <>
struct doctest::StringMaker<char*> {
  static doctest::String convert(const char* text) { return text ? text : "(null)"; }
};
