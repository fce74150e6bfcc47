#include "app.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <sstream>

#include "core/camera.h"
#include "core/task_list.h"
#include "render/task_wiring.h"
#include "util/error.h"
#include "util/progress.h"
#include "util/todo.h"

namespace pathlab::gui {
namespace {

// The integrator menu: each of render.h's kIntegrators as "name (the tasks it runs)".
const std::vector<std::string>& integratorMenu() {
  static const std::vector<std::string> menu = [] {
    std::vector<std::string> items;
    for (const IntegratorEntry& entry : kIntegrators) items.push_back(std::string(entry.name) + " (" + entry.runs + ")");
    return items;
  }();
  return menu;
}
constexpr int kInspectedSamples = 16;
const ImVec4 kWarning(1.0f, 0.45f, 0.35f, 1.0f), kGood(0.5f, 0.9f, 0.5f, 1.0f), kDim(0.65f, 0.65f, 0.65f, 1.0f);

std::vector<TodoReached> todosOfTask(int task) {
  std::vector<TodoReached> result;
  char prefix[8];
  std::snprintf(prefix, sizeof prefix, "T%d.", task);
  for (const TodoReached& todo : todosReached())
    if (todo.tag.rfind(prefix, 0) == 0) result.push_back(todo);
  return result;
}

}  // namespace

// The views of every task, made once: panels keep pointers into it.
std::vector<const DebugView*> viewsOfTask(int task) {
  static const std::vector<DebugView> all = allDebugViews();
  std::vector<const DebugView*> result;
  for (const DebugView& view : all)
    if (view.task == task) result.push_back(&view);
  return result;
}

namespace {

// Where an image of `size` pixels lands when fitted into `available`
// keeping its aspect ratio.
float fitScale(ImVec2 available, int width, int height) {
  return std::max(0.05f, std::min(available.x / float(width), available.y / float(height)));
}

// An image drawn as an ImGui item, and the image pixel under the mouse.
struct ShownImage {
  bool hovered = false;
  Point2 mousePixel{0.0f};  // in image pixels
};

ShownImage showImage(const Texture& texture, float scale) {
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  ImGui::Image(texture.imguiId(), ImVec2(float(texture.width()) * scale, float(texture.height()) * scale));
  ShownImage shown;
  shown.hovered = ImGui::IsItemHovered();
  const ImVec2 mouse = ImGui::GetMousePos();
  shown.mousePixel = Point2((mouse.x - origin.x) / scale, (mouse.y - origin.y) / scale);
  return shown;
}

// A click is a press and release without dragging.
bool clicked(ImGuiMouseButton button) {
  if (!ImGui::IsMouseReleased(button)) return false;
  const ImVec2 drag = ImGui::GetMouseDragDelta(button, 0.0f);
  return drag.x * drag.x + drag.y * drag.y < 9.0f;
}

}  // namespace

App::App(Scene scene, AppOptions options)
    : base_(std::move(scene)),
      options_(std::move(options)),
      camera_(base_.camera),
      width_(base_.render.width),
      height_(base_.render.height),
      spp_(base_.render.samplesPerPixel),
      maxDepth_(base_.render.maxDepth),
      lightSamples_(base_.render.lightSamples),
      renderWorker_([](const RenderJob& job, const std::atomic<bool>& cancel,
                       const std::function<void(RenderFrame)>& publish) {
        RenderOptions renderOptions = job.options;
        renderOptions.cancel = &cancel;
        ProgressiveRender progressive(*job.scene, renderOptions);
        while (progressive.step()) publish({progressive.image(), progressive.stats(), job.generation});
        if (!cancel) publish({progressive.image(), progressive.stats(), job.generation});
      }),
      viewWorker_([](const ViewJob& job, const std::atomic<bool>&, const std::function<void(ViewResult)>& publish) {
        ViewResult result;
        result.key = job.key;
        try {
          DebugViewRequest request(*job.scene, job.scene->render.width, job.scene->render.height);
          request.pixel = job.pixel;
          request.depth = job.depth;
          request.viewCamera = job.viewCamera;
          request.threads = job.threads;
          result.output = job.view->render(request);
        } catch (const std::exception& e) {
          result.error = e.what();
        }
        publish(std::move(result));
      }) {
  // "1:reference 2:student ..." -> which tasks run the student's code.
  std::istringstream summary(options_.taskSummary);
  for (std::string entry; summary >> entry;) {
    const int task = std::atoi(entry.c_str());
    if (task >= 1 && task <= kTaskCount) studentTask_[size_t(task)] = entry.find("student") != std::string::npos;
  }
  if (options_.panel >= 1 && options_.panel <= kTaskCount) selectedTab_ = options_.panel;
  restartRender();
  inspect(IVec2(width_ / 2, height_ / 2));  // the pixel the views inspect until one is clicked
}

// ---- Scene and render -------------------------------------------------------

void App::restartRender() {
  auto scene = std::make_shared<Scene>(base_);
  scene->camera = camera_;
  scene->render.width = width_;
  scene->render.height = height_;
  scene->render.samplesPerPixel = spp_;
  scene->render.maxDepth = maxDepth_;
  scene->render.lightSamples = lightSamples_;
  scene_ = scene;
  RenderOptions renderOptions;
  renderOptions.integrator = kIntegrators[integrator_].integrator;
  renderOptions.progress = false;
  renderOptions.threads = options_.threads;
  renderOptions.maxPassSpp = 4;  // refresh the window often
  renderOptions.traversal = defaultTraversal(options_.taskSummary);
  renderWorker_.submit({scene_, renderOptions, ++generation_});
  renderCurrent_ = false;
  if (pixel_ && (pixel_->x >= width_ || pixel_->y >= height_)) pixel_.reset();
  inspectionStale_ = pixel_.has_value();  // re-traced in frame(), once no drag is under way
}

void App::takeResults() {
  if (std::optional<RenderFrame> frame = renderWorker_.take()) {
    if (frame->generation == generation_) {
      renderImage_ = std::move(frame->image);
      renderStats_ = frame->stats;
      renderTexture_.upload(renderImage_, exposure_);
      renderCurrent_ = renderStats_.completedSpp >= spp_;
    }
  }
  if (std::optional<ViewResult> result = viewWorker_.take()) {
    shownKey_ = result->key;
    viewError_ = result->error;
    viewOutput_ = std::move(result->output);
    if (viewError_.empty()) viewTexture_.upload(viewOutput_.image, 0.0f);
  }
}

void App::inspect(IVec2 pixel) {
  pixel_ = pixel;
  inspectionStale_ = false;
  if (!inspectionAccelerator_) {
    inspectionAccelerator_ = std::make_unique<const Accelerator>(base_);
    inspectionLights_ = std::make_unique<const Lights>(Lights::fromScene(base_, kLinkedTasks.environment));
  }
  RenderOptions renderOptions;
  renderOptions.integrator = kIntegrators[integrator_].integrator;
  inspection_ = inspectPixel(*scene_, *inspectionAccelerator_, *inspectionLights_, renderOptions, pixel,
                             std::min(spp_, kInspectedSamples));
}

bool App::panelSettled() const {
  if (selectedTab_ == kLabPanel) return lab_.settled();
  const std::vector<const DebugView*> panelViews = viewsOfTask(selectedTab_);
  return panelViews.empty() ||
         (shownKey_ == viewKey(*panelViews[size_t(selectedView_[size_t(selectedTab_)])]) && viewWorker_.idle());
}

bool App::settled() const { return renderCurrent_ && renderWorker_.idle() && panelSettled(); }

void App::frame() {
  takeResults();
  // Re-inspect after the camera or settings changed, but not on every frame
  // of a drag: the list would flicker, and 16 re-traced paths cost a few ms.
  if (inspectionStale_ && !ImGui::IsMouseDown(ImGuiMouseButton_Left) && !ImGui::IsMouseDown(ImGuiMouseButton_Right)) {
    inspect(*pixel_);
  }
  runScript();
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  const float renderWidth = std::floor(display.x * 0.52f);
  drawRenderWindow(renderWidth, display.y);
  drawSidePanel(renderWidth, display.x - renderWidth, display.y);
}

void App::drawRenderWindow(float width, float height) {
  ImGui::SetNextWindowPos(ImVec2(0, 0));
  ImGui::SetNextWindowSize(ImVec2(width, height));
  ImGui::Begin("Render", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
  const RenderStats& stats = renderStats_;
  ImGui::Text("%s  %dx%d  %d/%d spp  %.1f s  %s rays/s", base_.source.c_str(), width_, height_, stats.completedSpp,
              spp_, stats.seconds, formatRate(stats.seconds > 0 ? double(stats.rays) / stats.seconds : 0.0).c_str());
  if (stats.nonFiniteSamples > 0) {
    ImGui::TextColored(kWarning, "%llu NaN/Inf samples (first at pixel %d,%d): left out of the image",
                       (unsigned long long)stats.nonFiniteSamples, stats.firstNonFinitePixel->x,
                       stats.firstNonFinitePixel->y);
  }
  ImGui::TextColored(kDim, "click: inspect a pixel   drag: orbit   right-drag: pan   wheel: zoom");
  if (!renderTexture_.empty()) {
    const ImVec2 available = ImGui::GetContentRegionAvail();
    const float scale = fitScale(ImVec2(available.x, available.y * 0.6f), renderTexture_.width(), renderTexture_.height());
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    const ShownImage shown = showImage(renderTexture_, scale);
    if (pixel_) {  // the inspected pixel, outlined
      ImGui::GetWindowDrawList()->AddRect(
          ImVec2(origin.x + float(pixel_->x) * scale - 2, origin.y + float(pixel_->y) * scale - 2),
          ImVec2(origin.x + float(pixel_->x + 1) * scale + 2, origin.y + float(pixel_->y + 1) * scale + 2),
          IM_COL32(255, 255, 60, 255));
    }
    const ImGuiIO& io = ImGui::GetIO();
    bool moved = false;
    if (shown.hovered && clicked(ImGuiMouseButton_Left)) {
      inspect(IVec2(std::clamp(int(shown.mousePixel.x), 0, width_ - 1), std::clamp(int(shown.mousePixel.y), 0, height_ - 1)));
    } else if (shown.hovered && ImGui::IsMouseDragging(ImGuiMouseButton_Left)) {
      camera_ = orbitCamera(camera_, -0.3f * io.MouseDelta.x, 0.3f * io.MouseDelta.y);
      moved = io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f;
    } else if (shown.hovered && ImGui::IsMouseDragging(ImGuiMouseButton_Right)) {
      camera_ = panCamera(camera_, Vec2(io.MouseDelta.x, io.MouseDelta.y) / scale, height_);
      moved = io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f;
    }
    if (shown.hovered && io.MouseWheel != 0.0f) {
      camera_ = dollyCamera(camera_, std::pow(0.9f, io.MouseWheel));
      moved = true;
    }
    if (moved) restartRender();
  }
  ImGui::Separator();
  ImGui::BeginChild("inspector", ImVec2(0, 0), false, ImGuiWindowFlags_HorizontalScrollbar);
  drawInspector();
  ImGui::EndChild();
  ImGui::End();
}

// ---- Right-hand side ------------------------------------------------------------

void App::drawSidePanel(float x, float width, float height) {
  ImGui::SetNextWindowPos(ImVec2(x, 0));
  ImGui::SetNextWindowSize(ImVec2(width, height));
  ImGui::Begin("PathLab debugger", nullptr,
               ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
  drawSettings();
  drawPanelSelector();
  ImGui::Separator();
  ImGui::BeginChild("panel", ImVec2(0, 0), false, ImGuiWindowFlags_HorizontalScrollbar);
  if (selectedTab_ == kLabPanel) {
    lab_.draw();
  } else {
    drawTaskPanel(selectedTab_);
  }
  ImGui::EndChild();
  ImGui::End();
}

// One button per task and the lab's, wrapped into as many rows as the panel's
// width needs, so every label stays whole however many tasks there are. A task
// with a TODO left is marked; one the course does not hand out is dimmed.
void App::drawPanelSelector() {
  const ImGuiStyle& style = ImGui::GetStyle();
  const float right = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
  selectorLabels_.clear();
  selectorRows_ = 1, selectorCut_ = 0;
  for (int tab = 1; tab <= kLabPanel; ++tab) {
    char label[64];
    const bool todo = tab != kLabPanel && !todosOfTask(tab).empty();
    if (tab == kLabPanel) {
      std::snprintf(label, sizeof label, "Lab###panel-lab");
    } else {
      std::snprintf(label, sizeof label, "%d %s%s###panel%d", tab, kTaskLabels[tab], todo ? " (TODO)" : "", tab);
    }
    const float width = ImGui::CalcTextSize(label, nullptr, true).x + 2.0f * style.FramePadding.x;
    if (tab > 1 && ImGui::GetItemRectMax().x + style.ItemSpacing.x + width <= right) {
      ImGui::SameLine();
    } else if (tab > 1) {
      ++selectorRows_;
    }
    const bool selected = tab == selectedTab_, dim = tab != kLabPanel && !kTaskHandedOut[tab];
    ImGui::PushStyleColor(ImGuiCol_Button, style.Colors[selected ? ImGuiCol_ButtonActive : ImGuiCol_FrameBg]);
    ImGui::PushStyleColor(ImGuiCol_Text, todo ? kWarning : dim ? kDim : style.Colors[ImGuiCol_Text]);
    if (ImGui::Button(label)) selectedTab_ = tab;
    ImGui::PopStyleColor(2);
    selectorLabels_.emplace_back(label, std::strcspn(label, "#"));
    if (ImGui::GetItemRectMax().x > right + 0.5f) ++selectorCut_;
    if (ImGui::IsItemHovered()) {
      if (tab == kLabPanel) {
        ImGui::SetTooltip("The sampling lab: every warp against its pdf");
      } else {
        ImGui::SetTooltip("Task %d: %s%s%s", tab, kTaskTitles[tab], todo ? "\na TODO is not done yet" : "",
                          dim ? "\nnot handed out in this course: the reference runs" : "");
      }
    }
  }
}

void App::drawSettings() {
  if (!ImGui::CollapsingHeader("Settings", ImGuiTreeNodeFlags_DefaultOpen)) return;
  bool changed = false;
  ImGui::PushItemWidth(140);
  int size[2] = {width_, height_};
  if (ImGui::InputInt2("resolution", size, ImGuiInputTextFlags_EnterReturnsTrue)) {
    width_ = std::clamp(size[0], 8, 4096), height_ = std::clamp(size[1], 8, 4096);
    changed = true;
  }
  ImGui::SameLine();
  changed |= ImGui::Combo(
      "integrator", &integrator_,
      [](void*, int i, const char** text) { return *text = integratorMenu()[size_t(i)].c_str(), true; }, nullptr,
      int(std::size(kIntegrators)));
  changed |= ImGui::SliderInt("spp", &spp_, 1, 4096, "%d", ImGuiSliderFlags_Logarithmic);
  ImGui::SameLine();
  changed |= ImGui::SliderInt("max depth (-m)", &maxDepth_, 0, 16);
  changed |= ImGui::SliderInt("light samples (-l)", &lightSamples_, 1, 64, "%d", ImGuiSliderFlags_Logarithmic);
  ImGui::SameLine();
  if (ImGui::SliderFloat("exposure", &exposure_, -6.0f, 6.0f, "%+.1f stops") && !renderImage_.pixels.empty()) {
    renderTexture_.upload(renderImage_, exposure_);  // display only: no re-render
  }
  int threads = options_.threads;
  if (ImGui::SliderInt("threads (0: all)", &threads, 0, 64)) {
    options_.threads = threads;
    changed = true;
  }
  ImGui::SameLine();
  if (ImGui::Button("reset camera")) {
    camera_ = base_.camera;
    changed = true;
  }
  ImGui::PopItemWidth();
  if (changed) restartRender();

  // Which code runs, and what is not done yet: wrapped, so that any number of tasks shows whole.
  ImGui::Text("tasks:");
  for (int task = 1; task <= kTaskCount; ++task) {
    const bool undone = !todosOfTask(task).empty();
    char text[48];
    std::snprintf(text, sizeof text, "%d:%s%s", task, studentTask_[size_t(task)] ? "yours" : "reference",
                  undone ? "(TODO)" : "");
    ImGui::SameLine();
    if (ImGui::GetContentRegionAvail().x < ImGui::CalcTextSize(text).x) ImGui::NewLine();
    ImGui::TextColored(undone ? kWarning : (studentTask_[size_t(task)] ? kGood : kDim), "%s", text);
  }
}

void App::drawInspector() {
  if (!pixel_) return;
  ImGui::TextColored(kDim, "Inspector: the clicked pixel's first %d samples, traced again with the render's random numbers",
                     kInspectedSamples);
  const PixelInspection& inspection = inspection_;
  ImGui::Text("pixel %d,%d: %zu samples, mean (%.4f, %.4f, %.4f), integrator %s", inspection.pixel.x,
              inspection.pixel.y, inspection.samples.size(), double(inspection.mean.x), double(inspection.mean.y),
              double(inspection.mean.z), kIntegrators[integrator_].name);
  if (renderCurrent_ && inspection.pixel.x < renderImage_.width && inspection.pixel.y < renderImage_.height) {
    const Color shown = renderImage_.at(inspection.pixel.x, inspection.pixel.y);
    ImGui::TextColored(kDim, "rendered pixel (all %d spp): (%.4f, %.4f, %.4f)", spp_, double(shown.x),
                       double(shown.y), double(shown.z));
  }
  if (inspection.nonFinite > 0) ImGui::TextColored(kWarning, "%d samples are NaN or Inf", inspection.nonFinite);
  for (const InspectedSample& sample : inspection.samples) {
    char label[160];
    std::snprintf(label, sizeof label, "sample %u at (%.3f, %.3f): L = (%.4f, %.4f, %.4f), %zu rays%s###s%u",
                  sample.index, double(sample.raster.x), double(sample.raster.y), double(sample.radiance.x),
                  double(sample.radiance.y), double(sample.radiance.z), sample.rays.size(),
                  sample.finite ? "" : "  NaN/Inf!", sample.index);
    if (!sample.finite) ImGui::PushStyleColor(ImGuiCol_Text, kWarning);
    const bool open = ImGui::TreeNodeEx(label, sample.index < 2 ? ImGuiTreeNodeFlags_DefaultOpen : 0);
    if (!sample.finite) ImGui::PopStyleColor();
    if (!open) continue;
    for (const std::string& line : sample.lines) {
      const bool blocked = line.find("BLOCKED") != std::string::npos;
      ImGui::TextColored(blocked ? kWarning : ImGui::GetStyleColorVec4(ImGuiCol_Text), "%s", line.c_str());
    }
    ImGui::TreePop();
  }
}

std::string App::viewKey(const DebugView& view) const {
  std::string key = std::to_string(view.task) + "/" + view.name + "@" + std::to_string(generation_);
  if (view.inputs & kUsesPixel) {
    key += " pixel " + (pixel_ ? std::to_string(pixel_->x) + "," + std::to_string(pixel_->y) : std::string("centre"));
  }
  if (view.inputs & kUsesDepth) key += " depth " + std::to_string(depth_);
  if ((view.inputs & kUsesViewCamera) && viewCamera_) {
    char camera[96];
    std::snprintf(camera, sizeof camera, " from %.4f,%.4f,%.4f", double(viewCamera_->position.x),
                  double(viewCamera_->position.y), double(viewCamera_->position.z));
    key += camera;
  }
  return key;
}

void App::drawTaskPanel(int task) {
  const std::vector<const DebugView*> panelViews = viewsOfTask(task);
  ImGui::Text("Task %d: %s", task, kTaskTitles[task]);
  ImGui::SameLine();
  if (studentTask_[size_t(task)]) {
    ImGui::TextColored(kGood, "your code: %s", kTaskFiles[task]);
  } else {
    ImGui::TextColored(kDim, "reference solution");
  }
  for (const TodoReached& todo : todosOfTask(task)) {
    ImGui::TextColored(kWarning, "TODO %s not done yet: %s:%d (its result is a placeholder)", todo.tag.c_str(),
                       todo.file.c_str(), todo.line);
  }
  if (panelViews.empty()) return;
  int& selected = selectedView_[size_t(task)];
  for (size_t i = 0; i < panelViews.size(); ++i) {
    if (i > 0) ImGui::SameLine();
    ImGui::RadioButton(panelViews[i]->name.c_str(), &selected, int(i));
  }
  const DebugView& view = *panelViews[size_t(selected)];
  ImGui::TextColored(kDim, "%s", view.description.c_str());
  if (view.inputs & kUsesDepth) ImGui::SliderInt("depth", &depth_, 0, int(kMaxBvhDepth));
  if (view.inputs & kUsesViewCamera) {
    ImGui::TextColored(kDim, "drag the picture to see it from elsewhere");
    if (viewCamera_) {
      ImGui::SameLine();
      if (ImGui::SmallButton("back to the render's camera")) viewCamera_.reset();
    }
  }

  // Recompute the view when what it reads has changed.
  const std::string key = viewKey(view);
  if (key != submittedKey_ && key != shownKey_) {
    viewWorker_.submit({&view, scene_, pixel_.value_or(IVec2(-1, -1)), depth_,
                        (view.inputs & kUsesViewCamera) ? viewCamera_ : std::nullopt, options_.threads, key});
    submittedKey_ = key;
  }
  const bool current = shownKey_ == key;
  if (!current) ImGui::TextColored(kDim, "computing...");
  if (!viewError_.empty()) {
    ImGui::TextColored(kWarning, "this view failed: %s", viewError_.c_str());
    return;
  }
  if (viewTexture_.empty() || shownKey_.rfind(std::to_string(task) + "/" + view.name + "@", 0) != 0) return;

  const ImVec2 available = ImGui::GetContentRegionAvail();
  const float scale = fitScale(ImVec2(available.x, std::max(200.0f, available.y * 0.62f)), viewTexture_.width(),
                               viewTexture_.height());
  const ShownImage shown = showImage(viewTexture_, scale);
  const ImGuiIO& io = ImGui::GetIO();
  if (shown.hovered && (view.inputs & kUsesViewCamera) && ImGui::IsMouseDragging(ImGuiMouseButton_Left) &&
      (io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f)) {
    viewCamera_ = orbitCamera(viewCamera_.value_or(camera_), -0.3f * io.MouseDelta.x, 0.3f * io.MouseDelta.y);
  } else if (shown.hovered && (view.inputs & kCameraImage) && !viewCamera_ && clicked(ImGuiMouseButton_Left) &&
             shown.mousePixel.x < float(width_) && shown.mousePixel.y < float(height_)) {
    inspect(IVec2(shown.mousePixel));
  }
  ImGui::TextUnformatted(viewOutput_.report.c_str());
}

}  // namespace pathlab::gui
