#include "noise.h"

#include <algorithm>
#include <cmath>

#include "rng.h"

namespace tissue::datagen {
namespace {

double quintic(double t) {
  return t * t * t * (t * (t * 6.0 - 15.0) + 10.0);
}

double latticeValue(std::int32_t x, std::int32_t y, std::int32_t z, std::uint64_t seed) {
  return 2.0 * toUnit(hashLattice(x, y, z, seed)) - 1.0;
}

double lerp(double a, double b, double t) {
  return a + (b - a) * t;
}

}  // namespace

double valueNoise(double x, double y, double z, std::uint64_t seed) {
  const double fx = std::floor(x), fy = std::floor(y), fz = std::floor(z);
  const auto ix = std::int32_t(fx), iy = std::int32_t(fy), iz = std::int32_t(fz);
  const double tx = quintic(x - fx), ty = quintic(y - fy), tz = quintic(z - fz);
  double plane[2];
  for (int k = 0; k < 2; ++k) {
    const double c00 = latticeValue(ix, iy, iz + k, seed), c10 = latticeValue(ix + 1, iy, iz + k, seed);
    const double c01 = latticeValue(ix, iy + 1, iz + k, seed);
    const double c11 = latticeValue(ix + 1, iy + 1, iz + k, seed);
    plane[k] = lerp(lerp(c00, c10, tx), lerp(c01, c11, tx), ty);
  }
  return lerp(plane[0], plane[1], tz);
}

double fbm(double x, double y, double z, int octaves, std::uint64_t seed) {
  double sum = 0.0, amplitude = 1.0, norm = 0.0;
  for (int o = 0; o < octaves; ++o) {
    // Each octave gets its own seed and a small offset so lattice points do not line up.
    sum += amplitude * valueNoise(x + 0.37 * o, y + 0.71 * o, z + 0.13 * o, seed + std::uint64_t(o));
    norm += amplitude;
    amplitude *= 0.5;
    x *= 2.0;
    y *= 2.0;
    z *= 2.0;
  }
  return sum / norm;
}

WorleyDistances worley(double x, double y, double z, std::uint64_t seed) {
  const double fx = std::floor(x), fy = std::floor(y), fz = std::floor(z);
  const auto ix = std::int32_t(fx), iy = std::int32_t(fy), iz = std::int32_t(fz);
  double d1 = 1e30, d2 = 1e30;  // squared distances
  for (int dz = -1; dz <= 1; ++dz) {
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        const std::uint64_t h = hashLattice(ix + dx, iy + dy, iz + dz, seed);
        const double px = fx + dx + toUnit(mix64(h + 1)) - x;
        const double py = fy + dy + toUnit(mix64(h + 2)) - y;
        const double pz = fz + dz + toUnit(mix64(h + 3)) - z;
        const double d = px * px + py * py + pz * pz;
        if (d < d1) {
          d2 = d1;
          d1 = d;
        } else if (d < d2) {
          d2 = d;
        }
      }
    }
  }
  return {std::sqrt(d1), std::sqrt(d2)};
}

double smoothstep(double e0, double e1, double x) {
  const double t = std::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

}  // namespace tissue::datagen
