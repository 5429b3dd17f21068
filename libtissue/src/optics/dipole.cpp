// Jensen et al. 2001 dipole (shared/reference/dipole.md).
#include "tissue/optics/dipole.h"

#include <cmath>
#include <numbers>

namespace tissue::optics {

double diffuseFresnelReflectance(double eta) {
  return -1.440 / (eta * eta) + 0.710 / eta + 0.668 + 0.0636 * eta;
}

Dipole makeDipole(double sigmaA, double sigmaSPrime, double eta) {
  Dipole d;
  const double sigmaTPrime = sigmaA + sigmaSPrime;
  const double fdr = diffuseFresnelReflectance(eta);
  d.alphaPrime = sigmaSPrime / sigmaTPrime;
  d.sigmaTr = std::sqrt(3.0 * sigmaA * sigmaTPrime);
  d.a = (1.0 + fdr) / (1.0 - fdr);
  d.zr = 1.0 / sigmaTPrime;
  d.zv = d.zr * (1.0 + 4.0 * d.a / 3.0);
  return d;
}

namespace {
// One source term z (1 + sigma_tr d) e^(-sigma_tr d) / d^3 with d = sqrt(r^2 + z^2).
double sourceTerm(double z, double sigmaTr, double r) {
  const double dist = std::sqrt(r * r + z * z);
  return z * (1.0 + sigmaTr * dist) * std::exp(-sigmaTr * dist) / (dist * dist * dist);
}
}  // namespace

double dipoleRd(const Dipole& d, double r) {
  // Jensen 2001 (the radiant exitance of the real and the mirrored virtual source).
  return d.alphaPrime / (4.0 * std::numbers::pi) *
         (sourceTerm(d.zr, d.sigmaTr, r) + sourceTerm(d.zv, d.sigmaTr, r));
}

double dipoleTotalRd(const Dipole& d) {
  // Jensen 2001; equals (alpha'/2)(e^(-sigma_tr z_r) + e^(-sigma_tr z_v)).
  const double root = std::sqrt(3.0 * (1.0 - d.alphaPrime));
  return 0.5 * d.alphaPrime * (1.0 + std::exp(-4.0 / 3.0 * d.a * root)) * std::exp(-root);
}

}  // namespace tissue::optics
