// Remote calls: what the judge asks the candidate to compute. Each suite's
// calls.h declares its calls with PATHLAB_REMOTE_CALL, and the judge-side
// functions (namespace pathlab::candidate) that tests use in place of the
// task's own: candidate::intersectTriangle(...) runs the student's
// intersectTriangle in the candidate process and returns its answer.
//
// Every call is a batch: callMany<C>(items) sends many argument tuples in
// one message (statistical tests draw 10^6 samples), call<C>(args...) one.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <tuple>
#include <type_traits>
#include <vector>

#include "wire.h"

namespace pathlab::remote {

template <class Signature>
struct CallType;
template <class R, class... A>
struct CallType<R(A...)> {
  using Result = R;
  using Args = std::tuple<std::decay_t<A>...>;
};

// PATHLAB_REMOTE_CALL(Name, id, Result(Args...)): ids are unique within a suite.
#define PATHLAB_REMOTE_CALL(Name, callId, ...)               \
  struct Name : ::pathlab::remote::CallType<__VA_ARGS__> {   \
    static constexpr uint32_t id = callId;                   \
    static constexpr const char* name = #Name;               \
  }

// The candidate did not answer: it crashed, threw, or sent something that
// does not decode. The test that made the call fails with this message.
class CandidateError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Judge side (judge.cpp): sends one request and returns the answer's
// payload, starting the candidate process on first use (and again after it
// crashed). Throws CandidateError.
std::string exchange(uint32_t id, const char* name, const std::string& request);

template <class C>
std::vector<typename C::Result> callMany(const std::vector<typename C::Args>& items) {
  wire::Writer request;
  request.put(uint64_t(items.size()));
  for (const auto& item : items) request.put(item);
  const std::string answer = exchange(C::id, C::name, request.bytes());
  std::vector<typename C::Result> results(items.size());
  try {
    wire::Reader reader(answer);
    for (auto& result : results) read(reader, result);
    reader.expectEnd();
  } catch (const wire::WireError& e) {
    throw CandidateError(std::string("the candidate's answer to ") + C::name + " is malformed: " + e.what());
  }
  return results;
}

template <class C, class... A>
typename C::Result call(A&&... args) {
  return callMany<C>({typename C::Args(std::forward<A>(args)...)}).front();
}

// What the candidate printed since the last call of this function (clipped
// and with control characters replaced): shown under a failing test.
std::string takeCandidateOutput();

}  // namespace pathlab::remote
