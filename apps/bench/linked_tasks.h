// Whose code each course task is in this binary, so that benchmark output
// says whose code ran: "yours" (the student's file: tasks/, or the folder
// PATHLAB_STUDENT_DIR names) or "reference" (solutions/). CMake chooses per
// task (PATHLAB_TASKS, PATHLAB_TASKn: cmake/PathLabTasks.cmake) and records
// the choice as PATHLAB_TASK_SUMMARY ("1:reference 2:student ..."), the
// string `pathlab --version` prints. A binary compiled without it still knows
// one case for sure: a task with no solutions/ file (a student release) can
// only be the student's; anything else is reported as "unknown", never
// guessed.
#pragma once

#include <nlohmann/json.hpp>

#include <array>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

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
  std::array<Code, 8> code{};  // code[1] .. code[7]
  bool recorded = false;       // from the build's PATHLAB_TASK_SUMMARY

  Code operator[](int task) const { return code[size_t(task)]; }
};

namespace detail {

// Which solutions/ files existed when this was compiled (the same test
// pathlab_task_variant() makes: without one, a task falls back to the student's).
inline constexpr std::array<bool, 8> kHaveSolution = {
    false,
#if __has_include("../../solutions/01-camera-rays/camera_rays.cpp")
    true,
#else
    false,
#endif
#if __has_include("../../solutions/02-intersection/intersection.cpp")
    true,
#else
    false,
#endif
#if __has_include("../../solutions/03-bvh/bvh.cpp")
    true,
#else
    false,
#endif
#if __has_include("../../solutions/04-direct-lighting/direct_lighting.cpp")
    true,
#else
    false,
#endif
#if __has_include("../../solutions/05-path-tracing/path_tracing.cpp")
    true,
#else
    false,
#endif
#if __has_include("../../solutions/06-mirror-glass/mirror_glass.cpp")
    true,
#else
    false,
#endif
#if __has_include("../../solutions/07-environment/environment.cpp")
    true,
#else
    false,
#endif
};

}  // namespace detail

// `summary`: "1:reference 2:student ..." as CMake writes it; nullptr when
// the binary was compiled without it.
inline LinkedTasks parseTaskSummary(const char* summary) {
  LinkedTasks tasks;
  for (int n = 1; n <= 7; ++n) tasks.code[size_t(n)] = detail::kHaveSolution[size_t(n)] ? Code::Unknown : Code::Yours;
  if (!summary) return tasks;
  std::istringstream in(summary);
  for (std::string entry; in >> entry;) {
    const size_t colon = entry.find(':');
    if (colon == std::string::npos) continue;
    const int n = std::atoi(entry.c_str());
    const std::string variant = entry.substr(colon + 1);
    if (n < 1 || n > 7) continue;
    if (variant == "student") tasks.code[size_t(n)] = Code::Yours;
    else if (variant == "reference") tasks.code[size_t(n)] = Code::Reference;
    else continue;
    tasks.recorded = true;
  }
  return tasks;
}

inline LinkedTasks linkedTasks() {
#ifdef PATHLAB_TASK_SUMMARY
  return parseTaskSummary(PATHLAB_TASK_SUMMARY);
#else
  return parseTaskSummary(nullptr);
#endif
}

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
inline std::string describeAllTasks(const LinkedTasks& tasks) {
  std::string out = describeTasks(tasks, {1, 2, 3, 4, 5, 6, 7});
  for (int n = 1; n <= 7; ++n) {
    if (tasks[n] != Code::Unknown) continue;
    return out + " (this pathlab-bench was compiled without PATHLAB_TASK_SUMMARY, the record of whose code it links)";
  }
  return out;
}

// {"3": "yours", ...} for the given tasks.
inline nlohmann::json tasksJson(const LinkedTasks& tasks, const std::vector<int>& which) {
  nlohmann::json json = nlohmann::json::object();
  for (int n : which) json[std::to_string(n)] = codeName(tasks[n]);
  return json;
}

inline nlohmann::json allTasksJson(const LinkedTasks& tasks) { return tasksJson(tasks, {1, 2, 3, 4, 5, 6, 7}); }

}  // namespace pathlab::bench
