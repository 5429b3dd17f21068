#pragma once
/// \file
/// CPU reference of texture-space diffusion's own model on one frame (GL-free): the exact
/// convolution of the irradiance over the mesh surface with the material's radial diffusion
/// profile, M(x_o) = sum_i R(|x_i - x_o|) E(x_i) A_i (the diffusion term of Jimenez et al. eq. 1,
/// Jensen's dipole BSSRDF, with the Euclidean distance as there). The samples are the texels of
/// the frame's irradiance map read back, each with its world position and surface area.

#include <span>
#include <vector>

#include "tissue/core/types.h"

namespace tissue::render {

/// A radial profile sampled at increasing radii: R(r) per RGB channel, mm^-2 (linear between
/// samples, 0 beyond the last).
struct RadialProfileTable {
  std::vector<float> radiusMm;  ///< increasing, mm
  std::vector<Float3> value;    ///< mm^-2, one per radius
};

/// Points of the surface carrying irradiance.
struct SurfaceSamples {
  std::vector<Float3> positionMm;  ///< mm, world space
  std::vector<float> areaMm2;      ///< mm^2 of surface each sample stands for
  std::vector<Float3> irradiance;  ///< linear RGB irradiance E
};

/// R(r), mm^-2, by linear interpolation in `table`.
Float3 evaluateProfile(const RadialProfileTable& table, float rMm);

/// M(x_o) = sum_i R(|x_i - x_o|) E_i A_i for each query point (mm), over the samples within
/// `cutoffMm` (a uniform grid of that cell size finds them). Each sample stands for a disk of
/// area A_i, so R is averaged over the annulus that disk sweeps at distance |x_i - x_o| (from
/// the cumulative profile): the narrowest skin Gaussians (sigma 0.08 mm) are far below a texel,
/// and a point value of R would count their energy wrongly.
std::vector<Float3> convolveOverSurface(const SurfaceSamples& samples, std::span<const Float3> queriesMm,
                                        const RadialProfileTable& profile, float cutoffMm);

}  // namespace tissue::render
