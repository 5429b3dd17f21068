// Henyey-Greenstein phase function and its sampling (shared/reference/phase_functions.md).
#include "tissue/optics/phase_function.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace tissue::optics {

double henyeyGreenstein(double cosTheta, double g) {
  const double denom = 1.0 + g * g - 2.0 * g * cosTheta;
  return (1.0 - g * g) / (4.0 * std::numbers::pi * denom * std::sqrt(denom));
}

double sampleHenyeyGreenstein(double g, double xi) {
  if (std::abs(g) < 1e-6) return 2.0 * xi - 1.0;
  // Inverse of the HG cumulative distribution in cos t.
  const double f = (1.0 - g * g) / (1.0 - g + 2.0 * g * xi);
  return std::clamp((1.0 + g * g - f * f) / (2.0 * g), -1.0, 1.0);
}

}  // namespace tissue::optics
