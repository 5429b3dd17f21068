#pragma once
/// \file
/// The ground truth that every separable kernel approximates: a material's radial diffusion
/// profile R(r) (mm^-2, per RGB channel) and the normalised 2D kernel made from it by rotation
/// about the axis (Freude 2014, §6.1). Lengths in mm.

#include <array>
#include <string>
#include <vector>

#include "tissue/core/result.h"
#include "tissue/optics/materials.h"

namespace tissue::optics {

/// A radial diffusion profile sampled per RGB channel, evaluated by linear interpolation.
struct RadialProfileRgb {
  std::string name;                                  ///< material name, for messages
  std::vector<double> radiusMm;                      ///< increasing sample radii from 0, mm
  std::array<std::vector<double>, kChannels> value;  ///< R(r) per channel at radiusMm, mm^-2
  double kernelHalfWidthMm = 10.0;  ///< half-width W of the square kernel domain [-W, W]^2, mm
};

/// R(r) of `channel` at `r` mm by linear interpolation, mm^-2; 0 beyond the last sample.
double evaluateProfile(const RadialProfileRgb& profile, int channel, double r);

/// The dipole profile (Jensen 2001; Freude §6.1 simulates the same coefficients with MCML) of
/// `material`, sampled at 4096 radii up to sqrt(2) W so the square's corners are covered. W is
/// the largest channel's min(6 diffusion lengths 1/sigma_tr, 30 transport mean free paths
/// 1/sigma_t'), as `tissue-sim profile` uses. Errors: non-positive or non-finite coefficients.
Result<RadialProfileRgb> groundTruthProfile(const ScatteringMaterial& material);

/// A profile rotated into a square of (2h+1)^2 cells centred on r = 0 (Freude §6.1), each channel
/// normalised so its cells sum to 1 (Freude §6.2: "all ground-truth kernels were normalized").
struct GroundTruthKernel {
  std::string name;                                   ///< material name
  int halfCells = 100;                                ///< h: the grid has 2h+1 cells per side
  double cellMm = 0.1;                                ///< cell width, mm (= W / (h + 1/2))
  std::array<std::vector<double>, kChannels> values;  ///< row-major (2h+1)^2 cell weights, sum 1
  RadialProfileRgb profile;                           ///< the profile it was made from

  /// Cells per side, 2h+1.
  int size() const { return 2 * halfCells + 1; }
  /// Cell weight of `channel` at row `y`, column `x` (0-based, centre at h).
  double at(int channel, int y, int x) const {
    return values[static_cast<std::size_t>(channel)][static_cast<std::size_t>(y * size() + x)];
  }
};

/// Rotates `profile` into a (2h+1)^2 grid over [-W, W]^2, each cell the mean of 4x4 point samples
/// times its area, then normalises each channel to sum 1. `halfCells` h in [2, 400] (Freude used
/// 200 samples per side). Errors: a bad h or a channel without energy.
Result<GroundTruthKernel> groundTruthKernel(const RadialProfileRgb& profile, int halfCells = 100);

}  // namespace tissue::optics
