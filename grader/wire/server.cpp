// The candidate process: answers the judge's calls with the linked task code.
#include "server.h"

#include <cstdio>
#include <exception>
#include <map>
#include <stdexcept>
#include <string>

#include "candidate_process.h"
#include "protocol.h"

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace pathlab::remote {
namespace {
int requests = -1, answers = -1;  // Server::run's descriptors, for ask()
}  // namespace

std::string ask(const std::string& question) {
  writeMessage(answers, kResponseMagic, uint32_t(Status::Asks), question);
  uint32_t id = 0;
  std::string reply;
  if (!readMessage(requests, kRequestMagic, id, reply) || id != kReplyId) {
    throw std::runtime_error("the judge did not reply to an ask");
  }
  return reply;
}

std::string Server::schema() const {
  std::map<uint32_t, std::string> ordered(schemas_.begin(), schemas_.end());
  std::string json;
  for (const auto& [id, call] : ordered) json += (json.empty() ? "{\"" : ",\"") + std::to_string(id) + "\":" + call;
  return json + "}";
}

int Server::run(int requestFd, int responseFd) {
  requests = requestFd;
  answers = responseFd;
  uint32_t id = 0;
  std::string request;
  while (readMessage(requestFd, kRequestMagic, id, request)) {
    auto handler = handlers_.find(id);
    if (handler == handlers_.end()) {
      writeMessage(responseFd, kResponseMagic, uint32_t(Status::UnknownCall), "call " + std::to_string(id));
      continue;
    }
    wire::Writer answer;
    Status status = Status::Ok;
    try {
      wire::Reader reader(request);
      handler->second(reader, answer);
    } catch (const wire::WireError& e) {
      status = Status::BadRequest;
      answer.bytes() = e.what();
    } catch (const std::exception& e) {
      status = Status::Threw;
      answer.bytes() = e.what();
    } catch (...) {
      status = Status::Threw;
      answer.bytes() = "an exception that is not a std::exception";
    }
    if (status != Status::Ok && answer.bytes().size() > kMaxErrorMessageBytes) {  // the judge takes no more
      answer.bytes().resize(kMaxErrorMessageBytes - 32);
      answer.bytes() += " [... message cut ...]";
    }
    writeMessage(responseFd, kResponseMagic, uint32_t(status), answer.bytes());
  }
  return 0;
}

}  // namespace pathlab::remote

int main(int argc, char** argv) {
  if (argc == 2 && std::string(argv[1]) == "--wire-schema") {  // what tools/adversary reads
    pathlab::remote::Server server;
    pathlab::remote::registerCalls(server);
    std::printf("%s\n", server.schema().c_str());
    return 0;
  }
  pathlab::remote::candidateDiesWithJudge();
#if defined(__GLIBC__)
  // Reuse the memory of one batch for the next (see judge.cpp).
  mallopt(M_MMAP_THRESHOLD, 1 << 30);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
#endif
  pathlab::remote::Server server;
  pathlab::remote::registerCalls(server);
  try {
    const int requests = pathlab::remote::candidateRequestFd(), answers = pathlab::remote::candidateResponseFd();
    if (requests < 0 || answers < 0) {
      std::fprintf(stderr,
                   "a candidate answers a test suite's calls: run the suite (test-NN-name), not this program\n");
      return 2;
    }
    return server.run(requests, answers);
  } catch (const std::exception&) {
    return 3;  // the judge went away mid-message
  }
}
