// Schlick phase function (shared/reference/phase_functions.md; François et al. 2006, §3).
#include "tissue/optics/schlick_phase.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace tissue::optics {

double schlickPhase(double cosTheta, double k) {
  const double denom = 1.0 - k * cosTheta;
  return (1.0 - k * k) / (4.0 * std::numbers::pi * denom * denom);
}

double schlickKFromG(double g) {
  return std::clamp(1.55 * g - 0.55 * g * g * g, -kSchlickMaxK, kSchlickMaxK);
}

double schlickMeanCosine(double k) {
  if (std::abs(k) < 1e-8) return 0.0;
  // 2 pi int mu p(mu) dmu over [-1, 1] = (1 - k^2)/(2 k^2) [ln((1 - k)/(1 + k)) + 2k/(1 - k^2)].
  const double kk = k * k;
  return (1.0 - kk) / (2.0 * kk) * (std::log((1.0 - k) / (1.0 + k)) + 2.0 * k / (1.0 - kk));
}

}  // namespace tissue::optics
