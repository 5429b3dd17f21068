#pragma once
/// \file
/// The shading methods the viewer can switch the organ between at run time (key M, the panel):
/// Lit always; separable SSS and texture-space diffusion when the organ has an optical material
/// (kernel and Gaussians fitted to its dipole profile); ray marching when it has a layer stack
/// and subsurface map (materials::RayMarchMaterial; the loop uploads the planes it needs);
/// layered parallax when it has an inner-layer texture.

#include <string>
#include <vector>

#include "organ_assets.h"
#include "tissue/core/result.h"
#include "tissue/render/shading.h"

namespace tissue::viewer {

/// Textures already uploaded to the renderer (none: the method is not offered).
struct LayerTextures {
  render::TextureHandle innerBase;      ///< the parallax inner layer (sRGB)
  render::TextureHandle opacity;        ///< the parallax outer layer's opacity
  render::TextureHandle subsurfaceMap;  ///< the ray-march layer boundaries (LinearData)
};

/// The settings the panel changes (each change rebuilds the methods).
struct MethodChoices {
  std::string kernel = "preintegrated";  ///< separable kernel model (materials::makeSeparableMaterial)
  int taps = 17;                         ///< separable taps, odd, 5..63
  int gaussians = 6;                     ///< texture-space Gaussians, 1..8
  int samples = 32;                      ///< ray-march samples per pixel, 1..256
};

/// The separable kernel models the panel offers.
inline const std::vector<std::string> kKernelModels{"preintegrated", "svd", "deon", "jimenez", "guided"};

/// The methods available for `organ`, Lit first. Errors when a material cannot be turned into
/// a kernel (the message names the material and the model).
Result<std::vector<render::MethodSettings>> organMethods(const OrganAssets& organ,
                                                         const LayerTextures& layers,
                                                         const MethodChoices& choices = {});

/// The name of a method ("lit", "separable", "texture-space", "ray-march", "parallax").
std::string methodName(const render::MethodSettings& method);

/// The index of the method called `name` in `methods`; the error says which names this organ offers.
Result<std::size_t> findMethod(const std::vector<render::MethodSettings>& methods, const std::string& name);

}  // namespace tissue::viewer
