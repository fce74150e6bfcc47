#include "util/todo.h"

#include <algorithm>
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

// __FILE__ is relative to the repository where the compiler can be told
// so (GCC and Clang: -fmacro-prefix-map); MSVC's is absolute, with
// backslashes: keep the part from the task's folder on.
std::string repositoryRelative(std::string file) {
  std::replace(file.begin(), file.end(), '\\', '/');
  size_t from = std::string::npos;  // the last /tasks/ or /solutions/
  for (const char* folder : {"/tasks/", "/solutions/"}) {
    const size_t at = file.rfind(folder);
    if (at != std::string::npos && (from == std::string::npos || at > from)) from = at;
  }
  return from == std::string::npos ? file : file.substr(from + 1);
}

}  // namespace

void reportTodo(const char* tag, const char* fileAsCompiled, int line) {
  const std::string file = repositoryRelative(fileAsCompiled);
  // The task number is the digit after 'T' in tags like "T2.1".
  const char* task = (tag[0] == 'T') ? tag + 1 : tag;
  int taskNumber = std::atoi(task);
  std::lock_guard<std::mutex> lock(todoMutex());
  std::fprintf(stderr, "task %d not implemented: %s:%d (TODO %s)\n", taskNumber, file.c_str(), line, tag);
  todoList().push_back({tag, file, line});
}

std::vector<TodoReached> todosReached() {
  std::lock_guard<std::mutex> lock(todoMutex());
  return todoList();
}

}  // namespace pathlab
