#pragma once
/// \file
/// The small vector maths on the plain types, written once for every module and app: Float3
/// arithmetic, bounds, and column-major 4x4 affine transforms (the model matrices of
/// render::SceneObject and the C API). Modules with real linear algebra use Eigen or GLM inside.

#include <algorithm>
#include <array>
#include <cmath>
#include <span>

#include "tissue/core/types.h"

namespace tissue {

inline Float3 operator+(Float3 a, Float3 b) {
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}
inline Float3 operator-(Float3 a, Float3 b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
inline Float3 operator-(Float3 a) {
  return {-a.x, -a.y, -a.z};
}
inline Float3 operator*(Float3 a, float s) {
  return {a.x * s, a.y * s, a.z * s};
}
inline Float3 operator*(float s, Float3 a) {
  return a * s;
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
/// `a` scaled to unit length; `a` itself when it is (nearly) zero.
inline Float3 normalize(Float3 a) {
  return normalizeOr(a, a);
}
inline bool isFinite(Float3 a) {
  return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z);
}

/// An axis-aligned box, mm. Empty (lo > hi) until a point is added.
struct Bounds3 {
  Float3 lo{1e30f, 1e30f, 1e30f};
  Float3 hi{-1e30f, -1e30f, -1e30f};
  bool empty() const { return lo.x > hi.x; }
  void add(Float3 p) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  void add(const Bounds3& b) {
    if (!b.empty()) add(b.lo), add(b.hi);
  }
  Float3 centre() const { return (lo + hi) * 0.5f; }
};

/// The bounds of `points` (empty for none).
inline Bounds3 boundsOf(std::span<const Float3> points) {
  Bounds3 b;
  for (const Float3& p : points)
    b.add(p);
  return b;
}

/// A 4x4 matrix, column-major (element (row r, column c) at [c * 4 + r]), as GL and the C API
/// take it. Model matrices map object space (mm) to world space (mm).
using Mat4 = std::array<float, 16>;

inline constexpr Mat4 kIdentity4{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

/// m * (p, 1): a point (mm).
inline Float3 transformPoint(const Mat4& m, Float3 p) {
  return {m[0] * p.x + m[4] * p.y + m[8] * p.z + m[12], m[1] * p.x + m[5] * p.y + m[9] * p.z + m[13],
          m[2] * p.x + m[6] * p.y + m[10] * p.z + m[14]};
}
/// m * (d, 0): a direction or a displacement (no translation).
inline Float3 transformDirection(const Mat4& m, Float3 d) {
  return {m[0] * d.x + m[4] * d.y + m[8] * d.z, m[1] * d.x + m[5] * d.y + m[9] * d.z,
          m[2] * d.x + m[6] * d.y + m[10] * d.z};
}
/// The determinant of the upper 3x3 part (its volume scale; < 0 mirrors).
inline float determinant3(const Mat4& m) {
  return m[0] * (m[5] * m[10] - m[9] * m[6]) - m[4] * (m[1] * m[10] - m[9] * m[2]) +
         m[8] * (m[1] * m[6] - m[5] * m[2]);
}
/// Whether the bottom row is (0, 0, 0, 1), every entry is finite and the 3x3 part invertible.
inline bool isAffineInvertible(const Mat4& m) {
  for (float v : m)
    if (!std::isfinite(v)) return false;
  if (m[3] != 0.0f || m[7] != 0.0f || m[11] != 0.0f || m[15] != 1.0f) return false;
  return std::abs(determinant3(m)) > 1e-12f;
}
/// The inverse of an affine `m` (isAffineInvertible(m) must hold).
inline Mat4 inverseAffine(const Mat4& m) {
  // The 3x3 part's inverse by cofactors, then the translation -A^-1 t.
  const float a = m[0], b = m[4], c = m[8], d = m[1], e = m[5], f = m[9], g = m[2], h = m[6], i = m[10];
  const float det = a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g);
  const float s = 1.0f / det;
  Mat4 r{};
  r[0] = (e * i - f * h) * s, r[4] = (c * h - b * i) * s, r[8] = (b * f - c * e) * s;
  r[1] = (f * g - d * i) * s, r[5] = (a * i - c * g) * s, r[9] = (c * d - a * f) * s;
  r[2] = (d * h - e * g) * s, r[6] = (b * g - a * h) * s, r[10] = (a * e - b * d) * s;
  const Float3 t = transformDirection(r, {m[12], m[13], m[14]});
  r[12] = -t.x, r[13] = -t.y, r[14] = -t.z, r[15] = 1.0f;
  return r;
}
/// The world bounds of object bounds `b` under `m` (its eight corners transformed).
inline Bounds3 transformBounds(const Mat4& m, const Bounds3& b) {
  Bounds3 out;
  if (b.empty()) return out;
  for (int corner = 0; corner < 8; ++corner)
    out.add(transformPoint(
        m, {(corner & 1) ? b.hi.x : b.lo.x, (corner & 2) ? b.hi.y : b.lo.y, (corner & 4) ? b.hi.z : b.lo.z}));
  return out;
}

}  // namespace tissue
