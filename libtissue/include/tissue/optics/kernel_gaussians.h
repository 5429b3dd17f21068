#pragma once
/// \file
/// d'Eon & Luebke's sum-of-Gaussians fit of a diffusion profile (GPU Gems 3 ch. 14; Freude eq.
/// 4.15), for the texture-space diffusion renderer and the `deon` kernel model. Lengths in mm.

#include "tissue/core/result.h"
#include "tissue/optics/ground_truth_kernel.h"
#include "tissue/optics/materials.h"

namespace tissue::optics {

/// Fits R(r) ~ sum_i w_i G(v_i, r), G(v, r) = exp(-r^2 / (2 v)) / (2 pi v), to the shape of each
/// channel of `profile` (each normalised to total 1, so each channel's weights sum to 1 and are
/// >= 0; the albedo is left to the diffuse colour, as d'Eon's table). The variances v_i (mm^2,
/// increasing) are shared by the channels, as d'Eon's. Minimises the 2D squared error
/// sum_c integral (R_c - fit_c)^2 2 pi r dr: Nelder-Mead over log v, and for given v the weights
/// by least squares with sum w = 1, w >= 0. `count` in 1..8 (2, 4, 6 for texture space).
Result<GaussianSum> fitGaussians(const RadialProfileRgb& profile, int count);

}  // namespace tissue::optics
