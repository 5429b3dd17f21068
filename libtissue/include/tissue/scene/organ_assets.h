#pragma once
/// \file
/// An organ's assets, loaded once for every app and host: its render mesh (mm, with UVs: the
/// file's own when usable, else the automatic atlas), its material file (the one reader,
/// material_file.h) and the textures that material names. GL-free: organ_methods.h uploads them.

#include <cstddef>
#include <filesystem>
#include <optional>
#include <vector>

#include "tissue/core/image.h"
#include "tissue/core/result.h"
#include "tissue/core/surface_mesh.h"
#include "tissue/core/vec_math.h"
#include "tissue/mesh/local_planes.h"
#include "tissue/scene/material_file.h"

namespace tissue::scene {

/// Where an organ's assets come from (plain struct with defaults).
struct OrganSource {
  std::filesystem::path mesh;           ///< OBJ, PLY, OFF or STL
  std::filesystem::path material;       ///< data/materials/<organ>.json; empty: defaultMaterial()
  float meshScaleToMm = 1.0f;           ///< mm per file unit
  MaterialFileOptions materialOptions;  ///< where the material's textures are looked up
  /// Meshes without usable UVs (none, or overlapping) get mesh::computeUvAtlas's atlas, which
  /// keeps the geometric vertices (a scenario still moves them); the material's painted
  /// textures are then dropped, since they belong to the file's UVs. false: such a mesh is an
  /// error naming the file.
  bool uvAtlasFallback = true;
};

/// A loaded organ.
struct OrganAssets {
  SurfaceMesh mesh;                     ///< render vertices with UVs, mm
  MaterialFile material;                ///< the file's, or defaultMaterial()
  std::optional<Image8> baseColor;      ///< sRGB (painted); empty: the renderer's tissue-like constant
  std::optional<Image8> normalMap;      ///< tangent space
  std::optional<Image8> opacity;        ///< layered parallax: the outer layer's opacity (red)
  std::optional<Image8> innerBase;      ///< layered parallax: the inner layer (sRGB)
  std::optional<Image8> subsurfaceMap;  ///< ray marching: RGBA layer boundaries (linear data)
  bool atlas = false;                   ///< the UVs are the automatic atlas's
  std::size_t atlasCharts = 0;          ///< its charts (0 with the file's UVs)
  float uvPerMm = 0.0f;                 ///< texture units per mm (subsurface::uvPerMmOf)
  mesh::PlaneFitSettings planes;        ///< sigma_t of the first layer (mm^-1; François eq. 8)
  Bounds3 bounds;                       ///< of the rest shape, mm, object space
};

/// Loads `source`. Errors name the file at fault and the fix.
Result<OrganAssets> loadOrganAssets(const OrganSource& source);

}  // namespace tissue::scene
