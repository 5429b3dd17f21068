#pragma once
/// \file
/// The viewer application: a window showing one organ, which the user orbits, zooms and pokes.
/// The frame loop runs named, timed phases: input, deform, mesh, upload, render, present.

#include <filesystem>
#include <string>

#include "organ_assets.h"
#include "tissue/core/result.h"

namespace tissue::viewer {

/// What the command line asks for.
struct ViewerOptions {
  std::filesystem::path mesh;        ///< the organ's mesh file (UVs required)
  DataFolders folders;               ///< where materials and textures are found
  int width = 1280;                  ///< window width, screen coordinates
  int height = 720;                  ///< window height, screen coordinates
  long frames = 0;                   ///< frames to run; 0: until the window closes
  std::filesystem::path screenshot;  ///< PNG of the last frame (offscreen, window size); empty: none
  bool pokeScript = false;           ///< poke the top of the organ automatically
  /// The organ's shading method at start: lit, separable, texture-space or parallax (M cycles).
  std::string method = "lit";
};

/// Runs the viewer until the window closes, Esc, or `options.frames`. The error is one line
/// for the user (no display, unreadable mesh, GL failure).
Result<void> runViewer(const ViewerOptions& options);

}  // namespace tissue::viewer
