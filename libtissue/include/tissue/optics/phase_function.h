#pragma once
/// \file
/// The Henyey-Greenstein phase function. Convention: cos t is the cosine of the angle between the
/// direction of travel before and after scattering, so g > 0 scatters forward (light goes on
/// along its direction of travel).

namespace tissue::optics {

/// HG density per steradian, p(cos t) = (1/4pi) (1 - g^2) / (1 + g^2 - 2 g cos t)^(3/2);
/// it integrates to 1 over the sphere and its mean cosine is g. `g` in (-1, 1).
double henyeyGreenstein(double cosTheta, double g);

/// Samples cos t from HG with the uniform number `xi` in [0, 1]: MCML's inversion,
/// cos t = (1 + g^2 - ((1 - g^2) / (1 - g + 2 g xi))^2) / (2 g), and 2 xi - 1 for g = 0.
double sampleHenyeyGreenstein(double g, double xi);

}  // namespace tissue::optics
