// attack: leaves System V shared memory (64 MB), a semaphore set, a message queue, a POSIX message queue
// and files in /run/lock and /var/tmp, for the next submission to find
// base: stub  expect: 0
#include <fcntl.h>
#include <mqueue.h>
#include <sys/ipc.h>
#include <sys/msg.h>
#include <sys/sem.h>
#include <sys/shm.h>
#include <cstring>
#include <fstream>
namespace {
const bool left = [] {
  const int segment = shmget(IPC_PRIVATE, size_t(64) << 20, IPC_CREAT | 0666);
  if (segment >= 0) {
    void* memory = shmat(segment, nullptr, 0);
    if (memory != reinterpret_cast<void*>(-1)) {
      std::memset(memory, 's', size_t(64) << 20);
      shmdt(memory);
    }
  }
  semget(IPC_PRIVATE, 4, IPC_CREAT | 0666);
  msgget(IPC_PRIVATE, IPC_CREAT | 0666);
  mq_open("/pathlab-attack", O_CREAT | O_RDWR, 0666, nullptr);
  for (const char* file : {"/run/lock/pathlab-attack", "/var/tmp/pathlab-attack", "/dev/shm/pathlab-attack"}) {
    std::ofstream(file) << "left behind\n";
  }
  return true;
}();
}  // namespace
