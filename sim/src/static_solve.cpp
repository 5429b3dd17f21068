// Static equilibrium by regularised Newton steps (implicit-Euler steps from rest), see the header.
#include "tissue/sim/static_solve.h"

#include <algorithm>
#include <cmath>

#include "tissue/sim/forces.h"
#include "tissue/sim/units.h"

namespace tissue::sim {
namespace {

double potentialEnergy(const MassSpringSystem& system, std::span<const Vec3d> x) {
  return elasticEnergy(system, x) + gravityEnergy(system, x);
}

}  // namespace

double maxFreeForceN(const MassSpringSystem& system, std::span<const Vec3d> x) {
  std::vector<Vec3d> v(x.size()), f(x.size());
  ForceScratch scratch;
  computeForces(system, x, v, f, scratch);
  double worst = 0.0;
  for (std::size_t k = 0; k < x.size(); ++k)
    if (system.invMasses[k] != 0.0) worst = std::max(worst, length(f[k]));
  return forceToNewton(worst);
}

StaticSolveReport solveStatic(const MassSpringSystem& system, std::vector<Vec3d>& x,
                              const StaticSolveConfig& config) {
  StaticSolveReport report;
  StepWorkspace ws;
  double h = config.initialStep;
  double energy = potentialEnergy(system, x);
  report.residualN = maxFreeForceN(system, x);
  State trial;
  while (report.residualN > config.toleranceN && report.iterations < config.maxIterations) {
    ++report.iterations;
    // One implicit-Euler step from rest: x' = x + h^2 (M + h^2 K)^-1 f(x).
    trial.x = x;
    trial.v.assign(x.size(), Vec3d{});
    ws.previousDeltaV.clear();
    (void)stepImplicitEuler(system, trial, h, ws, config.linear);
    const double trialEnergy = potentialEnergy(system, trial.x);
    bool finite = std::isfinite(trialEnergy);
    for (const Vec3d& p : trial.x)
      finite = finite && isFinite(p);
    // Accept a step that lowers the energy or, at the energy's rounding floor, the residual.
    const double trialResidual = finite ? maxFreeForceN(system, trial.x) : 0.0;
    const bool lower = trialEnergy <= energy;
    const bool flat = trialEnergy <= energy + 1e-12 * std::abs(energy) && trialResidual < report.residualN;
    if (finite && (lower || flat)) {
      x = trial.x;
      energy = trialEnergy;
      report.residualN = trialResidual;
      ++report.acceptedSteps;
      h = std::min(config.maxStep, 4.0 * h);
    } else {
      h *= 0.25;
      if (h < 1e-12) break;  // no step lowers the energy any more: at a minimum within rounding
    }
  }
  report.converged = report.residualN <= config.toleranceN;
  report.potentialEnergy = energy;
  return report;
}

}  // namespace tissue::sim
