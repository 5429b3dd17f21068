#pragma once
/// \file
/// What the viewer's frames share, and the steps that build or rebuild it: the organ (the
/// scenario that moves it, and its assets from the scene module: mesh, material, textures), the
/// loop from the scenario (and Reset), the renderer's textures and methods, the recording.

#include <fstream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "glfw_window.h"
#include "instrument_control.h"
#include "orbit_camera.h"
#include "panel.h"
#include "tissue/quality/controller.h"
#include "tissue/render/renderer.h"
#include "tissue/scenario/scenario.h"
#include "tissue/scene/budget.h"
#include "tissue/scene/option_catalog.h"
#include "tissue/scene/organ_assets.h"
#include "tissue/scene/organ_loop.h"
#include "tissue/scene/organ_methods.h"
#include "tissue/scene/session.h"
#include "viewer_app.h"

namespace tissue::viewer {

class FrameTimer;

/// The panel's defaults: the main job's, with the ray march at the panel's fixed sample count
/// (François et al. 2006 Algorithm 2 per pixel) rather than adaptive.
scene::MethodChoices viewerChoices();

/// Everything the frames share. Members die in reverse order: the loop (its meshes), the panel
/// and the renderer before the window whose context they need.
struct Viewer {
  scenario::Scenario scenario;  ///< what moves the organ (springs, mass, pins, instrument)
  scene::OrganAssets organ;     ///< the scenario's mesh with UVs (mm), its material and textures
  std::unique_ptr<Window> window;
  std::optional<render::Renderer> renderer;
  std::unique_ptr<Panel> panel;
  std::optional<scene::OrganLoop> loop;
  std::size_t inspectView = 0;  ///< the view key I shows next (tissue::inspect::kInspectionViews)
  std::optional<OrbitCamera> orbit;
  std::optional<InstrumentControl> tool;        ///< the interactive instrument
  Bounds3 box;                                  ///< mm, the rest shape's bounding box (the home view)
  render::Scene scene;                          ///< objects[0] the organ, then the instrument
  scene::OrganTextures textures;                ///< the organ's, on the renderer
  std::vector<render::MethodSettings> methods;  ///< what M and the panel switch between
  std::size_t method = 0;                       ///< the organ's method now, an index into methods
  scene::MethodChoices choices = viewerChoices();
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
  // The frame budget (issue 16): the quality controller chooses the organ's method and setting.
  double budgetMs = 0.0;  ///< ms; 0: off (the panel's method)
  std::optional<quality::QualityController> controller;
  std::optional<scene::BudgetChoice> budgetChoice;  ///< the last frame's choice
  int budgetOption = -1;                            ///< the table option of budgetMethod
  render::MethodSettings budgetMethod;
  scene::OptionCatalog budgetOptions;  ///< the organ's options, their settings built off the frame path
};

/// With a budget: the controller's choice for this frame (camera, `width` x `height`) as the
/// organ's method (after applyMethod). Errors when an option cannot be built.
Result<void> applyBudget(Viewer& v, int width, int height);
/// The last frame's measured passes (the organ's method's) and whole frame (ms) for the controller.
void learnBudget(Viewer& v, double frameMs);

/// Loads `scenarioFile` (tissue::scenario; meshes also from folders.shared/meshes; it must have an
/// instrument) and its organ through scene::loadOrganAssets: the scenario's mesh, the material
/// data/materials/<mesh stem>.json when there is one (else the default organ material) and the
/// textures it names (the generated 1024^2 ones first). Errors name the file.
Result<void> loadOrgan(Viewer& v, const std::filesystem::path& scenarioFile, const DataFolders& folders);

/// The name of a method ("lit", "separable", "texture-space", "ray-march", "parallax").
std::string methodName(const render::MethodSettings& method);
/// The method drawn this frame: the budget's choice ("<method> <setting>") under a budget, else
/// the panel's method.
std::string drawnMethod(const Viewer& v);
/// The index of the method called `name` in `methods`; the error says which names this organ offers.
Result<std::size_t> findMethod(const std::vector<render::MethodSettings>& methods, const std::string& name);

/// Creates (or, after Reset, re-creates) the loop from the scenario, with the planes uploaded
/// (ray marching needs them), and the interactive instrument at the scenario's start pose.
Result<void> createLoop(Viewer& v);
/// Creates the renderer on the window's context, uploads the organ (the loop's mesh and the
/// instrument) and its textures, and builds the shading methods (`initialMethod` first shown).
Result<void> setUpRendering(Viewer& v, const std::string& initialMethod);
/// Rebuilds the methods with `choices`, keeping the method shown.
Result<void> rebuildMethods(Viewer& v, const scene::MethodChoices& choices);
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
