#include "tissue/sim/stability_study.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "tissue/sim/units.h"

namespace tissue::sim {
namespace {

constexpr double kRestLength = 10.0;    ///< mm
constexpr double kDisplacement = 0.1;   ///< mm, initial stretch along the spring
constexpr double kEnergyCeiling = 1e8;  ///< times the initial energy

/// One mass (vertex 1) on one spring from a pinned anchor (vertex 0) along x, no gravity, undamped.
MassSpringSystem oneSpring(double mass, double stiffness) {
  MassSpringSystem system;
  addSpring(system.springs, 0, 1, kRestLength, stiffness, 0.0);
  (void)finalizeSpringNetwork(system.springs, 2);  // valid by construction
  system.masses = {mass, mass};
  system.invMasses = {0.0, 1.0 / mass};
  system.config.gravity = {};
  return system;
}

}  // namespace

bool isStableStep(Integrator integrator, double mass, double stiffness, double h) {
  const MassSpringSystem system = oneSpring(mass, stiffness);
  const double omega = std::sqrt(stiffnessFromNewtonPerMm(stiffness) / mass);
  const double hw = h * omega;
  // Quarter of the run: at least 1000 steps and 4 oscillation periods.
  const long periodSteps = static_cast<long>(std::ceil(2.0 * std::numbers::pi / hw));
  const long quarter = std::max(1000L, 4 * periodSteps);

  State state{{{0.0, 0.0, 0.0}, {kRestLength + kDisplacement, 0.0, 0.0}}, {{}, {}}};
  StepWorkspace ws;
  const double e0 = elasticEnergy(system, state.x);
  double earlierMax = e0, lastMax = 0.0;
  for (long n = 0; n < 4 * quarter; ++n) {
    step(integrator, system, state, h, ws);
    const double e = kineticEnergy(system, state.v) + elasticEnergy(system, state.x);
    if (!std::isfinite(e) || e > kEnergyCeiling * e0) return false;
    if (n < 3 * quarter)
      earlierMax = std::max(earlierMax, e);
    else
      lastMax = std::max(lastMax, e);
  }
  // Growth test (catches explicit Euler at small h, where growth per step is only 1 + h^2 w^2);
  // the allowance covers the coarser sampling of the orbit at large h w.
  return lastMax <= (1.0 + 0.01 + hw * hw) * earlierMax;
}

StabilityCase measureStability(Integrator integrator, double mass, double stiffness,
                               const StabilityStudyConfig& config) {
  StabilityCase c;
  c.integrator = integrator;
  c.mass = mass;
  c.stiffness = stiffness;
  c.referenceDt = 2.0 * std::sqrt(mass / stiffnessFromNewtonPerMm(stiffness));
  if (integrator == Integrator::SymplecticEuler || integrator == Integrator::VelocityVerlet)
    c.theoryMaxDt = c.referenceDt;
  c.minDtTested = config.minFactor * c.referenceDt;
  c.maxDtTested = config.maxFactor * c.referenceDt;

  auto stable = [&](double h) {
    ++c.trials;
    return isStableStep(integrator, mass, stiffness, h);
  };
  if (stable(c.maxDtTested)) {
    c.stableAtMaxTested = true;
    return c;
  }
  // A stable lower bound: down by factors of 10 to the smallest step tested.
  double lo = c.maxDtTested, hi = c.maxDtTested;
  for (;;) {
    hi = lo;
    lo = std::max(lo / 10.0, c.minDtTested);
    if (stable(lo)) break;
    if (lo <= c.minDtTested) return c;  // unstable at every step tested
  }
  // Bisection between stable lo and unstable hi.
  while (hi - lo > config.relativeTolerance * lo) {
    const double mid = 0.5 * (lo + hi);
    (stable(mid) ? lo : hi) = mid;
  }
  c.measuredMaxDt = lo;
  return c;
}

std::vector<StabilityCase> runStabilityStudy(const StabilityStudyConfig& config) {
  std::vector<StabilityCase> cases;
  for (Integrator integrator : config.integrators)
    for (double m : config.masses)
      for (double k : config.stiffnesses)
        cases.push_back(measureStability(integrator, m, k, config));
  return cases;
}

}  // namespace tissue::sim
