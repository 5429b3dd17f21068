// Jimenez et al.'s reference separable skin kernel, re-derived from the steps in
// shared/reference/separable_sss_kernel.md (Freude eq. 4.8).
#include "tissue/optics/kernel_jimenez.h"

#include <cmath>

#include "kernel_models.h"

namespace tissue::optics {
namespace {

// Step 1: the reference's Gaussian, with its literal 3.14 (it cancels in the normalisation).
double referenceGaussian(double variance, double rr) {
  return std::exp(-rr * rr / (2.0 * variance)) / (2.0 * 3.14 * variance);
}

}  // namespace

double jimenezProfile(const JimenezParameters& p, int channel, double rMm) {
  // Step 2: d'Eon's red skin column without its narrowest Gaussian (the strength takes its role).
  const double rr = rMm / (0.001 + p.falloff[static_cast<std::size_t>(channel)]);
  return 0.100 * referenceGaussian(0.0484, rr) + 0.118 * referenceGaussian(0.187, rr) +
         0.113 * referenceGaussian(0.567, rr) + 0.358 * referenceGaussian(1.99, rr) +
         0.078 * referenceGaussian(7.41, rr);
}

std::vector<KernelTap> jimenezTaps(const JimenezParameters& p, int taps) {
  const auto n = static_cast<std::size_t>(taps);
  // Step 3: quadratic offsets, denser near 0.
  const double range = taps > 20 ? 3.0 : 2.0;
  std::vector<double> offset(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double o = -range + static_cast<double>(i) * 2.0 * range / (taps - 1);
    offset[i] = std::copysign(o * o / range, o);
  }
  // Step 4: weight = P(offset) times the span between the neighbours' midpoints.
  std::vector<std::array<double, kChannels>> w(n);
  for (std::size_t i = 0; i < n; ++i) {
    double area = 0;
    if (i > 0) area += std::abs(offset[i] - offset[i - 1]) / 2.0;
    if (i + 1 < n) area += std::abs(offset[i] - offset[i + 1]) / 2.0;
    for (int c = 0; c < kChannels; ++c)
      w[i][static_cast<std::size_t>(c)] = jimenezProfile(p, c, std::abs(offset[i])) * area;
  }
  // Step 5: the centre sample first; each channel normalised to sum 1.
  std::vector<std::size_t> order{n / 2};
  for (std::size_t i = 0; i < n; ++i)
    if (i != n / 2) order.push_back(i);
  std::array<double, kChannels> sum{};
  for (const auto& wi : w)
    for (std::size_t c = 0; c < kChannels; ++c)
      sum[c] += wi[c];
  std::vector<KernelTap> out;
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t i = order[k];
    std::array<double, kChannels> v{};
    for (std::size_t c = 0; c < kChannels; ++c) {
      // Step 6: strength keeps (1 - s) of the centre; each channel still sums to 1.
      v[c] = w[i][c] / sum[c] * p.strength[c] + (k == 0 ? 1.0 - p.strength[c] : 0.0);
    }
    out.push_back({{static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2])},
                   static_cast<float>(offset[i])});
  }
  return out;
}

namespace detail {

std::vector<DenseComponent> jimenezComponents(const GroundTruthKernel& truth, const JimenezParameters& p) {
  // The same kernel before sampling, on the grid: s P(|x|) normalised, plus (1 - s) at the centre.
  const int n = truth.size();
  DenseComponent comp;
  for (int c = 0; c < kChannels; ++c) {
    const auto ch = static_cast<std::size_t>(c);
    auto& a = comp.a[ch];
    double sum = 0;
    for (int j = 0; j < n; ++j) {
      a.push_back(jimenezProfile(p, c, std::abs(j - truth.halfCells) * truth.cellMm));
      sum += a.back();
    }
    for (double& v : a)
      v *= p.strength[ch] / sum;
    a[static_cast<std::size_t>(truth.halfCells)] += 1.0 - p.strength[ch];
  }
  return {comp};
}

}  // namespace detail
}  // namespace tissue::optics
