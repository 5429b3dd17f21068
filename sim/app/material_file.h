#pragma once
/// \file
/// Reading the layered material files of data/materials/ (schema in docs/DATA.md). The optics
/// module (issue 4) will own materials; until then the apps read them here.

#include <filesystem>
#include <string>
#include <vector>

#include "tissue/core/result.h"
#include "tissue/core/types.h"

namespace tissue::sim_app {

/// One layer: scattering and extinction in mm^-1 (RGB), Henyey-Greenstein/Schlick g.
struct MaterialLayer {
  std::string name;
  Float3 sigma_s;  ///< mm^-1
  Float3 sigma_t;  ///< mm^-1
  float g = 0.0f;  ///< mean cosine, -1..1
};

/// A layered material (François et al. §2.1: layer boundaries from the subsurface map).
struct LayeredMaterial {
  std::string name;
  float depthScaleMm = 1.0f;  ///< depth that a subsurface-map value of 1.0 means, mm
  float ior = 1.3f;           ///< relative index of refraction
  std::vector<MaterialLayer> layers;
  float firstLayerMinSigmaT =
      1.0f;  ///< mm^-1, smallest RGB extinction of the outer layer (plane radius, eq. 8)
};

/// data/materials/<mesh stem>.json for a mesh file.
std::filesystem::path materialFileFor(const std::filesystem::path& meshFile);

/// Parses a material file; errors name the file and the offending field.
Result<LayeredMaterial> readLayeredMaterial(const std::filesystem::path& path);

}  // namespace tissue::sim_app
