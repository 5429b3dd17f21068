#pragma once
// Private inline vector helpers for the mesh module's hot loops (float in, double where the
// sums need it). Eigen is used where there is linear algebra to do; these are just the basics.

#include <cmath>

#include "tissue/core/types.h"

namespace tissue::mesh::detail {

inline Float3 operator+(Float3 a, Float3 b) {
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}
inline Float3 operator-(Float3 a, Float3 b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
inline Float3 operator*(Float3 a, float s) {
  return {a.x * s, a.y * s, a.z * s};
}
inline float dot(Float3 a, Float3 b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
inline Float3 cross(Float3 a, Float3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline float length(Float3 a) {
  return std::sqrt(dot(a, a));
}
/// Unit vector, or `fallback` when `a` is (nearly) zero.
inline Float3 normalizeOr(Float3 a, Float3 fallback) {
  const float len = length(a);
  return len > 1e-20f ? a * (1.0f / len) : fallback;
}
inline bool isFinite(Float3 a) {
  return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z);
}

}  // namespace tissue::mesh::detail
