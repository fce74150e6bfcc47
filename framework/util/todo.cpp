#include "util/todo.h"

#include <cstdio>
#include <cstdlib>

namespace pathlab {
namespace {

std::mutex& todoMutex() {
  static std::mutex mutex;
  return mutex;
}

std::vector<TodoReached>& todoList() {
  static std::vector<TodoReached> list;
  return list;
}

}  // namespace

void reportTodo(const char* tag, const char* file, int line) {
  // The task number is the digit after 'T' in tags like "T2.1".
  const char* task = (tag[0] == 'T') ? tag + 1 : tag;
  int taskNumber = std::atoi(task);
  std::lock_guard<std::mutex> lock(todoMutex());
  std::fprintf(stderr, "task %d not implemented: %s:%d (TODO %s)\n", taskNumber, file, line, tag);
  todoList().push_back({tag, file, line});
}

std::vector<TodoReached> todosReached() {
  std::lock_guard<std::mutex> lock(todoMutex());
  return todoList();
}

}  // namespace pathlab
