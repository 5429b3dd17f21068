#pragma once
/// \file
/// The Schlick phase function (Blasi, Le Saëc and Schlick 1993), the one François et al. 2006
/// use in subsurface texture mapping (§3, after Table 1). Same convention as
/// phase_function.h: cos t is the cosine between the direction of travel before and after
/// scattering, so k > 0 scatters forward. The papers write (1 + g cos theta)^2 with theta
/// between the incoming light direction and the view direction, both pointing away from the
/// scattering point; that theta is pi - t, so the two forms agree.

namespace tissue::optics {

/// Largest |k| accepted: the density is only normalisable for |k| < 1, and at |k| -> 1 it
/// becomes a delta (shared/reference/phase_functions.md).
inline constexpr double kSchlickMaxK = 0.999;

/// Schlick density per steradian, p(cos t) = (1/4pi) (1 - k^2) / (1 - k cos t)^2; integrates to
/// 1 over the sphere for |k| < 1. `k` unitless.
double schlickPhase(double cosTheta, double k);

/// The usual map from a Henyey-Greenstein anisotropy to Schlick's k, k = 1.55 g - 0.55 g^3,
/// clamped to [-kSchlickMaxK, kSchlickMaxK] (k would reach 1 at g = 0.9381). Its mean cosine
/// is close to but not g (g = 0.75 gives 0.817).
double schlickKFromG(double g);

/// Mean cosine of the Schlick density with parameter `k` (closed form).
double schlickMeanCosine(double k);

}  // namespace tissue::optics
