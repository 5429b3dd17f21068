#pragma once
/// \file
/// A double-precision 3-vector for the simulator's state (positions in mm, velocities in mm/s,
/// forces in g*mm/s^2). The solver runs in double so that rounding stays far below the
/// analytic tolerances; results go out as tissue::Float3 (see state.h).

#include <cmath>

namespace tissue::sim {

/// Three doubles; the unit is the field's (mm, mm/s, g*mm/s^2).
struct Vec3d {
  double x = 0.0;
  double y = 0.0;
  double z = 0.0;
  friend bool operator==(const Vec3d&, const Vec3d&) = default;
};

inline Vec3d operator+(const Vec3d& a, const Vec3d& b) {
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}
inline Vec3d operator-(const Vec3d& a, const Vec3d& b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
inline Vec3d operator-(const Vec3d& a) {
  return {-a.x, -a.y, -a.z};
}
inline Vec3d operator*(double s, const Vec3d& a) {
  return {s * a.x, s * a.y, s * a.z};
}
inline Vec3d& operator+=(Vec3d& a, const Vec3d& b) {
  a.x += b.x;
  a.y += b.y;
  a.z += b.z;
  return a;
}
inline Vec3d& operator-=(Vec3d& a, const Vec3d& b) {
  a.x -= b.x;
  a.y -= b.y;
  a.z -= b.z;
  return a;
}
inline double dot(const Vec3d& a, const Vec3d& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
inline double length(const Vec3d& a) {
  return std::sqrt(dot(a, a));
}
inline bool isFinite(const Vec3d& a) {
  return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z);
}

}  // namespace tissue::sim
