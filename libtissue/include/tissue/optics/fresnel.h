#pragma once
/// \file
/// Fresnel reflection of unpolarised light at a plane interface (MCML manual, "Reflection or transmission at
/// boundary").

namespace tissue::optics {

/// What happens at an interface: the reflectance and, if light is transmitted, its cosine.
struct FresnelResult {
  double reflectance = 1.0;     ///< in [0, 1]; 1 under total internal reflection
  double cosTransmitted = 0.0;  ///< cosine of the refraction angle to the normal (>= 0)
};

/// Unpolarised Fresnel reflectance from index `n1` into `n2` for an incident cosine
/// `cosIncident` in [0, 1] to the normal: R = 1/2 [sin^2(a-b)/sin^2(a+b) + tan^2(a-b)/tan^2(a+b)].
/// Total internal reflection gives R = 1.
FresnelResult fresnelReflectance(double n1, double n2, double cosIncident);

}  // namespace tissue::optics
