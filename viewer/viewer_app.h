#pragma once
/// \file
/// The viewer application: a window showing one organ moved by the library's per-frame loop
/// (scene::OrganLoop: simulate, mesh, upload, render), which the user orbits, zooms and pokes
/// with the scenario's instrument, under a control panel (panel.h). Three modes: interactive
/// (mouse and keys drive the tool), scripted (the scenario's own path, no input) and replay (a
/// recorded session's input, camera and method switches).

#include <filesystem>
#include <string>

#include "tissue/core/result.h"

namespace tissue::viewer {

/// Where the project's data lives.
struct DataFolders {
  std::filesystem::path data;       ///< the source tree's data/ (meshes, materials, small textures)
  std::filesystem::path generated;  ///< the build's data/ (1024 x 1024 textures of target tissue_data)
  std::filesystem::path shared;     ///< ../shared (meshes a scenario may name)
};

/// What the command line asks for.
struct ViewerOptions {
  std::filesystem::path scenario;    ///< the scenario file (data/scenarios/*.json)
  DataFolders folders;               ///< where materials and textures are found
  int width = 1280;                  ///< window width, screen coordinates
  int height = 720;                  ///< window height, screen coordinates
  long frames = 0;                   ///< frames to run; 0: until the window closes (replay: the session's)
  std::filesystem::path screenshot;  ///< PNG of the last frame (the window, panel included); empty: none
  bool pokeScript = false;           ///< scripted: the scenario's own instrument path, no input
  /// The organ's shading method at start: lit, separable, texture-space, ray-march or parallax.
  std::string method = "lit";
  std::filesystem::path record;  ///< record the session into this file (R toggles); empty: R records to
                                 ///< tissue-viewer-session.json
  std::filesystem::path replay;  ///< drive the viewer by this recorded session; empty: none
  std::filesystem::path log;     ///< one CSV line per frame (phases ms, force N); empty: none
  /// ms; > 0: start under this frame budget (the quality controller chooses the organ's method,
  /// issue 16; the panel's slider changes it); 0: off
  double budgetMs = 0.0;
};

/// Runs the viewer until the window closes, Esc, or the frames run out. The error is one line
/// for the user (no display, unreadable scenario or session, GL failure).
Result<void> runViewer(const ViewerOptions& options);

}  // namespace tissue::viewer
