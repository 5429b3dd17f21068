#pragma once
/// \file
/// The reflectance of a homogeneous semi-infinite medium lit along its normal, split the way the
/// ray-marched method renders it (François et al. 2006 §2 single scattering; Jensen et al. 2001
/// §2.4: BSSRDF = single-scattering term + diffusion term): the single-scattered part as the
/// renderer's march computes it (refracted paths, Fresnel at entry and exit), the multiple-scattered part as
/// the dipole's total diffuse reflectance, and their sum, the albedo every shading method takes
/// its colour from (scene::opticalAlbedo). Coefficients in mm^-1; reflectances are unitless
/// fractions of the incident irradiance.
#include <array>

namespace tissue::optics {

/// The parts of one wavelength band's reflectance.
struct Reflectance {
  double single = 0.0;    ///< single scattering, hemispherical (cos-weighted over exit directions)
  double multiple = 0.0;  ///< multiple scattering: the dipole's total diffuse reflectance
  double total() const { return single + multiple; }
};

/// Single scattering of a half-space below an ambient of index 1 under normally incident
/// light, as the ray march computes it with a boundary (the view path refracted, Hanrahan and
/// Krueger 1993 §4): L(mu_o) / E = (1 - F(0)) (1 - F(mu_o)) alpha p(pi - theta') / ((1 + mu') n^2)
/// per steradian, mu' = cos theta' the refracted exit cosine (Snell), with the march's phase
/// function, Schlick's of k = schlickKFromG(g) (François et al. 2006 §3), integrated over the exit
/// hemisphere with mu_o. `sigmaA`, `sigmaS` mm^-1, `eta` the relative index (>= 1; 1: no boundary).
double singleScatteringReflectance(double sigmaA, double sigmaS, double g, double eta);

/// The single-scattered radiance factor at normal view under normal light, L(1) / E in sr^-1:
/// (1 - F(0))^2 alpha p(-1) / (2 n^2) (the integrand above at mu_o = 1; Schlick's phase of k =
/// schlickKFromG(g)).
double singleScatteringNormalRadiance(double sigmaA, double sigmaS, double g, double eta);

/// The band's reflectance parts: single as singleScatteringReflectance; multiple as the
/// entering fraction (1 - F(0)) of dipoleTotalRd(makeDipole(sigma_a, sigma_s (1 - g), eta))
/// (Jensen 2001, the BRDF approximation's R_d, the boundary in its term A) less the single
/// part, which the dipole's all-orders R_d already holds, the total then corrected to the 1D
/// Monte Carlo by monteCarloRatio (the dipole alone is 20 % too bright at reduced albedo 0.87
/// and 3-4x at 0.2 with g = 0.9: docs/RESULTS.md); total() <= 1 - F(0).
Reflectance semiInfiniteReflectance(double sigmaA, double sigmaS, double g, double eta);

/// The dipole model's total alone: single + max((1 - F(0)) R_d - single, 0), before the
/// Monte Carlo correction.
double dipoleModelReflectance(double sigmaA, double sigmaS, double g, double eta);

/// The nodes of the Monte Carlo correction table (reflectance_table.cpp): eta, g and reduced
/// albedo sigma_s' / (sigma_a + sigma_s'); at reduced albedo 1 the ratio is 1 (both return all
/// that enters).
inline constexpr std::array<double, 3> kReflectanceTableEta{1.3, 1.4, 1.5};
inline constexpr std::array<double, 5> kReflectanceTableG{0.0, 0.4, 0.8, 0.9, 0.97};
inline constexpr std::array<double, 14> kReflectanceTableAlbedo{0.05, 0.1, 0.2,  0.3,  0.4,  0.5,   0.6,
                                                                0.7,  0.8, 0.87, 0.92, 0.95, 0.975, 0.99};

/// The 1D Monte Carlo's diffuse reflectance (MCML's model, optics/monte_carlo.h, 10^4 photons a
/// node) over dipoleModelReflectance, interpolated (linear in sqrt(1 - reduced albedo), g and
/// eta; clamped to the nodes' range in g and eta; linear to 1 at reduced albedo 1).
double monteCarloRatio(double reducedAlbedo, double g, double eta);

/// The Fresnel reflectance of unpolarised light entering a medium of relative index `eta`
/// from the ambient (index 1) at incident cosine `cosIncident`; 0 at eta = 1.
double entryFresnel(double eta, double cosIncident);

}  // namespace tissue::optics
