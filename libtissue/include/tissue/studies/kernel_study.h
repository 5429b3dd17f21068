#pragma once
/// \file
/// Freude 2014's comparison of separable kernels (Tables 6.3 and 6.5): every model of rank one,
/// and SVD and d'Eon kernels of rank 1..6, against the exact 2-D convolution with a material's
/// ground-truth kernel, in kernel space and on the thesis's test signals (image space). GL-free.
/// Lengths in mm.

#include <array>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "tissue/core/result.h"
#include "tissue/optics/kernel.h"
#include "tissue/optics/kernel_error.h"
#include "tissue/optics/materials.h"

namespace tissue::studies {

using Rgb = std::array<double, optics::kChannels>;

/// One kernel of the study: its label in the tables, model and settings.
struct KernelSpec {
  std::string label;
  optics::KernelModel model = optics::KernelModel::Svd;
  optics::KernelSettings settings;
};

/// The rank-one kernels of Table 6.3 (SVD1, SVD1 normalised, pre-integrated, guided k=1,
/// manual, d'Eon 1, Jimenez).
std::vector<KernelSpec> rankOneSpecs();

/// The test signals, by the names the tables use (edge, circle+squares, shaded patch).
const std::vector<std::pair<std::string, optics::TestSignal>>& kernelStudySignals();

/// One kernel's figures.
struct KernelRun {
  double buildMs = 0;                   ///< ms, wall clock, from the radial profile to the taps
  double buildCpuMs = 0;                ///< ms, process CPU time of the same (single-threaded)
  Rgb kernelRms{};                      ///< kernel-space RMS against the ground truth, per channel
  std::map<std::string, Rgb> imageRms;  ///< image-space RMS by signal name, per channel
  std::vector<double> sliceRed;         ///< A(0, x) of the red channel, per grid cell
};

/// One material's study.
struct KernelStudy {
  std::string name;
  double cellMm = 0;  ///< mm, the ground-truth grid's cell
  int halfCells = 0;
  std::vector<double> truthSliceRed;      ///< the ground truth's red A(0, x), per grid cell
  std::map<std::string, KernelRun> runs;  ///< by label; "SVD k" / "d'Eon k" for the rank study
};

/// Runs the study for `material` (its dipole ground truth on a 100-cell half grid, 256^2 test
/// signals). Errors name the material and the kernel.
Result<KernelStudy> studyKernels(const optics::ScatteringMaterial& material);

/// One kernel of a material built as a renderer builds it (dipole profile, 2-D grid, model,
/// taps), timed, with its errors against the ground truth: `tissue-sim kernel`.
struct KernelMeasurement {
  std::string material;
  optics::SeparableKernel kernel{};
  /// ms: wall and process CPU time (the build is single-threaded; CPU time is disturbed less by
  /// load) of the second build; the first build of a process also pays for faulting in cold code
  /// and memory, reported apart.
  double buildMs = 0, buildCpuMs = 0, buildFirstMs = 0;
  Rgb kernelRms{};  ///< over the (2h+1)^2 ground-truth grid normalised to 1
  Rgb imageRms{};   ///< on the circle-and-squares signal in [0, 1], 256^2 pixels of gridCellMm
  Rgb energy{};     ///< the kernel's 2-D sum per channel
  double gridCellMm = 0, kernelHalfWidthMm = 0;
};
Result<KernelMeasurement> measureKernel(const optics::ScatteringMaterial& material, optics::KernelModel model,
                                        const optics::KernelSettings& settings);

/// The measurement as `tissue-sim kernel` prints it: material, model, rank, taps ([w_R, w_G,
/// w_B, offset_mm]), components (rank > 1), build_ms, build_cpu_ms, build_first_ms, kernel_rms,
/// image_rms, energy, grid_cell_mm, kernel_half_width_mm, units; JSON text.
std::string kernelMeasurementJson(const KernelMeasurement& m);

/// The sum of the three channels.
inline double sum(const Rgb& v) {
  return v[0] + v[1] + v[2];
}

}  // namespace tissue::studies
