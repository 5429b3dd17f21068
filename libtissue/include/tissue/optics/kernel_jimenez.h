#pragma once
/// \file
/// Jimenez et al.'s reference separable skin kernel (shared/reference/separable_sss_kernel.md;
/// Freude eq. 4.8): d'Eon's red skin Gaussians without the narrowest, per-channel falloff,
/// quadratic ("importance") tap placement and a strength that keeps part of the centre.

#include <vector>

#include "tissue/optics/kernel.h"

namespace tissue::optics {

/// The reference kernel's `taps` samples (odd, >= 3), centre first then in order of offset, each
/// channel summing to 1. Offsets in mm of d'Eon's skin profile (range 2 mm, 3 mm above 20 taps).
std::vector<KernelTap> jimenezTaps(const JimenezParameters& parameters, int taps);

/// The same kernel's profile P_c(r) before sampling (step 2 of the reference), unnormalised.
double jimenezProfile(const JimenezParameters& parameters, int channel, double rMm);

}  // namespace tissue::optics
