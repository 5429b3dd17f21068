// The split reflectance of a semi-infinite medium (reflectance.h).
#include "tissue/optics/reflectance.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "tissue/optics/dipole.h"
#include "tissue/optics/fresnel.h"
#include "tissue/optics/schlick_phase.h"

namespace tissue::optics {

double entryFresnel(double eta, double cosIncident) {
  if (eta <= 1.0) return 0.0;
  return fresnelReflectance(1.0, eta, cosIncident).reflectance;
}

double singleScatteringNormalRadiance(double sigmaA, double sigmaS, double g, double eta) {
  const double sigmaT = sigmaA + sigmaS;
  if (!(sigmaT > 0.0)) return 0.0;
  const double t = 1.0 - entryFresnel(eta, 1.0);
  // Light travels down (0, 0, -1), leaves up (0, 0, 1): the cosine of the turn is -1.
  return t * t * (sigmaS / sigmaT) * schlickPhase(-1.0, schlickKFromG(g)) / 2.0;
}

double singleScatteringReflectance(double sigmaA, double sigmaS, double g, double eta) {
  const double sigmaT = sigmaA + sigmaS;
  if (!(sigmaT > 0.0)) return 0.0;
  // At depth z the beam is E e^(-sigma_t z); scattered towards mu_o it is attenuated by
  // e^(-sigma_t z / mu_o) along dz / mu_o: L = E alpha p / (1 + mu_o) with alpha = sigma_s / sigma_t.
  // Exit direction (sin, 0, mu_o) averaged over the azimuth: the turn from (0, 0, -1) has cos = -mu_o.
  const double tIn = 1.0 - entryFresnel(eta, 1.0), albedo = sigmaS / sigmaT, k = schlickKFromG(g);
  constexpr int kSteps = 2000;
  double sum = 0.0;
  for (int i = 0; i < kSteps; ++i) {
    const double mu = (i + 0.5) / kSteps;
    const double tOut = 1.0 - entryFresnel(eta, mu);
    sum += tOut * schlickPhase(-mu, k) / (1.0 + mu) * mu;
  }
  return tIn * albedo * sum * (2.0 * std::numbers::pi / kSteps);
}

Reflectance semiInfiniteReflectance(double sigmaA, double sigmaS, double g, double eta) {
  Reflectance r;
  r.single = singleScatteringReflectance(sigmaA, sigmaS, g, eta);
  // The dipole's R_d counts every order of scattering per entering light (it is 1 without
  // absorption, alpha' = 1), so the first order is already in it: the entering fraction
  // (1 - F(0)) of it, less the single-scattered part, keeps single + multiple <= 1 - F(0)
  // (Jensen et al. 2001 add the two, which counts the first order twice at high albedo).
  const double all =
      (1.0 - entryFresnel(eta, 1.0)) * dipoleTotalRd(makeDipole(sigmaA, sigmaS * (1.0 - g), eta));
  r.multiple = std::max(all - r.single, 0.0);
  return r;
}

}  // namespace tissue::optics
