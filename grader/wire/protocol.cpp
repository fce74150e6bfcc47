#include "protocol.h"

#if defined(_WIN32)
#include <io.h>
#else
#include <unistd.h>
#endif

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace pathlab::remote {
namespace {

// One read or write of at most 1 GB (Windows' C runtime counts in unsigned int).
long rawRead(int fd, void* data, size_t size) {
#if defined(_WIN32)
  return _read(fd, data, unsigned(std::min(size, size_t(1) << 30)));
#else
  return long(::read(fd, data, std::min(size, size_t(1) << 30)));
#endif
}
long rawWrite(int fd, const void* data, size_t size) {
#if defined(_WIN32)
  return _write(fd, data, unsigned(std::min(size, size_t(1) << 30)));
#else
  return long(::write(fd, data, std::min(size, size_t(1) << 30)));
#endif
}

}  // namespace

long readSome(int fd, void* data, size_t size) {
  for (;;) {
    const long n = rawRead(fd, data, size);
    if (n < 0 && errno == EINTR) continue;
    return n;
  }
}

void closeDescriptor(int fd) {
  if (fd < 0) return;
#if defined(_WIN32)
  _close(fd);
#else
  ::close(fd);
#endif
}

bool readAll(int fd, void* data, size_t size) {
  char* at = static_cast<char*>(data);
  size_t done = 0;
  while (done < size) {
    const long n = readSome(fd, at + done, size - done);
    if (n < 0) throw std::runtime_error(std::string("read failed: ") + std::strerror(errno));
    if (n == 0) {
      if (done == 0) return false;
      throw std::runtime_error("the stream ended in the middle of a message");
    }
    done += size_t(n);
  }
  return true;
}

void writeAll(int fd, const void* data, size_t size) {
  const char* at = static_cast<const char*>(data);
  size_t done = 0;
  while (done < size) {
    const long n = rawWrite(fd, at + done, size - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw std::runtime_error(std::string("write failed: ") + std::strerror(errno));
    done += size_t(n);
  }
}

void writeMessage(int fd, uint32_t magic, uint32_t value, const std::string& payload) {
  Header header{magic, value, payload.size()};
  if (payload.size() <= 4096) {  // one write: an ask and its reply go back and forth thousands of times
    char message[sizeof header + 4096];
    std::memcpy(message, &header, sizeof header);
    std::memcpy(message + sizeof header, payload.data(), payload.size());
    writeAll(fd, message, sizeof header + payload.size());
    return;
  }
  writeAll(fd, &header, sizeof header);
  writeAll(fd, payload.data(), payload.size());
}

bool readMessage(int fd, uint32_t magic, uint32_t& value, std::string& payload, uint64_t maxBytes) {
  Header header;
  if (!readAll(fd, &header, sizeof header)) return false;
  if (header.magic != magic) throw std::runtime_error("not a message of this protocol (bad magic number)");
  const bool error =
      magic == kResponseMagic && header.value != uint32_t(Status::Ok) && header.value != uint32_t(Status::Asks);
  const bool ask = magic == kResponseMagic && header.value == uint32_t(Status::Asks);
  const uint64_t limit = error ? kMaxErrorMessageBytes : ask ? kMaxAskBytes : std::min(maxBytes, kMaxMessageBytes);
  if (header.size > limit) {
    throw std::runtime_error(
        (error ? "an error message of " : "a message of ") + std::to_string(header.size) +
        " bytes is over the limit of " + std::to_string(limit) + " bytes" +
        (error || ask || limit == kMaxMessageBytes ? "" : " (the most a right answer to this request takes)"));
  }
  value = header.value;
  payload.resize(header.size);
  if (header.size > 0 && !readAll(fd, payload.data(), header.size)) {
    throw std::runtime_error("the stream ended in the middle of a message");
  }
  return true;
}

}  // namespace pathlab::remote
