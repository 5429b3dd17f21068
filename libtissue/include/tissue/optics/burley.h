#pragma once
/// \file
/// Christensen & Burley 2015, "Approximate Reflectance Profiles for Efficient Subsurface
/// Scattering": normalized diffusion (shared/reference/burley.md). r and d in mm, R in mm^-2.

namespace tissue::optics {

/// Which measurement the shape parameter d = l / s is fitted to (the paper's three fits).
enum class BurleyFit {
  SearchlightMfp,        ///< searchlight, l = mean free path: s = 1.85 - A + 7 |A - 0.8|^3
  DiffuseMfp,            ///< diffuse surface transmission, l = mfp: s = 1.9 - A + 3.5 (A - 0.8)^2
  SearchlightDiffuseMfp  ///< searchlight, l = diffuse mean free path: s = 3.5 + 100 (A - 0.33)^4
};

/// R(r) = A (e^(-r/d) + e^(-r/(3d))) / (8 pi d r), mm^-2; its integral over the plane is A.
/// Diverges (integrably) at r = 0; `r` > 0 in mm, `d` > 0 in mm.
double burleyProfile(double r, double d, double albedo);

/// Fraction of the profile inside radius r: 1 - (1/4) e^(-r/d) - (3/4) e^(-r/(3d)).
double burleyCdf(double r, double d);

/// Radius (mm) at which the CDF equals `u` in [0, 1), by Newton iteration on burleyCdf
/// (importance sampling of the profile). The median is 1.552183 d.
double burleySampleRadius(double u, double d);

/// The scaling factor s(A) of `fit` for surface albedo `albedo` in [0, 1].
double burleyScaling(double albedo, BurleyFit fit);

}  // namespace tissue::optics
