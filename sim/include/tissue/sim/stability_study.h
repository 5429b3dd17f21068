#pragma once
/// \file
/// The stability study: for one mass on one spring (the other end pinned), the largest time
/// step at which each integrator stays stable, found by bisection, against the theory
/// (symplectic Euler and Verlet: h < 2/omega = 2 sqrt(m/k); explicit Euler undamped: unstable at
/// every h; implicit Euler and the fast mass-spring solver: unconditionally stable).

#include <optional>
#include <vector>

#include "tissue/sim/integrators.h"

namespace tissue::sim {

/// One measured case.
struct StabilityCase {
  Integrator integrator{};
  double mass = 0.0;                  ///< g
  double stiffness = 0.0;             ///< N/mm
  double referenceDt = 0.0;           ///< s, 2 sqrt(m/k): the explicit-family limit
  std::optional<double> theoryMaxDt;  ///< s; none for explicit Euler (no stable h) and implicit (no limit)
  std::optional<double>
      measuredMaxDt;               ///< s; none when no stable h was found, or when stable up to maxDtTested
  double minDtTested = 0.0;        ///< s
  double maxDtTested = 0.0;        ///< s
  bool stableAtMaxTested = false;  ///< stable at maxDtTested (100 times the reference)
  int trials = 0;                  ///< simulations run
};

/// The study's grid and search.
struct StabilityStudyConfig {
  std::vector<Integrator> integrators{Integrator::ExplicitEuler, Integrator::SymplecticEuler,
                                      Integrator::VelocityVerlet, Integrator::ImplicitEuler,
                                      Integrator::FastMassSpring};
  std::vector<double> masses{0.1, 1.0, 10.0};       ///< g
  std::vector<double> stiffnesses{0.01, 0.1, 1.0};  ///< N/mm
  double maxFactor = 100.0;                         ///< largest h tested, times the reference
  double minFactor = 1e-3;                          ///< smallest h tested, times the reference
  double relativeTolerance = 1e-4;                  ///< bisection stops at (hi - lo) <= tolerance * lo
};

/// Whether `integrator` stays stable at step `h` (s) for mass (g) on a spring (N/mm), undamped,
/// no gravity: the energy stays finite, below 1e8 times its start, and does not keep growing
/// (the last quarter of the run never exceeds the earlier maximum by more than 1% + (h omega)^2).
bool isStableStep(Integrator integrator, double mass, double stiffness, double h);

/// Bisection for one integrator, mass (g) and stiffness (N/mm).
StabilityCase measureStability(Integrator integrator, double mass, double stiffness,
                               const StabilityStudyConfig& config = {});

/// Every combination of the config's integrators, masses and stiffnesses.
std::vector<StabilityCase> runStabilityStudy(const StabilityStudyConfig& config = {});

}  // namespace tissue::sim
