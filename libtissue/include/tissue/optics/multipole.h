#pragma once
/// \file
/// Donner & Jensen 2005, "Light Diffusion in Multi-Layered Translucent Materials": the multipole
/// profile of a slab of thickness d (reflectance and transmittance), as summarised in
/// shared/reference/dipole.md. Lengths in mm, coefficients in mm^-1, profiles in mm^-2.

#include <vector>

#include "tissue/optics/dipole.h"

namespace tissue::optics {

/// A slab's dipole pairs: real sources at z_r,i, virtual sources at z_v,i (mm, from the top).
struct Multipole {
  Dipole dipole;                 ///< alpha', sigma_tr, A (from the same coefficients)
  double thicknessMm = 1.0;      ///< slab thickness d, mm
  std::vector<double> zReal;     ///< z_r,i = 2 i (d + 2 z_b) + l, i = -n..n, mm
  std::vector<double> zVirtual;  ///< z_v,i = 2 i (d + 2 z_b) - l - 2 z_b, mm
};

/// The multipole with `pairs` pairs on each side of the central dipole (i = -pairs..pairs; ~10
/// suffice). z_b = 2 A D with D = 1/(3 sigma_t'), l = 1/sigma_t'. Meaningful for thicknessMm > l: in a
/// thinner slab the real source lies below the slab and T(r) turns negative (a limit of the model).
Multipole makeMultipole(double sigmaA, double sigmaSPrime, double eta, double thicknessMm, int pairs = 10);

/// Reflectance profile R(r), mm^-2: alpha'/(4 pi) sum_i [z_r,i (1 + sigma_tr d_r,i) e^(-sigma_tr d_r,i)
/// / d_r,i^3 - z_v,i (...)], d_x,i = sqrt(r^2 + z_x,i^2). `r` in mm.
double multipoleR(const Multipole& m, double r);

/// Transmittance profile T(r), mm^-2: as multipoleR with (d - z) in place of z.
double multipoleT(const Multipole& m, double r);

/// Total reflectance, the integral of R over the plane in closed form: each source at height z
/// contributes (alpha'/2) sign(z) e^(-sigma_tr |z|) (the integral of z (1 + s d) e^(-s d) / d^3 2 pi r dr).
double multipoleTotalR(const Multipole& m);

/// Total transmittance, the closed-form integral of T over the plane.
double multipoleTotalT(const Multipole& m);

}  // namespace tissue::optics
