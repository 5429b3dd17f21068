#pragma once
/// \file
/// The few vector operations the viewer needs on tissue::Float3 (positions in mm, unit
/// directions). Inline, in the viewer's namespace, so they never leak into the library.

#include <cmath>

#include "tissue/core/types.h"

namespace tissue::viewer {

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
/// `a` scaled to unit length; `a` itself when it is (almost) zero.
inline Float3 normalize(Float3 a) {
  const float l = length(a);
  return l > 1e-20f ? a * (1.0f / l) : a;
}

}  // namespace tissue::viewer
