// CPU reference convolution of irradiance over the surface (the texture-space model, exact).
#include "tissue/render/texture_space_reference.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <unordered_map>

namespace tissue::render {

Float3 evaluateProfile(const RadialProfileTable& table, float rMm) {
  const auto& r = table.radiusMm;
  if (r.empty() || rMm > r.back() || rMm < r.front()) return {};
  const auto hi = std::size_t(std::upper_bound(r.begin(), r.end(), rMm) - r.begin());
  if (hi >= r.size()) return table.value.back();
  const std::size_t lo = hi - 1;
  const float t = (rMm - r[lo]) / (r[hi] - r[lo]);
  const Float3 a = table.value[lo], b = table.value[hi];
  return {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), a.z + t * (b.z - a.z)};
}

namespace {

/// P(r) = integral_0^r 2 pi t R(t) dt per channel at the table's radii (trapezoids).
std::vector<Float3> cumulativeProfile(const RadialProfileTable& table) {
  std::vector<Float3> p(table.radiusMm.size());
  double acc[3] = {0.0, 0.0, 0.0};
  for (std::size_t k = 1; k < p.size(); ++k) {
    const double r0 = double(table.radiusMm[k - 1]), r1 = double(table.radiusMm[k]);
    const Float3 a = table.value[k - 1], b = table.value[k];
    const double f = std::numbers::pi * (r1 - r0);
    acc[0] += f * (r0 * double(a.x) + r1 * double(b.x));
    acc[1] += f * (r0 * double(a.y) + r1 * double(b.y));
    acc[2] += f * (r0 * double(a.z) + r1 * double(b.z));
    p[k] = {float(acc[0]), float(acc[1]), float(acc[2])};
  }
  return p;
}

Float3 lookup(const std::vector<float>& r, const std::vector<Float3>& v, double x) {
  if (r.empty() || x <= double(r.front())) return v.empty() ? Float3{} : v.front();
  if (x >= double(r.back())) return v.back();
  const auto hi = std::size_t(std::upper_bound(r.begin(), r.end(), float(x)) - r.begin());
  const std::size_t lo = hi - 1;
  const float t = float((x - double(r[lo])) / double(r[hi] - r[lo]));
  return {v[lo].x + t * (v[hi].x - v[lo].x), v[lo].y + t * (v[hi].y - v[lo].y),
          v[lo].z + t * (v[hi].z - v[lo].z)};
}

}  // namespace

std::vector<Float3> convolveOverSurface(const SurfaceSamples& samples, std::span<const Float3> queriesMm,
                                        const RadialProfileTable& profile, float cutoffMm) {
  // Step 1: hash the samples into cells of size cutoffMm.
  const double cell = std::max(double(cutoffMm), 1e-6);
  const auto key = [cell](Float3 p, int dx, int dy, int dz) {
    const auto x = std::int64_t(std::floor(double(p.x) / cell)) + dx,
               y = std::int64_t(std::floor(double(p.y) / cell)) + dy,
               z = std::int64_t(std::floor(double(p.z) / cell)) + dz;
    // 21 bits per axis: unique within a million cells each way, so no cell is visited twice.
    constexpr std::int64_t kMask = (1 << 21) - 1;
    return (std::uint64_t(x & kMask) << 42) | (std::uint64_t(y & kMask) << 21) | std::uint64_t(z & kMask);
  };
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> grid;
  for (std::uint32_t i = 0; i < samples.positionMm.size(); ++i)
    grid[key(samples.positionMm[i], 0, 0, 0)].push_back(i);
  // Step 2: for each query, the 27 neighbouring cells.
  const std::vector<Float3> cumulative = cumulativeProfile(profile);
  std::vector<Float3> out(queriesMm.size());
  const double cutoff2 = double(cutoffMm) * double(cutoffMm);
  for (std::size_t q = 0; q < queriesMm.size(); ++q) {
    const Float3 xo = queriesMm[q];
    double sum[3] = {0.0, 0.0, 0.0};
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const auto it = grid.find(key(xo, dx, dy, dz));
          if (it == grid.end()) continue;
          for (std::uint32_t i : it->second) {
            const Float3 xi = samples.positionMm[i];
            const double ex = double(xi.x - xo.x), ey = double(xi.y - xo.y), ez = double(xi.z - xo.z);
            const double d2 = ex * ex + ey * ey + ez * ez;
            if (d2 > cutoff2) continue;
            // R averaged over the annulus [d - rho, d + rho] the sample's disk (radius rho,
            // area A) sweeps: texels are wider than the narrowest Gaussians, so a point value
            // would over- or under-count their energy; the average keeps it exact.
            const double d = std::sqrt(d2), rho = std::sqrt(double(samples.areaMm2[i]) / std::numbers::pi);
            const double inner = std::max(d - rho, 0.0), outer = d + rho;
            const Float3 pin = lookup(profile.radiusMm, cumulative, inner);
            const Float3 pout = lookup(profile.radiusMm, cumulative, outer);
            const double ring = std::numbers::pi * (outer * outer - inner * inner);
            const Float3 r{float((double(pout.x) - double(pin.x)) / ring),
                           float((double(pout.y) - double(pin.y)) / ring),
                           float((double(pout.z) - double(pin.z)) / ring)};
            const Float3 e = samples.irradiance[i];
            const double a = double(samples.areaMm2[i]);
            sum[0] += double(r.x) * double(e.x) * a, sum[1] += double(r.y) * double(e.y) * a,
                sum[2] += double(r.z) * double(e.z) * a;
          }
        }
    out[q] = {float(sum[0]), float(sum[1]), float(sum[2])};
  }
  return out;
}

}  // namespace tissue::render
