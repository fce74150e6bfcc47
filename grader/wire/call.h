// Remote calls: what the judge asks the candidate to compute. Each suite's
// calls.h declares its calls with PATHLAB_REMOTE_CALL, and the judge-side
// functions (namespace pathlab::candidate) that tests use in place of the
// task's own: candidate::intersectTriangle(...) runs the student's
// intersectTriangle in the candidate process and returns its answer.
//
// Every call is a batch: callMany<C>(items) sends many argument tuples in
// one message (statistical tests draw 10^6 samples), call<C>(args...) one.
//
// Every call names the shape of its answer (shape.h): the judge reads no
// more bytes than a right answer to its request can take, and checks each
// result against the request it answers as it decodes it.
#pragma once

#include <algorithm>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <tuple>
#include <type_traits>
#include <vector>

#include "shape.h"
#include "wire.h"

namespace pathlab::calls {
namespace shape = ::pathlab::remote::shape;  // the suites' calls name their answers' shapes
}  // namespace pathlab::calls

namespace pathlab::remote {

template <class Signature>
struct CallType;
template <class R, class... A>
struct CallType<R(A...)> {
  using Result = R;
  using Args = std::tuple<std::decay_t<A>...>;
};

// PATHLAB_REMOTE_CALL(Name, id, Shape, Result(Args...)): ids are unique
// within a suite; Shape is the answer's (shape.h): shape::Fixed, or e.g.
// shape::OnePer<2> for a vector as long as the third argument.
#define PATHLAB_REMOTE_CALL(Name, callId, AnswerShape, ...) \
  struct Name : ::pathlab::remote::CallType<__VA_ARGS__> {  \
    static constexpr uint32_t id = callId;                  \
    static constexpr const char* name = #Name;              \
    using Shape = AnswerShape;                              \
  }

// The candidate did not answer: it crashed, threw, or sent something that
// does not decode. The test that made the call fails with this message.
class CandidateError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The longest answer the judge reads, whatever its request: above any
// right answer the suites ask for (the largest, 10^6 light samples, is
// under 40 MB), far below what the judge's memory allows.
inline constexpr uint64_t kMaxAnswerBytes = uint64_t(96) << 20;

// What the judge answers when the candidate asks it for data mid-call
// (protocol.h): the reply to one ask's payload. Throws CandidateError for an
// ask it refuses (the call then fails with that message).
using AskHandler = std::function<std::string(const std::string& ask)>;

// An ask's payload decoded as Fields..., in order, and nothing after them;
// one that does not decode is the candidate's fault: a CandidateError saying
// "the candidate asked for <what> in a malformed way".
template <typename... Fields>
std::tuple<Fields...> readAsk(const std::string& ask, const char* what) {
  try {
    wire::Reader reader(ask);
    std::tuple<Fields...> fields{reader.get<Fields>()...};  // a braced list reads its items in order
    reader.expectEnd();
    return fields;
  } catch (const wire::WireError& e) {
    throw CandidateError(std::string("the candidate asked for ") + what + " in a malformed way: " + e.what());
  }
}

// Judge side (judge.cpp): sends one request and returns the answer's
// payload, starting the candidate process on first use (and again after it
// crashed); answers the candidate's asks with `asks` meanwhile (without one,
// an ask fails the call). An answer longer than maxAnswerBytes is not read.
// Throws CandidateError.
std::string exchange(uint32_t id, const char* name, const std::string& request, uint64_t maxAnswerBytes,
                     const AskHandler* asks = nullptr);

// The most bytes a right answer to `items` takes (its shape's bound), at most kMaxAnswerBytes.
template <class C>
uint64_t maxAnswerBytes(const std::vector<typename C::Args>& items) {
  uint64_t most = 0;
  for (const auto& item : items) {
    most = shape::saturatingAdd(most, C::Shape::maxBytes(shape::Of<typename C::Result>{}, item));
  }
  return std::min(most, kMaxAnswerBytes);
}

// An answer to `items`, read through C's shape: one result per item, each
// checked against its item. Throws wire::WireError, naming the result.
template <class C>
std::vector<typename C::Result> decodeAnswer(const std::string& answer, const std::vector<typename C::Args>& items) {
  std::vector<typename C::Result> results(items.size());
  size_t k = 0;
  try {
    wire::Reader reader(answer);
    for (; k < results.size(); ++k) C::Shape::read(reader, results[k], items[k]);
    reader.expectEnd();
  } catch (const wire::WireError& e) {
    if (results.size() <= 1) throw;
    throw wire::WireError("result " + std::to_string(k) + " of " + std::to_string(results.size()) + ": " + e.what());
  }
  return results;
}

template <class C>
std::vector<typename C::Result> callMany(const std::vector<typename C::Args>& items, const AskHandler* asks = nullptr) {
  wire::Writer request;
  request.put(uint64_t(items.size()));
  for (const auto& item : items) request.put(item);
  const std::string answer = exchange(C::id, C::name, request.bytes(), maxAnswerBytes<C>(items), asks);
  try {
    return decodeAnswer<C>(answer, items);
  } catch (const wire::WireError& e) {
    throw CandidateError(std::string("the candidate's answer to ") + C::name +
                         " does not match its request: " + e.what());
  }
}

template <class C, class... A>
typename C::Result call(A&&... args) {
  return callMany<C>({typename C::Args(std::forward<A>(args)...)}).front();
}

// What the candidate printed since the last call of this function (clipped
// and with control characters replaced): shown under a failing test.
std::string takeCandidateOutput();

// A new test case begins: the candidate's output so far and the times it
// died are not this test's (judge.cpp starts a candidate again after it
// died, at most a few times per test).
void newTestCase();

}  // namespace pathlab::remote
