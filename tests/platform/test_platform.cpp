// The operating-system layer (framework/util/platform.h), through the
// functions built on it: files read whole or refused with a reason, written
// atomically, folders, stderr silenced, workers started. One source for
// both halves: CTest `platform` runs it on Linux (platform_posix.cpp);
// tools/windows-check cross-compiles it with mingw-w64 and runs it under
// Wine (platform_windows.cpp). Plain main(), so that build needs nothing
// but the compiler. Run from a scratch folder: it writes there.
#include <atomic>
#include <chrono>
#include <cstdio>
#include <string>
#include <thread>
#include <vector>

#include "util/error.h"
#include "util/input_file.h"
#include "util/parallel.h"
#include "util/platform.h"
#include "util/todo.h"

#if defined(PATHLAB_SANITIZED) && !defined(_WIN32)
#include <sanitizer/common_interface_defs.h>
#endif

using namespace pathlab;

namespace {

int passes = 0, failures = 0;

void expect(bool ok, const std::string& what) {
  std::printf("%s %s\n", ok ? "ok  " : "FAIL", what.c_str());
  (ok ? passes : failures) += 1;
}

template <class F>
std::string errorOf(F f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

void run() {
  writeFileAtomically("platform-out.txt", "hello");
  expect(readInputFile("platform-out.txt", "text file", 100) == "hello", "a file written atomically reads back");
  writeFileAtomically("platform-out.txt", "second");
  expect(readInputFile("platform-out.txt", "text file", 100) == "second", "an existing file is replaced");
  expect(!fileStatus(partialPathFor("platform-out.txt")).found, "no temporary file is left behind");
  expect(requireRegularFile("platform-out.txt", "text file") == 6, "a regular file's size");

  std::string e = errorOf([] { readInputFile("platform-out.txt", "text file", 3); });
  expect(contains(e, "more than the"), "a file over the limit is refused: " + e);
  e = errorOf([] { readInputFile("no-such-file.txt", "scene file", 100); });
  expect(contains(e, "no-such-file.txt: cannot open scene file: "), "a missing file: " + e);
  createFolders("platform-folder/inner");
  e = errorOf([] { readInputFile("platform-folder", "scene file", 100); });
  expect(contains(e, "platform-folder: is a folder, expected a scene file"), "a folder read as a file: " + e);
  e = errorOf([] { requireRegularFile("platform-folder", "image"); });
  expect(contains(e, "is a folder, expected an image"), "a folder looked up as a file: " + e);

  const FileStatus missing = fileStatus("no-such-folder/x.png");
  expect(!missing.found && missing.missing && !missing.error.empty(), "a missing path: " + missing.error);
  const FileStatus folder = fileStatus("platform-folder");
  expect(folder.found && folder.kind == FileKind::Folder, "a folder's kind");
  expect(folderIsWritable("platform-folder"), "a folder of ours is writable");
  expect(maxFileNameBytes() >= 255, "file names of 255 bytes");
  expect(currentProcessId() > 0 && currentProcessId() == currentProcessId(), "a process id");
  // MSVC's __FILE__ is absolute, with backslashes: a TODO still names the repository's file.
  reportTodo("T1.1", "C:\\Users\\me\\tasks\\pathlab\\tasks\\01-camera-rays\\camera_rays.cpp", 7);
  expect(todosReached().back().file == "tasks/01-camera-rays/camera_rays.cpp", "a TODO's file from an absolute __FILE__");
  reportTodo("T1.2", "D:\\tasks\\pathlab\\solutions\\01-camera-rays\\camera_rays.cpp", 8);
  expect(todosReached().back().file == "solutions/01-camera-rays/camera_rays.cpp", "the last task folder in the path");
  reportTodo("T2.1", "tasks/02-intersection/intersection.cpp", 9);
  expect(todosReached().back().file == "tasks/02-intersection/intersection.cpp", "a TODO's file from a relative __FILE__");
  const std::string self = currentExecutablePath();
  expect(self.find("test-platform") != std::string::npos && fileStatus(self).kind == FileKind::Regular,
         "the program's own path (" + self + ")");
  // runProgram: this program started again (main's --write-arguments), every
  // argument arriving whole, its exit code coming back.
  const std::vector<std::string> arguments{"two words", "a \"quoted\" word", "ends in a backslash\\", "\\\"", "",
                                           "x\\y z"};
  std::vector<std::string> request{"--write-arguments", "platform-arguments.txt"};
  request.insert(request.end(), arguments.begin(), arguments.end());
  std::string runError;
  int code = runProgram(self, request, runError);
  expect(code == 7 && runError.empty(), "a program run, its exit code " + std::to_string(code) + " " + runError);
  std::string received;
  for (const std::string& argument : arguments) received += argument + "\n";
  expect(readInputFile("platform-arguments.txt", "text file", 1000) == received,
         "its arguments arrive whole: spaces, quotes, backslashes, an empty one");
  code = runProgram("no-such-program", {}, runError);
  expect(code == -1 && !runError.empty(), "a program that is not there: " + std::to_string(code) + ", " + runError);
  // loadSharedLibrary: a library of the system's, one of its functions; a library that is not there.
#if defined(_WIN32)
  const char* systemLibrary = "kernel32.dll";
  const char* systemFunction = "GetTickCount";
#elif defined(__APPLE__)
  const char* systemLibrary = "/usr/lib/libSystem.B.dylib";
  const char* systemFunction = "getpid";
#else
  const char* systemLibrary = "libc.so.6";
  const char* systemFunction = "getpid";
#endif
  std::string loadError;
  void* library = loadSharedLibrary(systemLibrary, loadError);
  expect(library && loadError.empty(), std::string("a shared library loads: ") + systemLibrary + " " + loadError);
  expect(library && sharedLibraryFunction(library, systemFunction) &&
             !sharedLibraryFunction(library, "noSuchFunctionInThisLibrary"),
         "its function is found, a function it lacks is not");
  loadError.clear();
  const bool missingLoaded = loadSharedLibrary("no-such-library.so", loadError) != nullptr;
  expect(!missingLoaded && !loadError.empty(), "a library that is not there: " + loadError);
  e = errorOf([] { writeFileAtomically("no-such-folder/x.txt", "x"); });
  expect(contains(e, "no-such-folder/x.txt: cannot write: "), "a write into a missing folder: " + e);

  // What a library prints while stderr is silenced must not appear (the
  // runner checks the output for this line).
  // A sanitizer's report raised meanwhile must appear: it is not chatter.
  const int saved = silenceStderr();
  std::fprintf(stderr, "SILENCED STDERR LEAKED\n");
  std::fflush(stderr);
#if defined(PATHLAB_SANITIZED) && !defined(_WIN32)
  std::printf("a sanitizer's report is expected on stderr\n");
  std::fflush(stdout);
  __sanitizer_report_error_summary("SANITIZER REPORT WHILE SILENCED");
#endif
  restoreStderr(saved);
  std::fprintf(stderr, "stderr restored\n");

  // The thread's CPU clock runs while it computes and stands still while it sleeps
  // (pathlab-bench times its ray-query share with it on a busy machine).
  const auto wallStart = std::chrono::steady_clock::now();
  const double cpuStart = currentThreadCpuSeconds();
  volatile double spin = 0.0;
  auto wallSeconds = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart).count(); };
  while (currentThreadCpuSeconds() - cpuStart < 0.05 && wallSeconds() < 10.0) {
    for (int i = 0; i < 100000; ++i) spin = spin + 1.0;
  }
  const double computed = currentThreadCpuSeconds() - cpuStart;
  expect(computed >= 0.05 && computed < 10.0,
         "the thread's CPU clock runs while it computes: " + std::to_string(computed) + " s");
  const double beforeSleep = currentThreadCpuSeconds();
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  const double slept = currentThreadCpuSeconds() - beforeSleep;
  expect(slept >= 0.0 && slept < 0.1, "and stands still while it sleeps 0.2 s: " + std::to_string(slept) + " s");

  std::atomic<int> pixels{0};
  forEachPixel(37, 11, 4, [&](int, int) { pixels.fetch_add(1); });
  expect(pixels.load() == 37 * 11, "forEachPixel on 4 threads visits every pixel once");
}

}  // namespace

int main(int argc, char** argv) {
  if (argc >= 3 && std::string(argv[1]) == "--write-arguments") {  // started by runProgram's test
    std::string text;
    for (int i = 3; i < argc; ++i) text += std::string(argv[i]) + "\n";
    writeFileAtomically(argv[2], text);
    return 7;
  }
  try {
    run();
  } catch (const std::exception& e) {
    expect(false, std::string("stopped by an exception: ") + e.what());
  }
  std::printf("%d passed, %d failed\n", passes, failures);
  return failures == 0 ? 0 : 1;
}
