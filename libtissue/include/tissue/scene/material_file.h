#pragma once
/// \file
/// The one reader of the project's layered material files (data/materials/<organ>.json, schema
/// in docs/DATA.md). Every shading method's inputs derive from what it returns
/// (tissue/scene/organ_methods.h): the first layer as an optical material for the separable
/// kernels and the texture-space Gaussians, the whole layer stack for ray marching (François et
/// al. 2006 §2.1), and the textures of layered parallax (Oat 2006; Norberg 2010 §2.2). Lengths
/// in mm, coefficients in mm^-1.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "tissue/core/image.h"
#include "tissue/core/result.h"
#include "tissue/core/types.h"
#include "tissue/optics/materials.h"
#include "tissue/subsurface/layer_stack.h"

namespace tissue::scene {

/// One homogeneous layer of a material file.
struct MaterialLayer {
  std::string name;
  Float3 sigmaS{1.0f, 1.0f, 2.0f};  ///< scattering coefficient per RGB channel, mm^-1
  Float3 sigmaT{1.5f, 1.5f, 2.5f};  ///< extinction per RGB channel, mm^-1 (>= sigmaS, > 0)
  float g = 0.8f;                   ///< Henyey-Greenstein mean cosine, -1 < g < 1
  std::string source;               ///< where the numbers come from
};

/// The texture files a material names, resolved to existing files (empty: none).
struct MaterialTextures {
  std::filesystem::path subsurface;  ///< RGBA layer boundaries (ray marching)
  std::filesystem::path baseColor;   ///< sRGB base colour
  std::filesystem::path normalMap;   ///< tangent-space normal map
  std::filesystem::path opacity;     ///< the outer layer's opacity (layered parallax)
  std::filesystem::path innerBase;   ///< the inner layer's colour (layered parallax: the vessels)
};

/// A parsed material file.
struct MaterialFile {
  std::filesystem::path file;  ///< where it was read from (empty: defaultMaterial())
  std::string name;
  float depthScaleMm = 3.0f;          ///< mm, the depth a subsurface-map value of 1 stands for
  float ior = 1.3f;                   ///< relative index of refraction of the tissue
  std::vector<MaterialLayer> layers;  ///< top first; at least one
  MaterialTextures textures;
};

/// Where a material's relative texture paths are looked up.
struct MaterialFileOptions {
  /// Folders searched in order for each relative texture path (e.g. the build's generated
  /// 1024^2 textures first, then the committed small ones). Empty: the folder above the
  /// file's own folder (data/ for data/materials/liver.json).
  std::vector<std::filesystem::path> textureRoots;
};

/// Reads `file`. Errors name the file and the key at fault, and say how to fix it; a texture
/// the file names but no root holds is an error naming the roots searched.
Result<MaterialFile> readMaterialFile(const std::filesystem::path& file,
                                      const MaterialFileOptions& options = {});

/// The material of an organ without a file: one layer with François et al. 2006 Table 1's
/// "organs" coefficients, no textures.
MaterialFile defaultMaterial();

/// The first layer as an optical material (sigma_a = sigma_t - sigma_s, eta = ior): the
/// separable kernels' and texture-space Gaussians' input (their dipole profile).
optics::ScatteringMaterial opticalMaterial(const MaterialFile& material);

/// The smallest RGB extinction of the first layer (mm^-1): sigma_t of the local planes' sphere
/// radius (François eq. 8).
float firstLayerMinSigmaT(const MaterialFile& material);

/// The layer stack for ray marching with `subsurfaceMap` (its RGBA boundaries): checked by
/// subsurface::validateLayerStack; errors name the file.
Result<subsurface::LayerStack> layerStack(const MaterialFile& material, const Image8& subsurfaceMap);

}  // namespace tissue::scene
