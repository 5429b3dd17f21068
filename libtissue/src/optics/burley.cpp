// Christensen & Burley 2015 normalized diffusion (shared/reference/burley.md).
#include "tissue/optics/burley.h"

#include <cmath>
#include <numbers>

namespace tissue::optics {

double burleyProfile(double r, double d, double albedo) {
  return albedo * (std::exp(-r / d) + std::exp(-r / (3.0 * d))) / (8.0 * std::numbers::pi * d * r);
}

double burleyCdf(double r, double d) {
  return 1.0 - 0.25 * std::exp(-r / d) - 0.75 * std::exp(-r / (3.0 * d));
}

double burleySampleRadius(double u, double d) {
  // Newton on CDF(x) = u in units of d; the CDF is concave, so starting right of the root at the
  // upper bound 3 ln(1 / (1 - u)) the iterates decrease monotonically onto it.
  if (u <= 0.0) return 0.0;
  double x = 3.0 * std::log(1.0 / (1.0 - u)) + 1e-12;
  for (int i = 0; i < 50; ++i) {
    const double f = burleyCdf(x, 1.0) - u;
    const double pdf = 0.25 * std::exp(-x) + 0.25 * std::exp(-x / 3.0);  // dCDF/dx
    const double step = f / pdf;
    x -= step;
    if (std::abs(step) < 1e-13 * (1.0 + x)) break;
  }
  return x * d;
}

double burleyScaling(double albedo, BurleyFit fit) {
  const double a = albedo;
  switch (fit) {
    case BurleyFit::SearchlightMfp:
      return 1.85 - a + 7.0 * std::pow(std::abs(a - 0.8), 3.0);
    case BurleyFit::DiffuseMfp:
      return 1.9 - a + 3.5 * (a - 0.8) * (a - 0.8);
    case BurleyFit::SearchlightDiffuseMfp:
      return 3.5 + 100.0 * std::pow(a - 0.33, 4.0);
  }
  return 1.0;
}

}  // namespace tissue::optics
