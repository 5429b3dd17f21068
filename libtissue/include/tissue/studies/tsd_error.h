#pragma once
/// \file
/// The error measure of `tissue-sim tsd-bench`: texture-space diffusion's diffused map (d'Eon
/// 2007; Jimenez and Gutierrez 2008) against the CPU reference of its own model, the radial
/// profile convolved over the surface the irradiance map samples (render/texture_space_reference.h).
/// GL-free: it works on maps read back (render::TextureSpaceMaps). Lengths in mm.

#include "tissue/render/renderer.h"
#include "tissue/render/texture_space_reference.h"

namespace tissue::studies {

/// The samples of a full-size, unculled irradiance map read back: every drawn texel (alpha > 0)
/// with its world position and its area |dP/du x dP/dv| / T^2, mm^2 (from the stretch map's
/// b = sqrt(|dP/du x dP/dv|)), and its irradiance.
render::SurfaceSamples surfaceSamplesOf(const render::TextureSpaceMaps& maps);

/// RMS (linear radiance, all channels) of a diffused map against the reference convolution at
/// its covered texels' positions (coverage >= 0.999), and relative to the reference's mean
/// there: over all covered texels, and over the charts' interiors only (texels whose 7 x 7
/// neighbourhood is covered too, away from the seams' dilation).
struct TexelError {
  double rms = 0.0;               ///< linear radiance
  double relative = 0.0;          ///< rms / mean reference channel value, covered texels
  double interiorRelative = 0.0;  ///< the same over the charts' interiors
};

TexelError diffusedMapError(const render::TextureSpaceMaps& maps, const render::SurfaceSamples& samples,
                            const render::RadialProfileTable& profile, float cutoffMm);

}  // namespace tissue::studies
