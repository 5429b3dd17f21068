// The split reflectance of a semi-infinite medium (reflectance.h).
#include "tissue/optics/reflectance.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "reflectance_table.h"
#include "tissue/optics/dipole.h"
#include "tissue/optics/fresnel.h"
#include "tissue/optics/schlick_phase.h"

namespace tissue::optics {

double entryFresnel(double eta, double cosIncident) {
  if (eta <= 1.0) return 0.0;
  return fresnelReflectance(1.0, eta, cosIncident).reflectance;
}

namespace {

// n^2 for a boundary (eta > 1), 1 without one (entryFresnel's convention).
double radianceSpread(double eta) {
  return eta > 1.0 ? eta * eta : 1.0;
}

}  // namespace

double singleScatteringNormalRadiance(double sigmaA, double sigmaS, double g, double eta) {
  const double sigmaT = sigmaA + sigmaS;
  if (!(sigmaT > 0.0)) return 0.0;
  const double t = 1.0 - entryFresnel(eta, 1.0);
  // Light travels down (0, 0, -1), leaves up (0, 0, 1): the cosine of the turn is -1. Leaving the
  // denser medium the radiance spreads over n^2 the solid angle (L / n^2 is invariant along a
  // ray: Hanrahan and Krueger 1993 §4, the truth's layeredSlabSingleScattering).
  return t * t * (sigmaS / sigmaT) * schlickPhase(-1.0, schlickKFromG(g)) / 2.0 / radianceSpread(eta);
}

double singleScatteringReflectance(double sigmaA, double sigmaS, double g, double eta) {
  const double sigmaT = sigmaA + sigmaS;
  if (!(sigmaT > 0.0)) return 0.0;
  // At depth z the beam is E e^(-sigma_t z); scattered towards the refracted exit cosine mu' it is
  // attenuated by e^(-sigma_t z / mu') along dz / mu': L' = E alpha p / (1 + mu') inside, with
  // alpha = sigma_s / sigma_t, and L = (1 - F(mu_o)) L' / n^2 outside (Hanrahan and Krueger 1993
  // §4: the view path refracts, Snell's law sin_o = n sin'). Exit direction (sin, 0, mu') averaged
  // over the azimuth: the turn from (0, 0, -1) has cos = -mu'.
  const double tIn = 1.0 - entryFresnel(eta, 1.0), albedo = sigmaS / sigmaT, k = schlickKFromG(g);
  const double spread = radianceSpread(eta);
  constexpr int kSteps = 2000;
  double sum = 0.0;
  for (int i = 0; i < kSteps; ++i) {
    const double mu = (i + 0.5) / kSteps;
    // One Fresnel evaluation gives both the exit transmittance and the refracted cosine mu'.
    const FresnelResult f = eta > 1.0 ? fresnelReflectance(1.0, eta, mu) : FresnelResult{0.0, mu};
    const double tOut = 1.0 - f.reflectance, inside = f.cosTransmitted;
    sum += tOut * schlickPhase(-inside, k) / (1.0 + inside) * mu / spread;
  }
  return tIn * albedo * sum * (2.0 * std::numbers::pi / kSteps);
}

double dipoleModelReflectance(double sigmaA, double sigmaS, double g, double eta) {
  // The dipole's R_d counts every order of scattering per entering light (it is 1 without
  // absorption, alpha' = 1), so the first order is already in it: the entering fraction
  // (1 - F(0)) of it, less the single-scattered part, keeps single + multiple <= 1 - F(0)
  // (Jensen et al. 2001 add the two, which counts the first order twice at high albedo).
  const double single = singleScatteringReflectance(sigmaA, sigmaS, g, eta);
  const double all =
      (1.0 - entryFresnel(eta, 1.0)) * dipoleTotalRd(makeDipole(sigmaA, sigmaS * (1.0 - g), eta));
  return std::max(all, single);
}

Reflectance semiInfiniteReflectance(double sigmaA, double sigmaS, double g, double eta) {
  Reflectance r;
  r.single = singleScatteringReflectance(sigmaA, sigmaS, g, eta);
  const double sp = sigmaS * (1.0 - g), reduced = sigmaA + sp > 0.0 ? sp / (sigmaA + sp) : 0.0;
  const double total =
      std::min(dipoleModelReflectance(sigmaA, sigmaS, g, eta) * monteCarloRatio(reduced, g, eta),
               1.0 - entryFresnel(eta, 1.0));
  r.multiple = std::max(total - r.single, 0.0);
  return r;
}

namespace {

// Linear interpolation weights of x on the sorted nodes (clamped): index of the lower node, weight of the
// upper.
template <std::size_t N>
std::pair<std::size_t, double> bracket(const std::array<double, N>& nodes, double x) {
  if (x <= nodes.front()) return {0, 0.0};
  if (x >= nodes.back()) return {N - 2, 1.0};
  std::size_t i = 0;
  while (nodes[i + 1] < x)
    ++i;
  return {i, (x - nodes[i]) / (nodes[i + 1] - nodes[i])};
}

}  // namespace

double monteCarloRatio(double reducedAlbedo, double g, double eta) {
  const double a = std::clamp(reducedAlbedo, 0.0, 1.0);
  const auto [ei, ew] = bracket(kReflectanceTableEta, eta);
  const auto [gi, gw] = bracket(kReflectanceTableG, g);
  // In x = sqrt(1 - a): the reflectance's natural variable near a = 1 (R ~ 1 - c x).
  const auto at = [&](std::size_t e, std::size_t k) {
    const double* row = kReflectanceRatio[e][k];  // 14 = kReflectanceTableAlbedo.size()
    const double x = std::sqrt(1.0 - a);
    const double xLast = std::sqrt(1.0 - kReflectanceTableAlbedo.back());
    if (x <= xLast) return 1.0 + (row[13] - 1.0) * x / xLast;  // ratio 1 at a = 1
    if (a <= kReflectanceTableAlbedo.front()) return row[0];
    std::size_t i = 0;
    while (kReflectanceTableAlbedo[i + 1] < a)
      ++i;
    const double x0 = std::sqrt(1.0 - kReflectanceTableAlbedo[i]),
                 x1 = std::sqrt(1.0 - kReflectanceTableAlbedo[i + 1]);
    return row[i] + (row[i + 1] - row[i]) * (x0 - x) / (x0 - x1);
  };
  // gi, gw by value: clang 14 (the fuzz tree's compiler) cannot capture structured bindings.
  const auto inG = [&at, gi = gi, gw = gw](std::size_t e) {
    return at(e, gi) * (1.0 - gw) + at(e, gi + 1) * gw;
  };
  return inG(ei) * (1.0 - ew) + inG(ei + 1) * ew;
}

}  // namespace tissue::optics
