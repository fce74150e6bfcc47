#include "shell.h"

#include <GLFW/glfw3.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>
#include <imgui.h>

#include <chrono>
#include <cstdio>
#include <vector>

#include "util/error.h"
#include "util/image.h"

namespace pathlab::gui {
namespace {

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

}  // namespace

int runShell(const ShellOptions& options, const std::function<std::unique_ptr<ShellClient>()>& makeClient) {
  glfwSetErrorCallback([](int code, const char* text) { std::fprintf(stderr, "GLFW error %d: %s\n", code, text); });
  if (!glfwInit()) throw Error("cannot open a window (no display? run it on a desktop, or under xvfb-run)");
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 0);
  GLFWwindow* window = glfwCreateWindow(options.width, options.height, options.title.c_str(), nullptr, nullptr);
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
  auto shutdown = [&] {
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    glfwDestroyWindow(window);
    glfwTerminate();
  };
  try {
    std::unique_ptr<ShellClient> client = makeClient();
    const auto start = std::chrono::steady_clock::now();
    while (!glfwWindowShouldClose(window) && !client->quitRequested()) {
      glfwWaitEventsTimeout(0.05);
      ImGui_ImplOpenGL3_NewFrame();
      ImGui_ImplGlfw_NewFrame();
      ImGui::NewFrame();
      try {
        client->frame();
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
      if (std::optional<std::string> path = client->takeScreenshotRequest()) {
        writeImage(readFramebuffer(window), *path);
        std::printf("wrote %s\n", path->c_str());
        std::fflush(stdout);
      }
      glfwSwapBuffers(window);
      const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      if (options.timeout > 0.0 && elapsed > options.timeout) {
        std::fprintf(stderr, "%s: the script did not finish within %.0f s\n", options.program.c_str(), options.timeout);
        status = 1;
        break;
      }
    }
  } catch (...) {
    shutdown();
    throw;
  }
  shutdown();
  return status;
}

}  // namespace pathlab::gui
