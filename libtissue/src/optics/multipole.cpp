// Donner & Jensen 2005 multipole for a slab (shared/reference/dipole.md).
#include "tissue/optics/multipole.h"

#include <cmath>
#include <numbers>

namespace tissue::optics {

Multipole makeMultipole(double sigmaA, double sigmaSPrime, double eta, double thicknessMm, int pairs) {
  Multipole m;
  m.dipole = makeDipole(sigmaA, sigmaSPrime, eta);
  m.thicknessMm = thicknessMm;
  const double l = 1.0 / (sigmaA + sigmaSPrime);   // depth of the real source, mm
  const double diffusion = l / 3.0;                // D = 1 / (3 sigma_t'), mm
  const double zb = 2.0 * m.dipole.a * diffusion;  // extrapolated boundary distance, mm
  // Mirror the source at both extrapolated boundaries, repeatedly (Donner & Jensen 2005).
  for (int i = -pairs; i <= pairs; ++i) {
    const double shift = 2.0 * i * (thicknessMm + 2.0 * zb);
    m.zReal.push_back(shift + l);
    m.zVirtual.push_back(shift - l - 2.0 * zb);
  }
  return m;
}

namespace {
// z (1 + s d) e^(-s d) / d^3, d = sqrt(r^2 + z^2): the exitance of a source at signed height z.
double sourceTerm(double z, double sigmaTr, double r) {
  const double dist = std::sqrt(r * r + z * z);
  return z * (1.0 + sigmaTr * dist) * std::exp(-sigmaTr * dist) / (dist * dist * dist);
}
// Integral of sourceTerm over the plane divided by 2 pi: sign(z) e^(-sigma_tr |z|).
double sourceTotal(double z, double sigmaTr) {
  return std::copysign(std::exp(-sigmaTr * std::abs(z)), z);
}
}  // namespace

double multipoleR(const Multipole& m, double r) {
  double sum = 0;
  for (std::size_t i = 0; i < m.zReal.size(); ++i)
    sum += sourceTerm(m.zReal[i], m.dipole.sigmaTr, r) - sourceTerm(m.zVirtual[i], m.dipole.sigmaTr, r);
  return m.dipole.alphaPrime / (4.0 * std::numbers::pi) * sum;
}

double multipoleT(const Multipole& m, double r) {
  const double d = m.thicknessMm;
  double sum = 0;
  for (std::size_t i = 0; i < m.zReal.size(); ++i)
    sum +=
        sourceTerm(d - m.zReal[i], m.dipole.sigmaTr, r) - sourceTerm(d - m.zVirtual[i], m.dipole.sigmaTr, r);
  return m.dipole.alphaPrime / (4.0 * std::numbers::pi) * sum;
}

double multipoleTotalR(const Multipole& m) {
  double sum = 0;
  for (std::size_t i = 0; i < m.zReal.size(); ++i)
    sum += sourceTotal(m.zReal[i], m.dipole.sigmaTr) - sourceTotal(m.zVirtual[i], m.dipole.sigmaTr);
  return 0.5 * m.dipole.alphaPrime * sum;
}

double multipoleTotalT(const Multipole& m) {
  const double d = m.thicknessMm;
  double sum = 0;
  for (std::size_t i = 0; i < m.zReal.size(); ++i)
    sum += sourceTotal(d - m.zReal[i], m.dipole.sigmaTr) - sourceTotal(d - m.zVirtual[i], m.dipole.sigmaTr);
  return 0.5 * m.dipole.alphaPrime * sum;
}

}  // namespace tissue::optics
