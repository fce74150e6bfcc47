// pathlab-confine PROGRAM [ARGS...]: runs PROGRAM with the system calls that
// reach beyond the process refused (EACCES), for the grader's uid sandbox
// (grader/driver/sandbox.py), where Gradescope's container allows no
// namespaces: bubblewrap's network and IPC namespaces do this job elsewhere.
//
// Refused, because a compiler and a candidate need none of them and each is a
// channel out of the sandbox or into the next submission's:
//   sockets of every family (a listener on 127.0.0.1, an abstract Unix
//   socket), io_uring (it opens sockets without the socket system call),
//   System V shared memory, semaphores and message queues and POSIX message
//   queues (they outlive every process), and the kernel's key rings (kept
//   per uid). socketpair stays: its two ends lead nowhere else.
// The filter is inherited by every child and cannot be lifted (no_new_privs).
// Calls of another architecture's ABI (32-bit x86 on x86-64) kill the
// process: libseccomp's default for a foreign architecture.
#include <cerrno>
#include <seccomp.h>
#include <cstdio>
#include <cstring>
#include <sys/prctl.h>
#include <unistd.h>

int main(int argc, char** argv) {
  if (argc < 2) {
    fprintf(stderr, "usage: pathlab-confine PROGRAM [ARGS...]\n");
    return 2;
  }
  scmp_filter_ctx filter = seccomp_init(SCMP_ACT_ALLOW);
  if (!filter) {
    fprintf(stderr, "pathlab-confine: seccomp_init failed\n");
    return 2;
  }
  const char* const refused[] = {"socket", "connect", "bind",     "listen",         "accept",      "accept4",
                                 "sendto", "sendmsg", "sendmmsg", "io_uring_setup", "shmget",      "shmat",
                                 "semget", "msgget",  "mq_open",  "add_key",        "request_key", "keyctl"};
  for (size_t i = 0; i < sizeof refused / sizeof refused[0]; ++i) {
    const int call = seccomp_syscall_resolve_name(refused[i]);
    if (call == __NR_SCMP_ERROR) continue;  // not a system call on this architecture
    const int rc = seccomp_rule_add(filter, SCMP_ACT_ERRNO(EACCES), call, 0);
    if (rc < 0) {
      fprintf(stderr, "pathlab-confine: cannot refuse %s: %s\n", refused[i], strerror(-rc));
      return 2;
    }
  }
  // no_new_privs first: an unprivileged process may only load a filter with it.
  if (prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) != 0) {
    perror("pathlab-confine: PR_SET_NO_NEW_PRIVS");
    return 2;
  }
  const int rc = seccomp_load(filter);
  if (rc < 0) {
    fprintf(stderr, "pathlab-confine: seccomp_load failed: %s\n", strerror(-rc));
    return 2;
  }
  seccomp_release(filter);
  execv(argv[1], argv + 1);
  fprintf(stderr, "pathlab-confine: cannot run %s: %s\n", argv[1], strerror(errno));
  return 127;
}
