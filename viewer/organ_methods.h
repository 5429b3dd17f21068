#pragma once
/// \file
/// The shading methods the viewer can switch the organ between at run time (key M): Lit always;
/// separable SSS and texture-space diffusion when the organ has an optical material (kernel and
/// Gaussians fitted to its dipole profile); layered parallax when it has an inner-layer texture.
/// Ray marching is not offered: it needs the subsurface maps and layer stack of tissue-sim's
/// raymarch scene.

#include <string>
#include <vector>

#include "organ_assets.h"
#include "tissue/core/result.h"
#include "tissue/render/shading.h"

namespace tissue::viewer {

/// Layer textures already uploaded to the renderer (none: the method is not offered).
struct LayerTextures {
  render::TextureHandle innerBase;  ///< the parallax inner layer (sRGB)
  render::TextureHandle opacity;    ///< the parallax outer layer's opacity
};

/// The methods available for `organ`, Lit first. Errors when a material cannot be turned into
/// a kernel (the message names the material).
Result<std::vector<render::MethodSettings>> organMethods(const OrganAssets& organ,
                                                         const LayerTextures& layers);

/// The index of the method called `name` ("lit", "separable", "texture-space", "parallax") in
/// `methods`; the error says which names this organ offers.
Result<std::size_t> findMethod(const std::vector<render::MethodSettings>& methods, const std::string& name);

}  // namespace tissue::viewer
