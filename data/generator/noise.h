#pragma once
/// \file
/// Lattice noises in 3D (pattern space, mm): value noise, its fractal sum and cellular
/// (Worley 1996) noise. All are deterministic functions of the position and a seed.

#include <cstdint>

namespace tissue::datagen {

/// Value noise at `(x, y, z)` (lattice units), quintic interpolation; result in [-1, 1].
double valueNoise(double x, double y, double z, std::uint64_t seed);

/// Fractal sum of `octaves` value noises; frequency doubles and amplitude halves each octave.
/// Result roughly in [-1, 1] (normalised by the sum of amplitudes).
double fbm(double x, double y, double z, int octaves, std::uint64_t seed);

/// Distances (lattice units) from a point to the nearest and second-nearest feature points.
struct WorleyDistances {
  double f1 = 0.0;
  double f2 = 0.0;
};

/// Cellular noise (Worley 1996, "A cellular texture basis function"): one jittered feature point
/// per unit cell, nearest two among the 27 neighbouring cells.
WorleyDistances worley(double x, double y, double z, std::uint64_t seed);

/// Hermite smoothstep of `x` between `e0` and `e1`, clamped to [0, 1].
double smoothstep(double e0, double e1, double x);

}  // namespace tissue::datagen
