#pragma once
/// \file
/// The demo's texture-space diffusion render of the poked organ (d'Eon et al. 2007 with the three
/// optimisations of Jimenez and Gutierrez 2008, d'Eon's six skin Gaussians).

#include <filesystem>
#include <nlohmann/json.hpp>

#include "tissue/mesh/deformable_surface.h"

namespace tissue::sim_app {

/// Renders `surface` as it is now with texture-space diffusion into `png` (atomically) and
/// returns what it did (or {"skipped": reason} when no GL context or data is available). Meshes
/// without usable UVs get the automatic atlas of their rest shape.
nlohmann::json renderTextureSpaceDemo(const mesh::DeformableSurface& surface,
                                      const std::filesystem::path& png, int width, int height);

}  // namespace tissue::sim_app
