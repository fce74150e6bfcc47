// What an answer must look like, given the request that asked for it: every
// remote call names its answer's shape (PATHLAB_REMOTE_CALL in call.h), and
// the judge reads each answer through it. A shape gives
//   maxBytes(Of<Result>, args)  the most bytes a right answer to `args` takes:
//                               the judge reads no longer answer;
//   read(reader, result, args)  the answer decoded and checked against the
//                               request as it is read (lengths, image sizes,
//                               index ranges), so that nothing is allocated
//                               for a length the request did not ask for;
//                               a mismatch throws wire::WireError.
// A call whose answer has a part of variable length cannot be declared with
// Fixed (a compile-time error), so a new kind of answer cannot skip its check.
#pragma once

#include <algorithm>
#include <cstdint>
#include <limits>
#include <string>
#include <tuple>
#include <vector>

#include "wire.h"

namespace pathlab::remote::shape {

template <class T>
struct Of {};

// a + b, or the largest uint64_t where that overflows.
constexpr uint64_t saturatingAdd(uint64_t a, uint64_t b) {
  return a > std::numeric_limits<uint64_t>::max() - b ? std::numeric_limits<uint64_t>::max() : a + b;
}
constexpr uint64_t saturatingMultiply(uint64_t a, uint64_t b) {
  return b != 0 && a > std::numeric_limits<uint64_t>::max() / b ? std::numeric_limits<uint64_t>::max() : a * b;
}

// No part whose length the answer chooses: a number, a vector of fixed
// size, an optional or a struct of such.
struct Fixed {
  template <class R, class Args>
  static constexpr uint64_t maxBytes(Of<R>, const Args&) {
    static_assert(wire::FixedSize<R>, "this answer has a part of variable length: declare its shape (shape.h)");
    return wire::maxWireSize<R>();
  }
  template <class R, class Args>
  static void read(wire::Reader& r, R& result, const Args&) {
    wire::read(r, result);
  }
};

// The length of argument I (a vector): one element of the answer per element asked about.
template <size_t I>
struct LengthOf {
  template <class Args>
  static size_t of(const Args& args) {
    return std::get<I>(args).size();
  }
};

// A vector with exactly Length::of(args) elements, each read by Element.
template <class Length, class Element = Fixed>
struct Exactly {
  template <class E, class Args>
  static uint64_t maxBytes(Of<std::vector<E>>, const Args& args) {
    return saturatingAdd(8, saturatingMultiply(Length::of(args), Element::maxBytes(Of<E>{}, args)));
  }
  template <class E, class Args>
  static void read(wire::Reader& r, std::vector<E>& result, const Args& args) {
    const size_t n = Length::of(args);
    r.expectCount(n, "a list");
    result.resize(n);
    for (E& e : result) Element::read(r, e, args);
  }
};

// One element per element of argument I.
template <size_t I, class Element = Fixed>
using OnePer = Exactly<LengthOf<I>, Element>;

// A vector of at most Length::of(args) elements, each read by Element (its
// bytes bounded as Exactly's are).
template <class Length, class Element = Fixed>
struct AtMost : Exactly<Length, Element> {
  template <class E, class Args>
  static void read(wire::Reader& r, std::vector<E>& result, const Args& args) {
    const size_t most = Length::of(args);
    const size_t n = r.count(wire::minWireSize<E>());
    if (n > most) {
      throw wire::WireError("a list of " + std::to_string(n) + " elements, where the request allows at most " +
                            std::to_string(most));
    }
    result.resize(n);
    for (E& e : result) Element::read(r, e, args);
  }
};

// An index (an unsigned number) below Length::of(args).
template <class Length>
struct IndexBelow {
  template <class T, class Args>
  static constexpr uint64_t maxBytes(Of<T>, const Args&) {
    return sizeof(T);
  }
  template <class T, class Args>
  static void read(wire::Reader& r, T& index, const Args& args) {
    wire::read(r, index);
    if (uint64_t(index) >= Length::of(args)) {
      throw wire::WireError("index " + std::to_string(index) + " is out of range (below " +
                            std::to_string(Length::of(args)) + ")");
    }
  }
};

}  // namespace pathlab::remote::shape
