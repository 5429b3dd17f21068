#pragma once
/// \file
/// Separable subsurface-scattering kernels for a screen-space (or texture-space) blur: Freude
/// 2014's models (SVD, pre-integration, guided optimisation, manual two-Gaussian), d'Eon &
/// Luebke's sum of Gaussians and Jimenez's reference skin kernel, each as importance-sampled
/// 1D taps ready for a shader.
///
/// Convention for the renderer: tap offsets are in mm on the surface. A blur pass reads the
/// irradiance at offset_mm * (pixels per mm) along its direction, where pixels per mm comes from
/// the shader's sssWidth and the projection (Jimenez's kernel scale, Freude eq. 4.11): sssWidth
/// maps mm to screen space. A component is applied as a horizontal then a vertical pass with the
/// same taps; rank-R kernels sum R such two-pass results (Freude eq. 5.10). Weights are per RGB
/// channel and each component's second pass is multiplied by its `sign`.

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "tissue/core/result.h"
#include "tissue/core/types.h"
#include "tissue/optics/ground_truth_kernel.h"

namespace tissue::optics {

/// One sample of a 1D kernel: RGB weights at an offset along the blur direction.
struct KernelTap {
  Float3 weight;         ///< per-channel weight (R, G, B); unitless
  float offsetMm = 0.f;  ///< offset from the centre pixel along the pass direction, mm
};

/// Channel `c` (0 R, 1 G, 2 B) of an RGB triple, as double.
inline double channelOf(const Float3& rgb, int c) {
  return static_cast<double>(c == 0 ? rgb.x : (c == 1 ? rgb.y : rgb.z));
}

/// One separable component a_i: E * a_i horizontally, then * a_i vertically, times `sign`.
struct KernelComponent {
  std::vector<KernelTap> taps;  ///< importance-sampled taps, centre first, then by |offset|
  Float3 sign{1.f, 1.f, 1.f};   ///< +-1 per channel (SVD components of negative eigenvalues)
  /// The component on the ground-truth grid (2h+1 cells of `SeparableKernel::cellMm`, centre at
  /// h), per channel, before tap sampling; the error measures use it.
  std::array<std::vector<double>, kChannels> dense;
};

/// The closed set of kernel models.
enum class KernelModel {
  Svd,            ///< rank-R SVD, Freude eq. 5.5-5.10 (+ eq. 5.12 with normalizeEnergy)
  PreIntegrated,  ///< a_p = integral of R_d along one axis, Freude eq. 5.17-5.18
  Guided,         ///< weighted least squares with ||a||_1^2 = ||R_d||_1 held exactly, eq. 5.19-5.20
  Manual,         ///< two 1D Gaussians, Freude eq. 5.21 (Jimenez's artist model)
  Deon,           ///< sum of R 2D Gaussians fitted to the profile, d'Eon & Luebke (Freude eq. 4.15)
  Jimenez         ///< the reference skin kernel with strength and falloff (separable_sss_kernel.md)
};

/// Parameters of the manual model (Freude eq. 5.21, Table A.1), per channel.
struct ManualGaussians {
  std::array<double, kChannels> sigmaNearMm{};  ///< sqrt(tau_n), mm (Table A.1 in cm, x10)
  std::array<double, kChannels> sigmaFarMm{};   ///< sqrt(tau_f), mm
  double nearWeight = 0.5;                      ///< w in [0, 1]: the near Gaussian's share
};

/// Parameters of Jimenez's reference kernel (separable_sss_kernel.md).
struct JimenezParameters {
  std::array<double, kChannels> strength{0.48, 0.41, 0.28};  ///< s: share of the blur vs the centre
  std::array<double, kChannels> falloff{1.0, 0.37, 0.3};     ///< f: per-channel width scale
};

/// How to build a kernel. Plain defaults reproduce Freude's settings.
struct KernelSettings {
  int taps = 17;                 ///< samples per 1D pass, odd >= 3; >= 2h+1 gives one tap per grid cell
  int rank = 1;                  ///< SVD rank, or d'Eon Gaussian count (each costs two 1D passes), 1..8
  bool normalizeEnergy = false;  ///< SVD: scale to the ground truth's 1-norm (eq. 5.12)
  int gridHalfCells = 100;       ///< h of the ground-truth grid (2h+1 cells per side)
  double guidedK = 1.0;          ///< Gamma's exponent k (eq. 5.20; 0 = plain least squares)
  double guidedB = 0.0;          ///< Gamma's axis term b, for kernel space [-1, 1] (0 = off)
  ManualGaussians manual;        ///< the manual model's parameters (see manualParameters)
  JimenezParameters jimenez;     ///< the reference kernel's parameters
};

/// A kernel ready for a shader, and what it was built from.
struct SeparableKernel {
  KernelModel model = KernelModel::PreIntegrated;
  std::vector<KernelComponent> components;  ///< one per rank (two 1D passes each)
  double cellMm = 0.1;                      ///< ground-truth grid cell, mm (for `dense`)
  int halfCells = 100;                      ///< h of the grid `dense` lives on

  /// The first component's taps (the whole kernel for rank-1 models).
  const std::vector<KernelTap>& taps() const { return components.front().taps; }
};

/// Builds `model` for the normalised ground truth `truth`. Errors: bad settings (even or too few
/// taps, rank out of range, manual parameters missing), or an optimisation that failed.
Result<SeparableKernel> buildKernel(const GroundTruthKernel& truth, KernelModel model,
                                    const KernelSettings& settings = {});

/// As above from a radial profile: rotates it into the grid first (groundTruthKernel).
Result<SeparableKernel> buildKernel(const RadialProfileRgb& profile, KernelModel model,
                                    const KernelSettings& settings = {});

/// As above from a material: its dipole profile (groundTruthProfile), then the grid.
Result<SeparableKernel> buildKernel(const ScatteringMaterial& material, KernelModel model,
                                    const KernelSettings& settings = {});

/// The model's command-line name: svd, preintegrated, guided, manual, deon, jimenez.
std::string_view kernelModelName(KernelModel model);

/// Parses a model name (case-insensitive). The error lists the names.
Result<KernelModel> parseKernelModel(std::string_view name);

/// Freude's Table A.1 parameters for Apple, Ketchup, Marble, Skin1 or Wholemilk (case-insensitive),
/// converted from cm to mm. The error names the materials that have them.
Result<ManualGaussians> manualParameters(std::string_view material);

/// The 2D kernel's total per channel, from the taps: sum over components of sign (sum of its taps'
/// weights)^2. 1 for every model that conserves energy (the ground truth is normalised to 1).
std::array<double, kChannels> kernelEnergy(const SeparableKernel& kernel);

}  // namespace tissue::optics
