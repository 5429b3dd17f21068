#pragma once
/// \file
/// What the viewer's frames share, and the steps that build or rebuild it: the loop from the
/// scenario (and Reset), the renderer's textures and methods, the recording.

#include <fstream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "glfw_window.h"
#include "instrument_control.h"
#include "orbit_camera.h"
#include "organ_assets.h"
#include "organ_methods.h"
#include "panel.h"
#include "tissue/render/renderer.h"
#include "tissue/scene/organ_loop.h"
#include "tissue/scene/session.h"

namespace tissue::viewer {

class FrameTimer;

/// Everything the frames share. Members die in reverse order: the loop (its meshes), the panel
/// and the renderer before the window whose context they need.
struct Viewer {
  explicit Viewer(OrganAssets assets) : organ(std::move(assets)) {}

  OrganAssets organ;
  std::unique_ptr<Window> window;
  std::optional<render::Renderer> renderer;
  std::unique_ptr<Panel> panel;
  std::optional<scene::OrganLoop> loop;
  std::optional<OrbitCamera> orbit;
  std::optional<InstrumentControl> tool;  ///< the interactive instrument
  Float3 boxLo, boxHi;                    ///< mm, the rest shape's bounding box (the home view)
  render::Scene scene;                    ///< objects[0] the organ, then the instrument
  render::TextureHandle normalMap;        ///< none: the organ has no normal map
  LayerTextures layers;
  std::vector<render::MethodSettings> methods;  ///< what M and the panel switch between
  std::size_t method = 0;                       ///< the organ's method now, an index into methods
  MethodChoices choices;
  std::string methodError;
  bool normalMapping = true;
  bool scripted = false;  ///< the scenario's own path, no input
  bool grasping = false;  ///< the interactive grasp state commanded
  std::optional<scene::Session> replay;
  std::optional<scene::SessionRecorder> recorder;
  std::filesystem::path recordFile;
  std::ofstream log;
  scene::LoopFrame last;  ///< the last frame's figures
  double maxForceN = 0.0;
  double fps = 0.0;
};

/// Creates (or, after Reset, re-creates) the loop from the scenario, with the planes uploaded
/// (ray marching needs them), and the interactive instrument at the scenario's start pose.
Result<void> createLoop(Viewer& v);
/// Creates the renderer on the window's context, uploads the organ (the loop's mesh and the
/// instrument) and its textures, and builds the shading methods (`initialMethod` first shown).
Result<void> setUpRendering(Viewer& v, const std::string& initialMethod);
/// Rebuilds the methods with `choices`, keeping the method shown.
Result<void> rebuildMethods(Viewer& v, const MethodChoices& choices);
/// Shows the organ with methods[method]; shadow maps when it scatters.
void applyMethod(Viewer& v);
/// Reset: a new loop from the scenario, attached; an ongoing recording is saved and stopped.
Result<void> resetLoop(Viewer& v);
/// Starts recording, or stops and saves (scene::saveSession into v.recordFile).
Result<void> toggleRecording(Viewer& v);
/// The per-frame CSV line (when logging) and the largest force.
void logFrame(Viewer& v, const FrameTimer& timer, const scene::LoopFrame& f);
/// The scenario's tissue parameters as short lines for the panel (units included).
std::vector<std::string> tissueLines(const scenario::Scenario& s);

}  // namespace tissue::viewer
