// One mass on one spring: the analytic period, the exact per-step amplification of explicit and
// implicit Euler, and the bounded energy of the symplectic integrators.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "test_systems.h"
#include "tissue/sim/forces.h"
#include "tissue/sim/integrators.h"

namespace tissue::sim {
namespace {

constexpr double kMass = 1.0;       // g
constexpr double kStiffness = 0.1;  // N/mm
constexpr double kRest = 10.0;      // mm

State displaced(double u, double v) {
  return {{{}, {kRest + u, 0.0, 0.0}}, {{}, {v, 0.0, 0.0}}};
}

/// sqrt(w^2 u^2 + v^2): the norm in which one Euler step is a scaled rotation.
double phaseNorm(const State& s, double w) {
  const double u = s.x[1].x - kRest;
  return std::sqrt(w * w * u * u + s.v[1].x * s.v[1].x);
}

TEST(OneSpring, PeriodOfSymplecticIntegratorsWithinOnePercent) {
  const auto system = test::oneSpring(kMass, kStiffness, kRest);
  const double w = test::omega(kMass, kStiffness);
  const double period = 2.0 * std::numbers::pi / w;
  const double h = period / 1000.0;
  for (Integrator integrator : {Integrator::SymplecticEuler, Integrator::VelocityVerlet}) {
    State s = displaced(0.5, 0.0);
    StepWorkspace ws;
    // Upward zero crossings of the displacement, linearly interpolated.
    std::vector<double> crossings;
    double prev = s.x[1].x - kRest;
    for (int n = 1; n <= 10500; ++n) {
      step(integrator, system, s, h, ws);
      const double u = s.x[1].x - kRest;
      if (prev < 0.0 && u >= 0.0) crossings.push_back(h * (n - 1 + prev / (prev - u)));
      prev = u;
    }
    ASSERT_GE(crossings.size(), 10u) << integratorName(integrator);
    const double measured =
        (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
    EXPECT_NEAR(measured / period, 1.0, 0.01) << integratorName(integrator);
  }
}

TEST(OneSpring, ExactAmplificationOfExplicitAndImplicitEuler) {
  const auto system = test::oneSpring(kMass, kStiffness, kRest);
  const double w = test::omega(kMass, kStiffness);
  for (double hw : {0.05, 0.5, 1.0}) {
    const double h = hw / w;
    const double explicitFactor = std::sqrt(1.0 + hw * hw);
    // The fast solver is exact backward Euler here: along one line the local step's direction
    // is exact, so its first global step already solves the (then linear) equations.
    for (auto [integrator, expected] : {std::pair{Integrator::ExplicitEuler, explicitFactor},
                                        std::pair{Integrator::ImplicitEuler, 1.0 / explicitFactor},
                                        std::pair{Integrator::FastMassSpring, 1.0 / explicitFactor}}) {
      State s = displaced(0.05, 3.0);
      StepWorkspace ws;
      for (int n = 0; n < 8; ++n) {
        const double before = phaseNorm(s, w);
        const StepStats stats = step(integrator, system, s, h, ws, {.relativeTolerance = 1e-14});
        const double ratio = phaseNorm(s, w) / before;
        EXPECT_NEAR(ratio / expected, 1.0, 1e-9)
            << integratorName(integrator) << " h w = " << hw << " step " << n << " cg " << stats.cgIterations;
      }
    }
  }
}

/// Largest |E / E0 - 1| over steps [from, to) of a run of `steps` steps.
std::vector<double> energyErrors(Integrator integrator, double hw, int steps) {
  const auto system = test::oneSpring(kMass, kStiffness, kRest);
  const double w = test::omega(kMass, kStiffness);
  State s = displaced(0.5, 0.0);
  StepWorkspace ws;
  const double e0 = elasticEnergy(system, s.x);
  std::vector<double> errors;
  for (int n = 0; n < steps; ++n) {
    step(integrator, system, s, hw / w, ws);
    errors.push_back(std::abs((kineticEnergy(system, s.v) + elasticEnergy(system, s.x)) / e0 - 1.0));
  }
  return errors;
}

TEST(OneSpring, SymplecticEnergyErrorIsBoundedOverTenThousandSteps) {
  // The conserved modified energies give the sup of the energy error for the harmonic
  // oscillator, a = h w / 2: symplectic Euler 2a / (1 - a), velocity Verlet a^2 / (1 - a^2).
  const double hw = 0.2, a = hw / 2.0;
  for (auto [integrator, bound] : {std::pair{Integrator::SymplecticEuler, 2.0 * a / (1.0 - a)},
                                   std::pair{Integrator::VelocityVerlet, a * a / (1.0 - a * a)}}) {
    const auto errors = energyErrors(integrator, hw, 10000);
    const double firstMax = *std::max_element(errors.begin(), errors.begin() + 1000);
    const double lastMax = *std::max_element(errors.end() - 1000, errors.end());
    const double allMax = *std::max_element(errors.begin(), errors.end());
    EXPECT_LE(allMax, bound * (1.0 + 1e-9)) << integratorName(integrator);
    EXPECT_GT(allMax, 0.2 * bound) << integratorName(integrator) << ": the bound should be nearly reached";
    EXPECT_LE(lastMax, 1.01 * firstMax) << integratorName(integrator) << ": energy error grows";
  }
  // Explicit Euler at the same step gains energy every step: the same test must fail for it.
  const auto explicitErrors = energyErrors(Integrator::ExplicitEuler, hw, 10000);
  EXPECT_GT(explicitErrors.back(), 1e6);
}

}  // namespace
}  // namespace tissue::sim
