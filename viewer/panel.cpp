// The ImGui adapter: every ImGui call of the viewer is in this file.
#include "panel.h"

#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <cstdio>

namespace tissue::viewer {
namespace {

/// A row "name  value unit".
void figure(const char* name, double value, const char* unit) {
  ImGui::Text("%-9s %7.2f %s", name, value, unit);
}

/// The method switches: one radio button per method the organ offers.
void methodSwitches(const PanelView& v, PanelActions& a) {
  for (std::size_t i = 0; i < v.methods.size(); ++i) {
    if (i % 2) ImGui::SameLine(130);  // two columns: "texture-space" fits
    if (ImGui::RadioButton(v.methods[i].c_str(), v.method == i) && v.method != i) a.method = i;
  }
}

/// The settings of the method shown; a change returns new choices.
void methodSettings(const PanelView& v, PanelActions& a) {
  scene::MethodChoices c = v.choices;
  bool changed = false;
  const std::string& name = v.methods[v.method];
  if (name == "separable") {
    int kernel = int(std::find(kKernelModels.begin(), kKernelModels.end(), c.kernel) - kKernelModels.begin());
    std::vector<const char*> names;
    for (const auto& k : kKernelModels)
      names.push_back(k.c_str());
    if (ImGui::Combo("kernel", &kernel, names.data(), int(names.size())))
      c.kernel = kKernelModels[kernel], changed = true;
    if (ImGui::SliderInt("taps", &c.taps, 5, 63)) c.taps |= 1, changed = true;  // odd: a centre tap
  } else if (name == "texture-space") {
    changed = ImGui::SliderInt("Gaussians", &c.gaussians, 1, 8);
  } else if (name == "ray-march") {
    changed = ImGui::SliderInt("samples", &c.samples, 1, 128);
  } else {
    ImGui::TextDisabled("no settings");
  }
  if (changed) a.choices = c;  // the methods are rebuilt (a kernel fit takes milliseconds)
  if (!v.methodError.empty()) ImGui::TextColored(ImVec4(1.0f, 0.4f, 0.3f, 1.0f), "%s", v.methodError.c_str());
}

}  // namespace

Result<std::unique_ptr<Panel>> Panel::create(GLFWwindow* window) {
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini in the working folder
  ImGui::StyleColorsDark();
  if (!ImGui_ImplGlfw_InitForOpenGL(window, true)) {
    ImGui::DestroyContext();
    return Error{"ImGui: cannot attach to the GLFW window"};
  }
  if (!ImGui_ImplOpenGL3_Init("#version 330 core")) {
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    return Error{"ImGui: no OpenGL 3 functions (its loader could not open libGL)"};
  }
  return std::unique_ptr<Panel>(new Panel());
}

Panel::~Panel() {
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
}

PanelActions Panel::build(const PanelView& v) {
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
  PanelActions a;
  ImGui::SetNextWindowPos(ImVec2(6, 6), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(250, 0), ImGuiCond_FirstUseEver);
  ImGui::Begin("tissue");
  ImGui::Text("%s, frame %ld, %.1f fps", v.mode.c_str(), v.frame, v.fps);
  figure("simulate", v.ms.simulateMs, "ms");
  figure("mesh", v.ms.meshMs, "ms");
  figure("upload", v.ms.uploadMs, "ms");
  figure("render", v.ms.renderMs, "ms");
  figure("panel", v.panelMs, "ms");
  ImGui::Separator();
  char force[48];
  std::snprintf(force, sizeof force, "force %.3f N (of %.2g)", v.forceN, v.forceScaleN);
  ImGui::ProgressBar(float(std::clamp(v.forceN / v.forceScaleN, 0.0, 1.0)), ImVec2(-1, 0), force);
  ImGui::Text("contacts %u, depth %.0f mm", v.contacts, double(v.toolDepthMm));
  if (ImGui::Button(v.grasped ? "release (G)" : "grasp (G)")) a.toggleGrasp = true;
  ImGui::SameLine();
  ImGui::Text(v.grasped ? "holding %u" : "free", v.grasped);
  ImGui::Separator();
  // The frame budget (issue 16): the quality controller picks method and setting under it.
  float budget = v.budgetMs;
  if (ImGui::SliderFloat("budget ms", &budget, 0.0f, 100.0f, budget > 0.0f ? "%.1f" : "off"))
    a.budgetMs = budget;
  if (!v.budgetChoice.empty()) ImGui::TextWrapped("chosen: %s", v.budgetChoice.c_str());
  // Under a budget the controller owns the method: the switches show what it drew, greyed out,
  // and its setting is the "chosen" line's (the panel's own settings return with the budget off).
  ImGui::BeginDisabled(!v.budgetChoice.empty());
  methodSwitches(v, a);
  ImGui::EndDisabled();
  if (v.budgetChoice.empty()) methodSettings(v, a);
  if (ImGui::CollapsingHeader("tissue")) {
    for (const auto& line : v.tissue)
      ImGui::TextUnformatted(line.c_str());
    ImGui::TextDisabled("(edit the scenario file, then Reset)");
  }
  if (ImGui::Button("Reset")) a.reset = true;
  ImGui::SameLine();
  if (ImGui::Button(v.recording ? "stop recording (R)" : "record (R)")) a.toggleRecord = true;
  if (v.recording) {
    ImGui::SameLine();
    ImGui::Text("%ld", v.recordedFrames);
  }
  ImGui::End();
  return a;
}

void Panel::draw() {
  ImGui::Render();
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

bool Panel::wantsMouse() const {
  return ImGui::GetIO().WantCaptureMouse;
}

bool Panel::wantsKeyboard() const {
  return ImGui::GetIO().WantCaptureKeyboard;
}

}  // namespace tissue::viewer
