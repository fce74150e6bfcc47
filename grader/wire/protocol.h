// How the judge and the candidate talk (docs/ta-guide.md, "Judge and
// candidate"). The judge — the test suite — owns every input, expected value
// and verdict, and never runs student code. The candidate is a separate
// process built from the student's task file, the framework and the
// reference for the other tasks; it only computes. The judge writes a
// request on the candidate's file descriptor 3 and reads the answer on its
// descriptor 4 (on Windows, pipes the candidate inherits:
// candidate_process.h); the candidate's stdout and stderr are only shown,
// never parsed.
//
//   request:  Header{kRequestMagic, call id, payload size}  payload
//   response: Header{kResponseMagic, status, payload size}  payload
//
// A call is a batch: the payload is a count and that many argument tuples,
// the answer that many results (calls.h in each suite's folder lists them).
//
// While it computes an answer, the candidate may ask the judge for data the
// judge serves only when asked, so that the judge itself counts what was
// taken (task 3's primitive tests and task 4's shadow rays, one per ask;
// task 11's samples, a batch at a time):
//   ask:      Header{kResponseMagic, Status::Asks, payload size}  payload
//   reply:    Header{kRequestMagic, kReplyId, payload size}  payload
// and then goes on to its answer.
#pragma once

#include <cstdint>
#include <string>

namespace pathlab::remote {

inline constexpr uint32_t kRequestMagic = 0x51455250;   // "PREQ"
inline constexpr uint32_t kResponseMagic = 0x53455250;  // "PRES"
inline constexpr int kRequestFd = 3;                    // the candidate reads requests here
inline constexpr int kResponseFd = 4;                   // and writes its answers here
// The largest message either side accepts (a 1e6-sample batch is ~30 MB).
inline constexpr uint64_t kMaxMessageBytes = uint64_t(512) << 20;
// The largest answer that is not Ok (an exception's message): the judge
// shows it under a failed test, so a candidate may not make it hold more.
inline constexpr uint64_t kMaxErrorMessageBytes = uint64_t(64) << 10;

enum class Status : uint32_t {
  Ok = 0,
  Threw = 1,        // the task's code threw: the payload is the message
  UnknownCall = 2,  // this candidate does not serve that call
  BadRequest = 3,   // the request did not decode
  Asks = 4,         // not an answer yet: a question to the judge (above)
};
inline constexpr uint32_t kReplyId = 0xFFFFFFFF;  // the judge's reply to an ask
// The longest ask the judge reads (asks are a few numbers).
inline constexpr uint64_t kMaxAskBytes = 4096;

struct Header {
  uint32_t magic = 0;
  uint32_t value = 0;  // the call id (request) or the Status (response)
  uint64_t size = 0;
};
static_assert(sizeof(Header) == 16);

// Whole-buffer reads and writes on a descriptor, retrying on EINTR. read
// returns false on end of file before the first byte; both throw
// std::runtime_error on errors and on a stream that ends mid-message.
bool readAll(int fd, void* data, size_t size);
void writeAll(int fd, const void* data, size_t size);

// One read of up to `size` bytes, retrying on EINTR: the count, 0 at end
// of file, -1 on an error.
long readSome(int fd, void* data, size_t size);
void closeDescriptor(int fd);  // ignores -1

// One framed message: header then payload. readMessage returns false at a
// clean end of file and throws on a bad magic or an oversized payload, read
// no further (over maxBytes and kMaxMessageBytes; for a response whose status
// is not Ok, over kMaxErrorMessageBytes).
void writeMessage(int fd, uint32_t magic, uint32_t value, const std::string& payload);
bool readMessage(int fd, uint32_t magic, uint32_t& value, std::string& payload, uint64_t maxBytes = kMaxMessageBytes);

}  // namespace pathlab::remote
