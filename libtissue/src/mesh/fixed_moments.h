#pragma once
// Exact moments of point sets for the plane fits. Positions are quantised to 2^-20 mm
// (about 1e-6 mm, finer than a float's resolution beyond 8 mm) relative to an origin; sums of
// the quantised coordinates and of their products are integers, so they can be updated
// incrementally without any rounding or drift, and the covariance n^2 C = n S2 - S1 S1^T is
// formed exactly before a single conversion to double.

#include <cmath>
#include <cstdint>

#include "tissue/core/types.h"

namespace tissue::mesh::detail {

__extension__ typedef __int128 Int128;  // GCC/Clang extension; exact 128-bit sums

inline constexpr double kQuantumPerMm = 1048576.0;  // 2^20 steps per mm

/// A quantised position (integer multiples of 2^-20 mm about the origin).
struct FixedPoint {
  std::int64_t x, y, z;
};

/// Rounds half up (floor(x + 1/2)), not half away from zero: then quantising about origins
/// that differ by whole quanta differs by exactly that integer shift, ties included, so the
/// covariance does not depend on the origin at all.
inline std::int64_t roundHalfUp(double x) {
  return std::int64_t(std::floor(x + 0.5));
}

inline FixedPoint quantise(Float3 p, Float3 origin) {
  // A float minus a float is exact in double, and so is the scaling by 2^20.
  return {roundHalfUp((double(p.x) - double(origin.x)) * kQuantumPerMm),
          roundHalfUp((double(p.y) - double(origin.y)) * kQuantumPerMm),
          roundHalfUp((double(p.z) - double(origin.z)) * kQuantumPerMm)};
}

/// Sums over a point set: count is implicit (the neighbourhood size).
struct FixedSums {
  std::int64_t s[3] = {0, 0, 0};      // sum q
  Int128 ss[6] = {0, 0, 0, 0, 0, 0};  // sum q q^T: xx xy xz yy yz zz

  void add(const FixedPoint& q, int sign) {
    s[0] += sign * q.x, s[1] += sign * q.y, s[2] += sign * q.z;
    ss[0] += sign * Int128(q.x) * q.x, ss[1] += sign * Int128(q.x) * q.y, ss[2] += sign * Int128(q.x) * q.z;
    ss[3] += sign * Int128(q.y) * q.y, ss[4] += sign * Int128(q.y) * q.z, ss[5] += sign * Int128(q.z) * q.z;
  }
  void add(const FixedSums& d) {
    for (int i = 0; i < 3; ++i)
      s[i] += d.s[i];
    for (int i = 0; i < 6; ++i)
      ss[i] += d.ss[i];
  }
};

}  // namespace tissue::mesh::detail
