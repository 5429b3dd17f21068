// CPU reference convolution of irradiance over the surface (the texture-space model, exact).
#include "tissue/render/texture_space_reference.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
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
            const Float3 r = evaluateProfile(profile, float(std::sqrt(d2)));
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
