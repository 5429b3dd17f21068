#pragma once
/// \file
/// `tissue-sim render --method texture-space`: one image of a mesh with the standalone
/// texture-space renderer (the pipeline's texture-space method is still its stub).

#include <filesystem>
#include <string>

#include "command.h"

namespace tissue::sim_app {

/// Options of the texture-space render.
struct TsdRenderOptions {
  std::filesystem::path mesh;
  std::filesystem::path out;
  std::filesystem::path baseColor;                  ///< sRGB albedo PNG; empty: a tissue-like constant
  int width = 1024;                                 ///< pixels
  int height = 768;                                 ///< pixels
  float scale = 1.0f;                               ///< mm per file unit
  int gaussians = 6;                                ///< 2, 4 or 6 terms of d'Eon's skin profile
  int mapSize = 1024;                               ///< T_max, texels
  bool cull = true, clip = true, depthSize = true;  ///< Jimenez et al. §3, §5, §4
};

/// Renders and reports (text or JSON); returns the exit code.
int renderTextureSpace(const TsdRenderOptions& options, const GlobalOptions& global);

}  // namespace tissue::sim_app
