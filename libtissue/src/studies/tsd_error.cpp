// Texture-space diffusion's diffused map against the CPU reference of its own model.
#include "tissue/studies/tsd_error.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace tissue::studies {

// The CPU reference of texture-space diffusion's own model: the samples of a full-size,
// unculled irradiance map read back (every drawn texel with its world position and its area
// |dP/du x dP/dv| / T^2, mm^2, from the stretch map's b = sqrt(|dP/du x dP/dv|)).
render::SurfaceSamples surfaceSamplesOf(const render::TextureSpaceMaps& maps) {
  render::SurfaceSamples samples;
  const double t2 = double(maps.size) * double(maps.size);
  for (std::size_t t = 0; t < maps.irradiance.pixels.size(); ++t) {
    const Float4 e = maps.irradiance.pixels[t], p = maps.position.pixels[t], st = maps.stretch.pixels[t];
    if (e.w <= 0.0f) continue;
    samples.positionMm.push_back({p.x, p.y, p.z});
    samples.areaMm2.push_back(float(double(st.z) * double(st.z) / t2));
    samples.irradiance.push_back({e.x, e.y, e.z});
  }
  return samples;
}

TexelError diffusedMapError(const render::TextureSpaceMaps& maps, const render::SurfaceSamples& samples,
                            const render::RadialProfileTable& profile, float cutoffMm) {
  const int t = maps.size;
  const auto covered = [&](int x, int y) {
    return x >= 0 && y >= 0 && x < t && y < t && maps.diffused.at(x, y).w >= 0.999f;
  };
  std::vector<Float3> queries, actual;
  std::vector<bool> interior;
  for (int y = 0; y < t; ++y)
    for (int x = 0; x < t; ++x) {
      if (!covered(x, y)) continue;
      const Float4 d = maps.diffused.at(x, y), p = maps.position.at(x, y);
      queries.push_back({p.x, p.y, p.z});
      actual.push_back({d.x / d.w, d.y / d.w, d.z / d.w});
      bool inside = true;
      for (int j = -3; j <= 3 && inside; ++j)
        for (int i = -3; i <= 3 && inside; ++i)
          inside = covered(x + i, y + j);
      interior.push_back(inside);
    }
  const auto reference = render::convolveOverSurface(samples, queries, profile, cutoffMm);
  double sum[2] = {}, mean[2] = {};
  for (std::size_t i = 0; i < actual.size(); ++i) {
    const Float3 a = actual[i], r = reference[i];
    const double e =
        double((a.x - r.x) * (a.x - r.x) + (a.y - r.y) * (a.y - r.y) + (a.z - r.z) * (a.z - r.z));
    for (int k = 0; k < (interior[i] ? 2 : 1); ++k)
      sum[k] += e, mean[k] += double(r.x + r.y + r.z);
  }
  TexelError out;
  out.rms = std::sqrt(sum[0] / (3.0 * double(std::max<std::size_t>(actual.size(), 1))));
  out.relative = mean[0] > 0.0 ? std::sqrt(sum[0] * 3.0 * double(actual.size())) / mean[0] : 0.0;
  const double n1 = double(std::count(interior.begin(), interior.end(), true));
  out.interiorRelative = mean[1] > 0.0 ? std::sqrt(sum[1] * 3.0 * n1) / mean[1] : 0.0;
  return out;
}

}  // namespace tissue::studies
