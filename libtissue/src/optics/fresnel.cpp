// Unpolarised Fresnel reflectance, in MCML's form (MCML manual, "Reflection or transmission at boundary").
#include "tissue/optics/fresnel.h"

#include <algorithm>
#include <cmath>

namespace tissue::optics {

FresnelResult fresnelReflectance(double n1, double n2, double cosIncident) {
  const double cosI = std::clamp(cosIncident, 0.0, 1.0);
  if (n1 == n2) return {0.0, cosI};
  if (cosI > 1.0 - 1e-12) {  // normal incidence
    const double r = (n2 - n1) / (n2 + n1);
    return {r * r, cosI};
  }
  if (cosI < 1e-6) return {1.0, 0.0};  // grazing
  const double sinI = std::sqrt(1.0 - cosI * cosI);
  const double sinT = n1 * sinI / n2;
  if (sinT >= 1.0) return {1.0, 0.0};  // total internal reflection
  const double cosT = std::sqrt(1.0 - sinT * sinT);
  // cos(a +- b), sin(a +- b) with a the incident and b the transmitted angle.
  const double cosSum = cosI * cosT - sinI * sinT;
  const double cosDiff = cosI * cosT + sinI * sinT;
  const double sinSum = sinI * cosT + cosI * sinT;
  const double sinDiff = sinI * cosT - cosI * sinT;
  const double r =
      0.5 * sinDiff * sinDiff * (cosDiff * cosDiff + cosSum * cosSum) / (sinSum * sinSum * cosDiff * cosDiff);
  return {std::clamp(r, 0.0, 1.0), cosT};
}

}  // namespace tissue::optics
