#pragma once
/// \file
/// The simulator's units, and the one place where the N/mm become internal units.
///
/// Inside the simulator lengths are mm, masses g and times s, so the consistent force unit is
/// g*mm/s^2 = 1e-6 N (a micronewton) and the consistent stiffness unit is g/s^2 = 1e-6 N/mm.
/// Configuration structs take the engineering units (N/mm, N*s/mm, N); the builders convert
/// them once with the constants below, and reports convert back.

namespace tissue::sim {

/// Internal force units (g*mm/s^2) per newton: 1 N = 1 kg*m/s^2 = 1e3 g * 1e3 mm/s^2.
inline constexpr double kForcePerNewton = 1.0e6;
/// Internal stiffness units (g/s^2) per N/mm: (1e6 g*mm/s^2) / mm.
inline constexpr double kStiffnessPerNewtonPerMm = kForcePerNewton;
/// Internal damping units (g/s) per N*s/mm: (1e6 g*mm/s^2) * s / mm.
inline constexpr double kDampingPerNewtonSecondPerMm = kForcePerNewton;
/// Standard gravity in mm/s^2.
inline constexpr double kStandardGravity = 9806.65;

/// N/mm -> g/s^2.
constexpr double stiffnessFromNewtonPerMm(double newtonPerMm) {
  return newtonPerMm * kStiffnessPerNewtonPerMm;
}
/// N*s/mm -> g/s.
constexpr double dampingFromNewtonSecondPerMm(double newtonSecondPerMm) {
  return newtonSecondPerMm * kDampingPerNewtonSecondPerMm;
}
/// g*mm/s^2 -> N.
constexpr double forceToNewton(double internalForce) {
  return internalForce / kForcePerNewton;
}

}  // namespace tissue::sim
