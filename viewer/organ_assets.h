#pragma once
/// \file
/// What the viewer shows: the scenario that moves the organ (tissue::scenario, run by
/// scene::OrganLoop), the organ's render mesh, and its material and textures, found beside the
/// mesh in the project's data folders (or flat defaults for a mesh from elsewhere).

#include <filesystem>
#include <optional>
#include <string>

#include "tissue/core/image.h"
#include "tissue/core/result.h"
#include "tissue/core/surface_mesh.h"
#include "tissue/materials/raymarch_material.h"
#include "tissue/mesh/local_planes.h"
#include "tissue/optics/materials.h"
#include "tissue/scenario/scenario.h"

namespace tissue::viewer {

/// Where the project's data lives.
struct DataFolders {
  std::filesystem::path data;       ///< the source tree's data/ (meshes, materials, small textures)
  std::filesystem::path generated;  ///< the build's data/ (1024 x 1024 textures of target tissue_data)
  std::filesystem::path shared;     ///< ../shared (meshes a scenario may name)
};

/// A loaded organ.
struct OrganAssets {
  scenario::Scenario scenario;      ///< what moves the organ (springs, mass, pins, instrument)
  SurfaceMesh mesh;                 ///< the scenario's mesh with UVs, mm (scene::OrganLoop::create)
  mesh::PlaneFitSettings planes;    ///< sigma_t from the first layer (mm^-1; François eq. 8)
  std::optional<Image8> baseColor;  ///< sRGB; empty: the renderer's tissue-like default
  std::optional<Image8> normalMap;  ///< tangent space; empty: flat
  std::optional<Image8> innerBase;  ///< sRGB inner layer of layered parallax (the vessel network)
  std::optional<Image8> opacity;    ///< the outer layer's opacity for layered parallax (red channel)
  /// The first layer of data/materials/<stem>.json as an optical material (mm^-1), for the
  /// separable and texture-space methods; empty for a mesh from outside the project.
  std::optional<optics::ScatteringMaterial> material;
  /// The whole layer stack and subsurface map for ray marching; empty without them.
  std::optional<materials::RayMarchMaterial> rayMarch;
};

/// Loads `scenarioFile` (tissue::scenario; meshes also from folders.shared/meshes), its mesh
/// (UVs required, scaled to mm), the first layer's extinction from data/materials/<stem>.json
/// when present (else 1.5 mm^-1), the layer stack and subsurface map for ray marching, and the
/// textures <stem>/{base_color,normal_map,inner_base,opacity}.png: the generated 1024 ones, else
/// the committed small ones. Errors name the file.
Result<OrganAssets> loadOrganAssets(const std::filesystem::path& scenarioFile, const DataFolders& folders);

}  // namespace tissue::viewer
