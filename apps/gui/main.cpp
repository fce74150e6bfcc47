// pathlab-gui [SCENE] [--panel N] [--screenshot FILE.png] [--script FILE]
// The visual debugger (see app.h). With --screenshot it renders a few
// passes, shows panel N, saves the window and exits: tests, docs and CI run
// it under Xvfb.
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "app.h"
#include "pathlab/error.h"
#include "pathlab/scene_io.h"

#ifndef PATHLAB_TASK_SUMMARY
#define PATHLAB_TASK_SUMMARY "unknown"
#endif

namespace {

using namespace pathlab;

struct Arguments {
  std::string scene;
  int panel = 1;
  std::string screenshot;
  std::string script;
  int threads = 0;
  int width = 1500, height = 900;
  double timeout = 600.0;
};

// The back buffer as an image (rows flipped: OpenGL's row 0 is the bottom).
Image readFramebuffer(GLFWwindow* window) {
  int width = 0, height = 0;
  glfwGetFramebufferSize(window, &width, &height);
  std::vector<uint8_t> rgba(size_t(width) * size_t(height) * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadBuffer(GL_BACK);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  float decode[256];
  for (int v = 0; v < 256; ++v) decode[v] = srgbToLinear(float(v) / 255.0f);
  Image image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const uint8_t* p = &rgba[(size_t(height - 1 - y) * size_t(width) + size_t(x)) * 4];
      image.at(x, y) = Color(decode[p[0]], decode[p[1]], decode[p[2]]);
    }
  return image;
}

std::string readFile(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw Error(path + ": cannot read the script");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

int run(const Arguments& args) {
  gui::AppOptions options;
  options.panel = args.panel;
  options.threads = args.threads;
  options.taskSummary = PATHLAB_TASK_SUMMARY;
  if (!args.script.empty()) options.script = gui::parseScript(readFile(args.script), args.script);
  if (!args.screenshot.empty()) {
    if (!isWritableImagePath(args.screenshot)) throw Error("--screenshot: " + args.screenshot + ": use a .png file");
    // Show the panel after a few passes (16 spp, or all if fewer), then save.
    options.script.push_back({"wait-spp", {"16"}, 0});
    options.script.push_back({"wait-panel", {}, 0});
    options.script.push_back({"screenshot", {args.screenshot}, 0});
    options.script.push_back({"quit", {}, 0});
  }
  Scene scene = args.scene.empty() ? defaultScene() : loadScene(args.scene);

  glfwSetErrorCallback([](int code, const char* text) { std::fprintf(stderr, "pathlab-gui: GLFW error %d: %s\n", code, text); });
  if (!glfwInit()) throw Error("cannot open a window (no display? run it on a desktop, or under xvfb-run)");
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 0);
  GLFWwindow* window = glfwCreateWindow(args.width, args.height, "PathLab debugger", nullptr, nullptr);
  if (!window) {
    glfwTerminate();
    throw Error("cannot create an OpenGL 3.0 window");
  }
  glfwMakeContextCurrent(window);
  glfwSwapInterval(1);
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // the layout is fixed: no imgui.ini beside the user's files
  ImGui::StyleColorsDark();
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  ImGui_ImplOpenGL3_Init("#version 130");

  int status = 0;
  {
    gui::App app(std::move(scene), std::move(options));
    const auto start = std::chrono::steady_clock::now();
    while (!glfwWindowShouldClose(window) && !app.quitRequested()) {
      // Wake at least every 50 ms: results arrive from background threads.
      glfwWaitEventsTimeout(0.05);
      ImGui_ImplOpenGL3_NewFrame();
      ImGui_ImplGlfw_NewFrame();
      ImGui::NewFrame();
      try {
        app.frame();
      } catch (...) {
        ImGui::EndFrame();
        throw;
      }
      ImGui::Render();
      int width = 0, height = 0;
      glfwGetFramebufferSize(window, &width, &height);
      glViewport(0, 0, width, height);
      glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
      glClear(GL_COLOR_BUFFER_BIT);
      ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
      if (std::optional<std::string> path = app.takeScreenshotRequest()) {
        writeImage(readFramebuffer(window), *path);
        std::printf("wrote %s\n", path->c_str());
        std::fflush(stdout);
      }
      glfwSwapBuffers(window);
      const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      if (!args.script.empty() || !args.screenshot.empty()) {
        if (elapsed > args.timeout) {
          std::fprintf(stderr, "pathlab-gui: the script did not finish within %.0f s\n", args.timeout);
          status = 1;
          break;
        }
      }
    }
  }
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  glfwDestroyWindow(window);
  glfwTerminate();
  return status;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App cli("PathLab visual debugger: the render, a pixel inspector and one panel per task", "pathlab-gui");
  Arguments args;
  cli.add_option("scene", args.scene, "scene file (.json or .dae); default: the embedded Cornell box");
  cli.add_option("--panel", args.panel, "open on task N's panel (1-7)")->check(CLI::Range(1, 7));
  cli.add_option("--screenshot", args.screenshot,
                 "render, show the panel, save the window to FILE.png and exit (tests, docs, CI under xvfb-run)");
  cli.add_option("--script", args.script, "run the commands in FILE (see apps/gui/script.h), then keep going");
  cli.add_option("-t,--threads", args.threads, "render threads (default: all)")->check(CLI::Range(0, 1024));
  cli.add_option("--window", args.width, "window width in pixels")->check(CLI::Range(640, 8192));
  cli.add_option("--timeout", args.timeout, "seconds a --script or --screenshot run may take (default 600)")
      ->check(CLI::Range(1.0, 86400.0));
  cli.set_version_flag("--version", "pathlab-gui 0.1 (tasks " PATHLAB_TASK_SUMMARY ")");
  try {
    cli.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return cli.exit(e);
  }
  args.height = args.width * 3 / 5;
  try {
    return run(args);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "pathlab-gui: %s\n", e.what());
    return 1;
  }
}
