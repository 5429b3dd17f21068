#pragma once
// Private: the direction maths of the truth's transport, shared by the path tracer and the slab
// reference: mirror reflection, Snell refraction in vector form, Henyey-Greenstein directions.

#include <cmath>
#include <numbers>

#include <glm/glm.hpp>

#include "tissue/optics/phase_function.h"

namespace tissue::truth::detail {

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

/// A new direction scattered from `d` by cos t = `cosTheta` and azimuth 2 pi `xi` (an orthonormal
/// basis around d: Duff et al. 2017, "Building an orthonormal basis, revisited", listing 3).
inline glm::dvec3 scatterDirection(const glm::dvec3& d, double cosTheta, double xi) {
  const double sign = std::copysign(1.0, d.z);
  const double a = -1.0 / (sign + d.z);
  const double b = d.x * d.y * a;
  const glm::dvec3 t1(1.0 + sign * d.x * d.x * a, sign * b, -sign * d.x);
  const glm::dvec3 t2(b, sign + d.y * d.y * a, -d.y);
  const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
  const double phi = 2.0 * std::numbers::pi * xi;
  return glm::normalize(sinTheta * std::cos(phi) * t1 + sinTheta * std::sin(phi) * t2 + cosTheta * d);
}

}  // namespace tissue::truth::detail
