// The ground-truth profile and its rotation into a 2D kernel (Freude 2014, §6.1).
#include "tissue/optics/ground_truth_kernel.h"

#include <algorithm>
#include <cmath>

#include "tissue/optics/dipole.h"

namespace tissue::optics {

double evaluateProfile(const RadialProfileRgb& profile, int channel, double r) {
  const auto& rs = profile.radiusMm;
  const auto& v = profile.value[static_cast<std::size_t>(channel)];
  if (rs.empty() || r > rs.back()) return 0.0;
  if (r <= rs.front()) return v.front();
  const auto hi = static_cast<std::size_t>(std::upper_bound(rs.begin(), rs.end(), r) - rs.begin());
  if (hi >= rs.size()) return v.back();
  const double t = (r - rs[hi - 1]) / (rs[hi] - rs[hi - 1]);
  return v[hi - 1] + t * (v[hi] - v[hi - 1]);
}

Result<RadialProfileRgb> groundTruthProfile(const ScatteringMaterial& material) {
  RadialProfileRgb profile;
  profile.name = material.name;
  std::array<Dipole, kChannels> dipoles;
  double halfWidth = 0;
  for (int c = 0; c < kChannels; ++c) {
    const double sa = material.sigmaA[static_cast<std::size_t>(c)];
    const double sps = material.sigmaSPrime(c);
    if (!(sa > 0.0) || !(sps > 0.0) || !std::isfinite(sa + sps) || !(material.eta >= 1.0))
      return Error{"material '" + material.name + "', channel " + std::to_string(c) +
                   ": the dipole ground truth needs sigma_a > 0, sigma_s' > 0 (mm^-1) and eta >= 1"};
    dipoles[static_cast<std::size_t>(c)] = makeDipole(sa, sps, material.eta);
    // The extent `tissue-sim profile` uses: 6 diffusion lengths, at most 30 mean free paths.
    const double sigmaTr = dipoles[static_cast<std::size_t>(c)].sigmaTr;
    halfWidth = std::max(halfWidth, std::min(6.0 / sigmaTr, 30.0 / (sa + sps)));
  }
  profile.kernelHalfWidthMm = halfWidth;
  const int samples = 4096;
  const double rMax = std::sqrt(2.0) * halfWidth * 1.001;
  for (int i = 0; i < samples; ++i) {
    const double r = rMax * i / (samples - 1);
    profile.radiusMm.push_back(r);
    for (int c = 0; c < kChannels; ++c)
      profile.value[static_cast<std::size_t>(c)].push_back(dipoleRd(dipoles[static_cast<std::size_t>(c)], r));
  }
  return profile;
}

Result<GroundTruthKernel> groundTruthKernel(const RadialProfileRgb& profile, int halfCells) {
  if (halfCells < 2 || halfCells > 400)
    return Error{"ground-truth kernel of '" + profile.name + "': half size " + std::to_string(halfCells) +
                 " cells is out of range; use 2..400"};
  if (!(profile.kernelHalfWidthMm > 0.0) || profile.radiusMm.size() < 2)
    return Error{"ground-truth kernel of '" + profile.name +
                 "': the profile needs >= 2 samples and a positive kernel half-width (mm)"};
  GroundTruthKernel k;
  k.name = profile.name;
  k.profile = profile;
  k.halfCells = halfCells;
  k.cellMm = profile.kernelHalfWidthMm / (halfCells + 0.5);
  const int n = k.size();
  const int sub = 4;  // 4x4 point samples per cell: the peak at r = 0 is narrow for some materials
  for (int c = 0; c < kChannels; ++c) {
    auto& v = k.values[static_cast<std::size_t>(c)];
    v.assign(static_cast<std::size_t>(n * n), 0.0);
    double sum = 0;
    for (int y = 0; y < n; ++y) {
      for (int x = 0; x < n; ++x) {
        double cell = 0;
        for (int sy = 0; sy < sub; ++sy) {
          for (int sx = 0; sx < sub; ++sx) {
            const double px = (x - halfCells + (sx + 0.5) / sub - 0.5) * k.cellMm;
            const double py = (y - halfCells + (sy + 0.5) / sub - 0.5) * k.cellMm;
            cell += evaluateProfile(profile, c, std::hypot(px, py));
          }
        }
        v[static_cast<std::size_t>(y * n + x)] = cell;
        sum += cell;
      }
    }
    if (!(sum > 0.0) || !std::isfinite(sum))
      return Error{"ground-truth kernel of '" + profile.name + "': channel " + std::to_string(c) +
                   " has no energy inside the kernel; check the profile"};
    for (double& x : v)
      x /= sum;  // Freude §6.2: each channel sums to 1
  }
  return k;
}

}  // namespace tissue::optics
