#pragma once
// The kernel models' private interface: each turns a normalised ground-truth grid into dense
// components on that grid (one file per model); kernel.cpp samples their taps.
#include <array>
#include <vector>

#include "tissue/core/result.h"
#include "tissue/optics/kernel.h"

namespace tissue::optics::detail {

/// A component on the grid: a_c per channel (2h+1 cells) and its sign per channel.
struct DenseComponent {
  std::array<std::vector<double>, kChannels> a;
  std::array<double, kChannels> sign{1.0, 1.0, 1.0};
};

/// Rank-R SVD (kernel_svd.cpp).
Result<std::vector<DenseComponent>> svdComponents(const GroundTruthKernel& truth, int rank, bool normalize);
/// Pre-integration (kernel_preintegrated.cpp).
std::vector<DenseComponent> preIntegratedComponents(const GroundTruthKernel& truth);
/// Guided optimisation (kernel_guided.cpp).
Result<std::vector<DenseComponent>> guidedComponents(const GroundTruthKernel& truth, double k, double b);
/// Manual two-Gaussian model (kernel_manual.cpp).
std::vector<DenseComponent> manualComponents(const GroundTruthKernel& truth, const ManualGaussians& p);
/// d'Eon sum of Gaussians on the grid, one component per Gaussian (kernel_gaussians.cpp).
std::vector<DenseComponent> gaussianComponents(const GroundTruthKernel& truth, const GaussianSum& sum);
/// Jimenez's reference kernel on the grid (kernel_jimenez.cpp).
std::vector<DenseComponent> jimenezComponents(const GroundTruthKernel& truth, const JimenezParameters& p);

/// Importance-sampled taps of one dense component (kernel_taps.cpp): the centre, then (taps-1)/2
/// offsets on each side at equal shares of the channel-summed |a|; each tap's weight is the
/// integral of a over the span nearest to it, so the weights keep the component's sum exactly.
/// taps >= 2h+1 gives one tap per cell.
std::vector<KernelTap> sampleTaps(const DenseComponent& component, double cellMm, int taps);

/// Integral over the cell [x - 1/2, x + 1/2] (x in cells) of a 1D Gaussian of variance
/// `varianceCells2` (cells^2), normalised to 1 on the line.
double gaussianCellIntegral(double xCells, double varianceCells2);

}  // namespace tissue::optics::detail
