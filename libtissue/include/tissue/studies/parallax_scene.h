#pragma once
/// \file
/// An organ ready for layered parallax (Oat 2006; Norberg 2010 §2.2), shared by the parallax
/// render and parallax-study: unique UVs (its own, else the scene module's automatic atlas), the
/// layer textures its material file names (base colour, normal map, opacity, the inner layer's
/// vessel network; scene::loadOrganAssets, dropped with the atlas since they belong to the file's
/// UVs), and a render::Scene of one parallax object on the caller's renderer. Lengths in mm.

#include <optional>

#include "tissue/core/image.h"
#include "tissue/core/result.h"
#include "tissue/render/renderer.h"
#include "tissue/render/scene.h"
#include "tissue/scene/organ_assets.h"
#include "tissue/studies/texture_space_organ.h"

namespace tissue::studies {

/// The parallax settings a command may change (defaults: ParallaxSettings').
struct ParallaxOptions {
  float layerDepthMm = 1.5f;  ///< mm, the one inner layer's depth
  render::ParallaxSettings settings;
};

/// The organ and its layer textures.
struct ParallaxOrgan {
  TsdOrgan organ;
  std::optional<Image8> baseColor, normalMap, opacity, innerBase;  ///< sRGB / tangent space / red
  /// The mesh's own UVs and its material's inner layer (false: atlas or no inner_base; the
  /// object then draws with the renderer's default colours).
  bool textured = false;
};

/// Loads `source` (scene::loadOrganAssets with the UV-atlas fallback; an empty material: the
/// default organ, untextured). Errors name the file at fault.
Result<ParallaxOrgan> loadParallaxOrgan(const scene::OrganSource& source);

/// Uploads `organ` to `renderer` (its context current) as the one parallax object of the returned
/// scene (one inner layer at options.layerDepthMm; its textures when textured), the camera
/// framing the mesh for width / height = `aspect`, no lights.
Result<render::Scene> makeParallaxScene(render::Renderer& renderer, const ParallaxOrgan& organ,
                                        const ParallaxOptions& options, float aspect);

}  // namespace tissue::studies
