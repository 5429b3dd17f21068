#pragma once
/// \file
/// The bridge from optics to the renderer's method settings, shared by the apps (tissue-sim and
/// tissue-viewer): turning an optical material into what the separable SSS method takes as plain arrays
/// (render::SeparableSettings: kernel components of taps {w_R, w_G, w_B, offset_mm} with their
/// signs, and a transmittance table),
/// and into the ground truth its CPU reference convolves with. The renderer itself never sees
/// optics, and optics never sees the renderer: this module sits above both. Lengths in mm.

#include <string>

#include "tissue/core/result.h"
#include "tissue/optics/materials.h"
#include "tissue/reference/screen_convolution.h"
#include "tissue/render/shading.h"

namespace tissue::materials {

/// A material ready for the separable method and for its reference.
struct SeparableMaterial {
  render::SeparableSettings settings;  ///< kernel components and transmittance for the renderer
  reference::RadialProfile truth;      ///< the dipole profile normalised to 1 (mm^-2): the reference's R
  std::string kernelName;              ///< e.g. "preintegrated-17", "svd2-17" (rank 2)
};

/// Builds kernel `model` (svd, preintegrated, guided, manual, deon, jimenez) with `taps` taps
/// for `material`, of `rank` components (SVD rank, or d'Eon's Gaussian count; 1..8, the other
/// models rank 1), all passed to the renderer with their signs (Freude eq. 5.10), and its transmittance T(d)
/// = int R(sqrt(r^2 + d^2)) dA / int R dA (Jimenez et al. 2010, for a normalised profile) at 16 thicknesses.
/// Errors name the model.
Result<SeparableMaterial> makeSeparableMaterial(const optics::ScatteringMaterial& material,
                                                const std::string& model, int taps, int rank = 1);

/// Texture-space diffusion settings for `material`: `gaussians` (1..8) Gaussians fitted to the
/// shape of its dipole profile (optics::fitGaussians, d'Eon eq. 4.15; weights sum to 1 per
/// channel, as the separable kernels), the separable method's transmittance table, pre-scatter
/// albedo; the rest (optimisations, map size) at their defaults. Errors name the material.
Result<render::TextureSpaceSettings> makeTextureSpaceSettings(const optics::ScatteringMaterial& material,
                                                              int gaussians);

}  // namespace tissue::materials
