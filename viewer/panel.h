#pragma once
/// \file
/// The viewer's control panel (Dear ImGui 1.86, GLFW and OpenGL 3 back ends): frame rate and
/// per-phase ms, the contact force with a bar, the shading method with its settings, the
/// tissue's parameters, the grasp and the recording. ImGui stays inside panel.cpp; ImGui's
/// OpenGL back end saves and restores the GL state it touches, and the renderer restores the
/// host's state after renderTo, so the two never see each other's state.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "tissue/core/result.h"
#include "tissue/scene/organ_loop.h"
#include "tissue/scene/organ_methods.h"

struct GLFWwindow;

namespace tissue::viewer {

/// The separable kernel models the panel offers (scene::MethodChoices::kernel).
inline const std::vector<std::string> kKernelModels{"preintegrated", "svd", "deon", "jimenez", "guided"};

/// What the panel shows this frame.
struct PanelView {
  double fps = 0.0;                  ///< frames/s over the last report window
  scene::LoopPhases ms;              ///< mean ms per loop phase over the last report window
  double panelMs = 0.0;              ///< ms, the panel itself
  double presentMs = 0.0;            ///< ms, the buffer swap
  double forceN = 0.0;               ///< N, |F| on the tool in the last frame
  double forceScaleN = 2.0;          ///< N, the force bar's full length
  std::uint32_t contacts = 0;        ///< vertices the tool touched
  std::uint32_t grasped = 0;         ///< vertices held
  float toolDepthMm = 0.0f;          ///< mm past the picked point
  std::vector<std::string> methods;  ///< names offered
  std::size_t method = 0;            ///< index of the method shown
  scene::MethodChoices choices;      ///< their settings
  std::string methodError;           ///< why the last change of settings failed (empty: none)
  std::vector<std::string> tissue;   ///< lines describing the scenario's springs, damping, mass
  std::string mode;                  ///< "interactive", "scripted" or "replay"
  long frame = 0;
  bool recording = false;
  long recordedFrames = 0;
  float budgetMs = 0.0f;     ///< ms, the frame budget (0: off)
  std::string budgetChoice;  ///< what the quality controller chose (empty: off)
};

/// What the user did in the panel.
struct PanelActions {
  std::optional<std::size_t> method;            ///< switch to this method
  std::optional<scene::MethodChoices> choices;  ///< rebuild the methods with these settings
  bool reset = false;                           ///< rebuild the loop from the scenario
  bool toggleGrasp = false;
  bool toggleRecord = false;
  std::optional<float> budgetMs;  ///< ms, a new frame budget (0: off)
};

/// The panel on one window. Not copyable.
class Panel {
 public:
  /// Sets ImGui up on `window` (its GL 3.3 context current); its GLFW callbacks chain to the
  /// window's own. Fails when ImGui's GL loader finds no GL 3 functions.
  static Result<std::unique_ptr<Panel>> create(GLFWwindow* window);
  ~Panel();
  Panel(const Panel&) = delete;
  Panel& operator=(const Panel&) = delete;

  /// Starts the ImGui frame and lays the panel out; returns what the user changed.
  PanelActions build(const PanelView& view);
  /// Draws the panel into the bound framebuffer, over the scene.
  void draw();
  /// Whether ImGui takes the mouse or keyboard this frame (the viewer then ignores them).
  bool wantsMouse() const;
  bool wantsKeyboard() const;

 private:
  Panel() = default;
};

}  // namespace tissue::viewer
