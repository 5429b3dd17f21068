#pragma once
/// \file
/// The analytic single-scattering radiance of a flat stack of constant-depth layers lit by a
/// distant light (the case where the local-plane estimate of François eq. 10 and Norberg's
/// eq. 13-14 are exact): integral of eq. 3 in closed form, layer by layer. Lengths in mm,
/// coefficients in mm^-1.

#include <span>

#include "tissue/core/types.h"
#include "tissue/subsurface/layer_stack.h"

namespace tissue::subsurface {

/// Radiance leaving the surface z = 0 (outward normal +z) towards `toEye`, for unit light
/// radiance arriving from direction `toLight` (both unit, z > 0), integrated down to the depth
/// `depthMaxMm` (M_max of eq. 15). `boundariesMm` are the layer-boundary depths, one fewer than
/// `layers`. Within layer j between depths a and b, with c = 1/mu_l + 1/mu_v:
///   L_j = sigma_s p / mu_v * exp(-c tau(a)) (1 - exp(-c sigma_t (b - a))) / (c sigma_t).
Float3 flatSlabSingleScattering(std::span<const LayerCoefficients> layers,
                                std::span<const float> boundariesMm, Float3 toEye, Float3 toLight,
                                float depthMaxMm);

}  // namespace tissue::subsurface
