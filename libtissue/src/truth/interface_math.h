#pragma once
// Private: the direction maths of the truth's transport, shared by the path tracer and the slab
// reference: mirror reflection, Snell refraction in vector form, Henyey-Greenstein directions.

#include <array>
#include <cmath>
#include <numbers>

#include <glm/glm.hpp>

#include "tissue/core/types.h"
#include "tissue/optics/phase_function.h"

namespace tissue::truth::detail {

/// A point or direction as the ray-mesh interface's array, and a Float3 in double precision.
inline std::array<double, 3> arr(const glm::dvec3& v) {
  return {v.x, v.y, v.z};
}
inline glm::dvec3 v3(Float3 f) {
  return {f.x, f.y, f.z};
}
inline double sq(double x) {
  return x * x;
}

/// `d` mirrored at the plane with unit normal `n` (either side).
inline glm::dvec3 reflect(const glm::dvec3& d, const glm::dvec3& n) {
  return d - 2.0 * glm::dot(d, n) * n;
}

/// Snell's law in vector form (Heckbert & Hanrahan 1984; pbrt-v3 eq. 8.8): the travel direction
/// `d` (unit) crossing a surface whose unit normal `n` faces against it (dot(d, n) < 0), from
/// index n1 into n2, with eta = n1 / n2, cosI = -dot(d, n) and the transmitted cosine cosT
/// (from optics::fresnelReflectance): t = eta d + (eta cosI - cosT) n.
inline glm::dvec3 refract(const glm::dvec3& d, const glm::dvec3& n, double eta, double cosI, double cosT) {
  return glm::normalize(eta * d + (eta * cosI - cosT) * n);
}

/// A new direction scattered from `d` by cos t = `cosTheta` and the azimuth (cos phi, sin phi)
/// (RandomStream::azimuth: no trigonometry), in an orthonormal basis around d (Duff et al. 2017,
/// "Building an orthonormal basis, revisited", listing 3).
inline glm::dvec3 scatterDirection(const glm::dvec3& d, double cosTheta, double cosPhi, double sinPhi) {
  const double sign = std::copysign(1.0, d.z);
  const double a = -1.0 / (sign + d.z);
  const double b = d.x * d.y * a;
  const glm::dvec3 t1(1.0 + sign * d.x * d.x * a, sign * b, -sign * d.x);
  const glm::dvec3 t2(b, sign + d.y * d.y * a, -d.y);
  const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
  return glm::normalize(sinTheta * cosPhi * t1 + sinTheta * sinPhi * t2 + cosTheta * d);
}

/// The same with the azimuth 2 pi `xi`.
inline glm::dvec3 scatterDirection(const glm::dvec3& d, double cosTheta, double xi) {
  const double phi = 2.0 * std::numbers::pi * xi;
  return scatterDirection(d, cosTheta, std::cos(phi), std::sin(phi));
}

}  // namespace tissue::truth::detail
