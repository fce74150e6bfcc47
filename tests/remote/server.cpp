// The candidate process: answers the judge's calls with the linked task code.
#include "server.h"

#if defined(__linux__)
#include <malloc.h>
#include <sys/prctl.h>
#endif

#include <csignal>
#include <exception>

#include "protocol.h"

namespace pathlab::remote {

int Server::run(int requestFd, int responseFd) {
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
    writeMessage(responseFd, kResponseMagic, uint32_t(status), answer.bytes());
  }
  return 0;
}

}  // namespace pathlab::remote

int main() {
#if defined(__linux__)
  // Outside a sandbox (ctest), a candidate whose judge died goes with it
  // (elsewhere it goes at its next read: the request pipe is closed).
  prctl(PR_SET_PDEATHSIG, SIGKILL);
  // Reuse the memory of one batch for the next (see judge.cpp).
  mallopt(M_MMAP_THRESHOLD, 1 << 30);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
#endif
  pathlab::remote::Server server;
  pathlab::remote::registerCalls(server);
  try {
    return server.run(pathlab::remote::kRequestFd, pathlab::remote::kResponseFd);
  } catch (const std::exception&) {
    return 3;  // the judge went away mid-message
  }
}
