#pragma once
/// \file
/// The main job (tissue-sim demo, scripts/run-main.sh): the default scenario run through the
/// trainee's loop on a headless context, its snapshots in every shading method, the scene a host
/// embeds, and the report (report.json, report.md). Any app or host can rerun it; tissue-sim
/// demo parses its options, calls runDemo and prints.

#include <filesystem>
#include <string>

#include "tissue/core/result.h"
#include "tissue/mesh/deformable_surface.h"
#include "tissue/scene/scene.h"
#include "tissue/studies/report.h"

namespace tissue::studies {

/// Settings of the main job (plain struct with defaults).
struct DemoConfig {
  std::filesystem::path outDir{};         ///< images, frames/, frames.csv, report.json, report.md (created)
  std::filesystem::path dataDir{};        ///< the project's data/: scenarios/, materials/, meshes/
  std::filesystem::path scenarioFile{};   ///< empty: dataDir/scenarios/liver_poke_grasp.json
  std::filesystem::path meshFile{};       ///< empty: the scenario's mesh; must have UVs and a material file
  int frames = 0;                         ///< 0: the scenario's
  int imageEvery = 100;                   ///< the loop's rendered frame is written every this many frames
  std::filesystem::path recordSession{};  ///< non-empty: write the run as a session (scene::SessionRecorder)
  int loopWidth = 480;                    ///< pixels of the frame the loop renders every frame
  int loopHeight = 360;                   ///< pixels
  int width = 960;                        ///< pixels of the snapshots and method renders
  int height = 720;                       ///< pixels
  bool logContext = true;                 ///< one stderr line naming the demo's headless context
};

/// What the main job hands back besides its images: the report it wrote (report.json and
/// report.md in outDir, every frame's contact force in the JSON) and the JSON object for stdout
/// (the same without the per-frame forces).
struct DemoRun {
  Report report;
  std::string json;
};

/// Runs the main job: `scene` gives the scenes' settings (material files, shared meshes, shaders,
/// the headless backend and EGL platform; the demo's scenes set their own MSAA, timers and GL).
/// Without a GL context it still simulates and reports ("render_skipped"). Writes into
/// config.outDir; errors name the file or option at fault.
Result<DemoRun> runDemo(const DemoConfig& config, const scene::SceneSettings& scene);

/// Frames organ 0 of `scene` (its shape `surface`) as the ray-march studies do
/// (rayMarchSceneFor: the whole organ, or with `closeUp` 40 mm around the poke site) and lights
/// it with their key and back lights, which stay; Scene::frameOrgans() frames it again.
Result<void> frameForRayMarch(scene::Scene& scene, const mesh::DeformableSurface& surface, float aspect,
                              bool closeUp);

}  // namespace tissue::studies
