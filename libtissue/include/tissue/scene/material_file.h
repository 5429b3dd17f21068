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
  /// The artist's term (docs/DECISIONS.md, "One material, colour from the optics"): true, the
  /// painted base_color texture modulates the optical albedo by its luminance relative to its
  /// mean (detail only, the colour stays the optics'); false, the flat optical albedo. Key
  /// "base_color_detail" of the file; hosts (the atlas) may switch it off to measure its effect.
  bool baseColorDetail = true;
};

/// A layer's reflectance as the methods use it (optics::semiInfiniteReflectance per RGB channel).
struct LayerReflectance {
  Float3 single;    ///< single-scattered reflectance, unitless
  Float3 multiple;  ///< multiple-scattered reflectance (dipole), unitless
  Float3 total;     ///< their sum: the layer's diffuse albedo
  Float3 sigmaTr;   ///< effective transport coefficient sqrt(3 sigma_a sigma_t'), mm^-1
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

/// `layer` of `material` (index in layers) as a half-space below air with the file's ior.
LayerReflectance layerReflectance(const MaterialFile& material, std::size_t layer);

/// The diffuse albedo of the organ, linear RGB 0..1: the first layer's total reflectance. The
/// colour of every method (lit, separable, texture space, parallax's outer layer) comes from it.
Float3 opticalAlbedo(const MaterialFile& material);

/// The base colour texture every method shades with (sRGB RGBA8): the optical albedo, times the
/// painted texture's luminance over its mean luminance when baseColorDetail is on and `painted`
/// is given (clamped to 1); a 4x4 flat image otherwise.
Image8 opticalBaseColor(const MaterialFile& material, const Image8* painted);

/// The image of the layer found at `depthMm` below each texel of `subsurfaceMap` (François et
/// al. 2006 §2.1 boundaries), each texel that layer's total albedo (sRGB RGBA8): the inner layer of
/// layered parallax from the optics. With baseColorDetail and `painted` (same size) its luminance
/// modulates it as in opticalBaseColor.
Image8 opticalLayerImage(const MaterialFile& material, const Image8& subsurfaceMap, float depthMm,
                         const Image8* painted);

/// Normal-incidence Fresnel reflectance of the outer surface, ((n - 1) / (n + 1))^2 for n = ior.
float specularF0(const MaterialFile& material);

/// The smallest RGB extinction of the first layer (mm^-1): sigma_t of the local planes' sphere
/// radius (François eq. 8).
float firstLayerMinSigmaT(const MaterialFile& material);

/// The layer stack for ray marching with `subsurfaceMap` (its RGBA boundaries): checked by
/// subsurface::validateLayerStack; errors name the file.
Result<subsurface::LayerStack> layerStack(const MaterialFile& material, const Image8& subsurfaceMap);

}  // namespace tissue::scene
