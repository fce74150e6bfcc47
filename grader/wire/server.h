// The candidate's side of remote calls: a table from call id to a function
// of the linked task code. Each suite's serve.cpp fills it in
// registerCalls(); candidate_main.cpp answers requests until the judge
// closes the pipe.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <tuple>
#include <unordered_map>

#include "call.h"
#include "wire.h"
#include "wire_schema.h"

namespace pathlab::remote {

class Server {
 public:
  // Serves call C with f, which takes C's arguments and returns its result.
  template <class C, class F>
  void serve(F f) {
    schemas_[C::id] =
        std::string("{\"name\":\"") + C::name + "\",\"answer\":" + wire::schemaOf<typename C::Result>() + "}";
    handlers_[C::id] = [f](wire::Reader& in, wire::Writer& out) {
      const size_t count = in.count(1);
      std::vector<typename C::Args> items(count);
      for (auto& item : items) read(in, item);
      in.expectEnd();
      for (const auto& item : items) out.put(typename C::Result(std::apply(f, item)));
    };
  }
  // Answers requests on requestFd until it closes; returns the exit code.
  int run(int requestFd, int responseFd);
  // {"ID": {"name": ..., "answer": schema}, ...}: the calls served and the shape of one result of each
  // (an answer is the request's count of results; wire_schema.h).
  std::string schema() const;

 private:
  std::unordered_map<uint32_t, std::string> schemas_;
  std::unordered_map<uint32_t, std::function<void(wire::Reader&, wire::Writer&)>> handlers_;
};

// During a call: asks the judge for data it serves only when asked
// (protocol.h) and returns its reply. Throws std::runtime_error when the
// judge does not reply.
std::string ask(const std::string& question);

// Defined by the suite's serve.cpp.
void registerCalls(Server& server);

}  // namespace pathlab::remote
