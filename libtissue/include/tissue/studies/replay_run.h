#pragma once
/// \file
/// A recorded session (scene/session.h) re-run headless through the trainee's loop,
/// deterministically: the same thread count gives bit-identical positions, fingerprinted by
/// positions_sha256. With `render` every frame is also uploaded and rendered (the
/// deformation-plus-render performance test). tissue-sim replay parses, calls and prints.

#include <filesystem>
#include <string>

#include "tissue/core/result.h"
#include "tissue/scene/scene.h"

namespace tissue::studies {

/// What to replay and what to write (plain struct with defaults).
struct ReplayConfig {
  std::filesystem::path session{};  ///< the session file (data/sessions/*.json, docs/SESSIONS.md)
  bool render = false;              ///< also upload and render every frame (lit, offscreen)
  std::filesystem::path outDir{};   ///< non-empty: report.json, frames.csv and (render) frame images
  int width = 480;                  ///< pixels of the rendered frames
  int height = 360;                 ///< pixels
  int imageEvery = 100;             ///< with render and outDir: every this many frames an image
  bool logContext = true;           ///< one stderr line naming the headless context (render)
  std::filesystem::path pvdDir{};   ///< non-empty: the ParaView series of every frame (inspect::PvdSeries)
  /// The organ's method: what --render draws and what the mesh phase keeps current (the local
  /// planes only for the ray march, tangents for a normal map, the ray march and parallax:
  /// SceneSettings::meshWorkFollowsMethod); with pvdDir every attribute, for the series.
  render::ShadingMethod method = render::ShadingMethod::Lit;
};

/// Replays `config.session` with the scenario it was recorded with in a scene of `scene`'s
/// settings (its material files, shared meshes, shaders, headless backend). Returns the report
/// as a JSON object's text: session, scenario, frames, rendered, positions_sha256, frame_ms
/// {median, p99, max}, method, plane_refit_frames and tangent_frames (frames whose mesh phase
/// did that work), mesh_ms {median, p99, max} (phase 2 whole), phases_ms (loop_report.h),
/// max_contact_force_N, divergence_events,
/// nan_frames, "out" when it wrote into outDir, and "pvd" (the .pvd's path) with pvdDir. A session of another
/// mesh, a missing file or a non-finite pose gives an error naming the file and frame.
Result<std::string> replaySession(const ReplayConfig& config, const scene::SceneSettings& scene);

}  // namespace tissue::studies
