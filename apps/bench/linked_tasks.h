// Whose code each course task is in this binary, so that benchmark output
// says whose code ran: "yours" (the student's file: tasks/, or the folder
// PATHLAB_STUDENT_DIR names) or "reference" (solutions/). CMake chooses per
// task (PATHLAB_TASKS, PATHLAB_TASKn: cmake/PathLabTasks.cmake) and records
// the choice as linkedTaskSummary() ("1:reference 2:student ..."), the
// string `pathlab --version` prints. A summary that does not name a task
// still tells one case for sure: a task with no solutions/ file when the
// build was configured (a student release; core/task_list.h) can only be
// the student's; anything else is reported as "unknown", never guessed.
#pragma once

#include <nlohmann/json.hpp>

#include <array>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "core/task_list.h"
#include "task_summary.h"

namespace pathlab::bench {

enum class Code { Reference, Yours, Unknown };

inline const char* codeName(Code code) {
  switch (code) {
    case Code::Reference: return "reference";
    case Code::Yours: return "yours";
    case Code::Unknown: return "unknown";
  }
  return "unknown";
}

struct LinkedTasks {
  std::array<Code, kTaskCount + 1> code{};  // code[1] .. code[kTaskCount]
  bool recorded = false;       // from linkedTaskSummary()

  Code operator[](int task) const { return code[size_t(task)]; }
};

// `summary`: "1:reference 2:student ..." as CMake writes it.
inline LinkedTasks parseTaskSummary(const char* summary) {
  LinkedTasks tasks;
  for (int n = 1; n <= kTaskCount; ++n) tasks.code[size_t(n)] = kTaskHasSolution[n] ? Code::Unknown : Code::Yours;
  std::istringstream in(summary);
  for (std::string entry; in >> entry;) {
    const size_t colon = entry.find(':');
    if (colon == std::string::npos) continue;
    const int n = std::atoi(entry.c_str());
    const std::string variant = entry.substr(colon + 1);
    if (n < 1 || n > kTaskCount) continue;
    if (variant == "student") tasks.code[size_t(n)] = Code::Yours;
    else if (variant == "reference") tasks.code[size_t(n)] = Code::Reference;
    else continue;
    tasks.recorded = true;
  }
  return tasks;
}

inline LinkedTasks linkedTasks() { return parseTaskSummary(linkedTaskSummary()); }

// "task 5 yours", "tasks 1-4, 6-7 reference; task 5 yours": the given tasks
// grouped by whose code they are.
inline std::string describeTasks(const LinkedTasks& tasks, const std::vector<int>& which) {
  std::string out;
  for (Code code : {Code::Yours, Code::Reference, Code::Unknown}) {
    std::vector<int> list;
    for (int n : which) {
      if (tasks[n] == code) list.push_back(n);
    }
    if (list.empty()) continue;
    std::string ranges;
    for (size_t i = 0; i < list.size();) {
      size_t j = i;
      while (j + 1 < list.size() && list[j + 1] == list[j] + 1) ++j;
      if (!ranges.empty()) ranges += ", ";
      ranges += std::to_string(list[i]);
      if (j > i) ranges.append("-").append(std::to_string(list[j]));  // (GCC 12 -Wrestrict misfires on "-" + string)
      i = j + 1;
    }
    if (!out.empty()) out += "; ";
    out += (list.size() > 1 ? "tasks " : "task ") + ranges + " " + codeName(code);
  }
  return out;
}

// Every task, and why some are "unknown" when they are.
inline std::vector<int> allTaskNumbers() {
  std::vector<int> all;
  for (int n = 1; n <= kTaskCount; ++n) all.push_back(n);
  return all;
}

inline std::string describeAllTasks(const LinkedTasks& tasks) {
  std::string out = describeTasks(tasks, allTaskNumbers());
  for (int n = 1; n <= kTaskCount; ++n) {
    if (tasks[n] != Code::Unknown) continue;
    return out + " (the task summary this pathlab-bench was built with does not say whose code it links)";
  }
  return out;
}

// {"3": "yours", ...} for the given tasks.
inline nlohmann::json tasksJson(const LinkedTasks& tasks, const std::vector<int>& which) {
  nlohmann::json json = nlohmann::json::object();
  for (int n : which) json[std::to_string(n)] = codeName(tasks[n]);
  return json;
}

inline nlohmann::json allTasksJson(const LinkedTasks& tasks) { return tasksJson(tasks, allTaskNumbers()); }

}  // namespace pathlab::bench
