#pragma once
/// \file
/// Jensen, Marschner, Levoy & Hanrahan 2001, "A Practical Model for Subsurface Light Transport":
/// the dipole diffusion profile of a semi-infinite medium (shared/reference/dipole.md).
/// Lengths in mm, coefficients in mm^-1, R_d in mm^-2.

namespace tissue::optics {

/// The dipole's derived quantities for one wavelength.
struct Dipole {
  double alphaPrime = 0.0;  ///< reduced albedo sigma_s' / sigma_t'
  double sigmaTr = 0.0;     ///< effective transport coefficient sqrt(3 sigma_a sigma_t'), mm^-1
  double zr = 0.0;          ///< depth of the real source 1/sigma_t', mm
  double zv = 0.0;          ///< height of the virtual source z_r (1 + 4A/3), mm
  double a = 1.0;           ///< boundary mismatch A = (1 + F_dr) / (1 - F_dr)
};

/// Diffuse Fresnel reflectance F_dr = -1.440/eta^2 + 0.710/eta + 0.668 + 0.0636 eta (Jensen 2001, a fit to
/// the integral of the Fresnel reflectance).
double diffuseFresnelReflectance(double eta);

/// The dipole for absorption `sigmaA` and reduced scattering `sigmaSPrime` (mm^-1), relative index `eta`.
Dipole makeDipole(double sigmaA, double sigmaSPrime, double eta);

/// R_d(r), mm^-2 (Jensen 2001, the diffusion term without the Fresnel factors): alpha'/(4 pi) [z_r (1 +
/// sigma_tr d_r) e^(-sigma_tr d_r)/d_r^3 + z_v (1 + sigma_tr d_v) e^(-sigma_tr d_v)/d_v^3]. `r` in mm.
double dipoleRd(const Dipole& dipole, double r);

/// The closed-form integral of R_d over the plane: (alpha'/2)(1 + e^(-(4/3) A sqrt(3(1-alpha'))))
/// e^(-sqrt(3(1-alpha'))) (Jensen 2001, its BRDF approximation).
double dipoleTotalRd(const Dipole& dipole);

}  // namespace tissue::optics
