#pragma once
/// \file
/// What the viewer shows: the organ's deformable surface and its textures, found beside the
/// mesh in the project's data folders (or flat defaults for a mesh from elsewhere).

#include <filesystem>
#include <optional>

#include "tissue/core/image.h"
#include "tissue/core/result.h"
#include "tissue/mesh/deformable_surface.h"
#include "tissue/optics/materials.h"

namespace tissue::viewer {

/// Where the project's data lives.
struct DataFolders {
  std::filesystem::path data;       ///< the source tree's data/ (meshes, materials, small textures)
  std::filesystem::path generated;  ///< the build's data/ (1024 x 1024 textures of target tissue_data)
};

/// A loaded organ.
struct OrganAssets {
  mesh::DeformableSurface surface;
  std::optional<Image8> baseColor;  ///< sRGB; empty: the renderer's tissue-like default
  std::optional<Image8> normalMap;  ///< tangent space; empty: flat
  std::optional<Image8> innerBase;  ///< sRGB inner layer of layered parallax (the vessel network)
  std::optional<Image8> opacity;    ///< the outer layer's opacity for layered parallax (red channel)
  /// The first layer of data/materials/<stem>.json as an optical material (mm^-1), for the
  /// subsurface methods; empty for a mesh from outside the project.
  std::optional<optics::ScatteringMaterial> material;
  float sigma_t = 1.5f;  ///< mm^-1, the planes' extinction (first layer, smallest channel)
};

/// Loads `meshFile` (UVs required), the first layer's extinction from
/// data/materials/<stem>.json when present (else 1.5 mm^-1), and the textures
/// <stem>/{base_color,normal_map,inner_base,opacity}.png: the generated 1024 ones, else the
/// committed small ones.
Result<OrganAssets> loadOrganAssets(const std::filesystem::path& meshFile, const DataFolders& folders);

}  // namespace tissue::viewer
