#pragma once
/// \file
/// Closed-form references of the path-traced truth on a flat layered half-space (constant-depth
/// layers under a plane surface z = 0, outward normal +z), for validation.

#include "tissue/core/types.h"
#include "tissue/truth/material.h"

namespace tissue::truth {

/// Single-scattered radiance leaving the surface towards `toEye` for a directional light arriving
/// from `toLight` (both unit, outside, z > 0) with the renderer's radiance scale `lightRadiance`
/// (irradiance pi * lightRadiance on a surface facing the light). Hanrahan & Krueger 1993, §4
/// (first-order scattering in layers under a Fresnel boundary), with the interface factors of
/// radiance: both rays refract (Snell) into directions with internal cosines mu_v, mu_l; the light
/// arrives as the collimated irradiance E_t = T_l E cos(theta_l) / mu_l; the scattered radiance
/// leaves with T_v / n^2. With c = 1/mu_l + 1/mu_v and tau(z) the optical depth, layer j between
/// depths a and b adds
///   sigma_s p(cos t) / mu_v * exp(-c tau(a)) (1 - exp(-c sigma_t (b - a))) / (c sigma_t),
/// p the Henyey-Greenstein phase of the angle between the refracted light's travel direction and
/// the refracted view ray's reversed direction. Layers end at the last thickness (no reflection
/// from below the stack). Per-texel maps are ignored. Values per band, in lightRadiance's units.
Rgb layeredSlabSingleScattering(const TruthMaterial& material, Float3 toEye, Float3 toLight,
                                Rgb lightRadiance);

}  // namespace tissue::truth
