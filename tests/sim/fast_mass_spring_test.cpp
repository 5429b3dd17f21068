// The fast mass-spring solver (Liu et al. 2013): rest stays rest bit for bit, the hanging chain's
// analytic equilibrium, stability far above the explicit limit, convergence to the exact
// backward-Euler step with more iterations, and the factor cache.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "test_systems.h"
#include "tissue/sim/forces.h"
#include "tissue/sim/integrators.h"
#include "tissue/sim/simulator.h"
#include "tissue/sim/units.h"

namespace tissue::sim {
namespace {

TEST(FastMassSpring, RestStateStaysExactlyAtRest) {
  // Damping of every kind and pins, but no gravity: nothing should move, to the last bit.
  const test::Patch patch = test::gridPatch(12, 9, 1.5f);
  const SystemConfig config{.gravity = {}, .rayleighMass = 0.5, .rayleighStiffness = 1e-4};
  const auto system = test::patchSystem(patch, 0.1, 1e-5, 2.0, {0, 5, 11}, config);
  const State rest = restState(patch.positions);
  State s = rest;
  StepWorkspace ws;
  for (int n = 0; n < 20; ++n)
    step(Integrator::FastMassSpring, system, s, 0.01, ws);
  EXPECT_EQ(std::memcmp(s.x.data(), rest.x.data(), s.x.size() * sizeof(Vec3d)), 0);
  EXPECT_EQ(std::memcmp(s.v.data(), rest.v.data(), s.v.size() * sizeof(Vec3d)), 0);
}

TEST(FastMassSpring, HangingChainReachesTheAnalyticEquilibrium) {
  // As HangingChain.StaticEquilibriumMatchesTheAnalyticStretch: link i carries the weight of
  // every mass below it, so its length is L0 + g sum_{j >= i} m_j / k_i.
  constexpr int kN = 10;
  constexpr double kL0 = 5.0;  // mm
  SpringNetwork springs;
  std::vector<double> masses{1.0};
  for (int i = 1; i <= kN; ++i) {
    addSpring(springs, i - 1, i, kL0, 0.05 + 0.01 * i, 2e-4);
    masses.push_back(0.5 + 0.1 * i);
  }
  ASSERT_TRUE(finalizeSpringNetwork(springs, kN + 1).ok());
  const std::uint32_t pinned[] = {0};
  const SystemConfig config{.gravity = {0.0, -kStandardGravity, 0.0}, .rayleighMass = 2.0};
  const auto system = makeSystem(springs, masses, pinned, config).value();
  State s;
  for (int i = 0; i <= kN; ++i)
    s.x.push_back({0.0, -kL0 * i, 0.0});
  s.v.assign(kN + 1, Vec3d{});
  StepWorkspace ws;
  for (int n = 0; n < 3000; ++n)
    step(Integrator::FastMassSpring, system, s, 0.01, ws);
  double y = 0.0;
  for (int i = 1; i <= kN; ++i) {
    double below = 0.0;
    for (int j = i; j <= kN; ++j)
      below += masses[j];
    y -= kL0 + kStandardGravity * below / stiffnessFromNewtonPerMm(0.05 + 0.01 * i);
    EXPECT_NEAR(s.x[i].y, y, 1e-7) << "vertex " << i;
    EXPECT_NEAR(s.x[i].x, 0.0, 1e-12);
  }
  EXPECT_EQ(s.x[0].y, 0.0);  // the pin held exactly
}

TEST(FastMassSpring, StableAtHundredTimesTheExplicitLimit) {
  const test::Patch patch = test::gridPatch(8, 8, 2.0f);
  std::vector<std::uint32_t> pinned{0, 1, 2, 3, 4, 5, 6, 7};
  const auto system = test::patchSystem(patch, 0.1, 0.0, 2.0, pinned, {.gravity = {}});
  const double limit = 2.0 / test::largestOmega(system, restState(patch.positions).x);
  State s = restState(patch.positions);
  s.v = test::pseudoRandomVelocities(s.v.size(), 5.0);
  for (std::uint32_t p : pinned)
    s.v[p] = {};
  const double e0 = kineticEnergy(system, s.v);
  // With a fixed 10 iterations a step is not exactly backward Euler; what must hold is that
  // no energy is gained and the high modes are damped out (symplectic Euler blows up at this
  // step: ImplicitEuler.StableAtHundredTimesTheExplicitLimit). Starting the iterations from the
  // inertial prediction alone fails this: the energy peaks at about 300 e0 in the first steps.
  StepWorkspace ws;
  double peak = 0.0, late = 0.0;
  for (int n = 0; n < 1000; ++n) {
    step(Integrator::FastMassSpring, system, s, 100.0 * limit, ws);
    const double e = kineticEnergy(system, s.v) + elasticEnergy(system, s.x);
    ASSERT_TRUE(std::isfinite(e)) << "step " << n;
    peak = std::max(peak, e);
    if (n >= 800) late = std::max(late, e);
  }
  EXPECT_LE(peak, e0);
  EXPECT_LE(late, 0.01 * e0);
}

/// |M (x' - x - h v) - h^2 f(x', v')| over the free vertices, v' = (x' - x) / h: the residual of
/// the exact (nonlinear) backward-Euler step, with f the full force (springs, gravity, Rayleigh
/// mass damping) evaluated by the force pass, independently of either solver.
double backwardEulerResidual(const MassSpringSystem& system, const State& start, const State& end, double h) {
  std::vector<Vec3d> f(start.x.size());
  ForceScratch scratch;
  computeForces(system, end.x, end.v, f, scratch);
  double sum = 0.0;
  for (std::size_t k = 0; k < f.size(); ++k) {
    if (system.invMasses[k] == 0.0) continue;
    const Vec3d r = system.masses[k] * (end.x[k] - start.x[k] - h * start.v[k]) - (h * h) * f[k];
    sum += dot(r, r);
  }
  return std::sqrt(sum);
}

TEST(FastMassSpring, MoreIterationsConvergeToTheExactBackwardEulerStep) {
  // A sagging, spinning patch at 5 times the explicit limit, so that the step is far from
  // linear (the linearised step's residual is a third of the residual of not moving). Rayleigh mass damping
  // is exact in the fast solver; no spring or stiffness damping.
  const test::Patch patch = test::gridPatch(7, 6, 2.0f);
  const SystemConfig config{.rayleighMass = 1.0};
  const auto system = test::patchSystem(patch, 0.05, 0.0, 1.0, {0, 6}, config);
  const double h = 5.0 * 2.0 / test::largestOmega(system, restState(patch.positions).x);
  State start = restState(patch.positions);
  start.v = test::pseudoRandomVelocities(start.v.size(), 30.0);
  start.v[0] = start.v[6] = {};

  auto fastStep = [&](int iterations) {
    State s = start;
    StepWorkspace ws;
    step(Integrator::FastMassSpring, system, s, h, ws, {.localGlobalIterations = iterations});
    return s;
  };
  const State reference = fastStep(10000);
  double previousResidual = INFINITY, previousDistance = INFINITY;
  for (int iterations : {10, 30, 100, 300, 1000, 3000}) {
    const State s = fastStep(iterations);
    const double residual = backwardEulerResidual(system, start, s, h);
    double distance = 0.0;
    for (std::size_t k = 0; k < s.x.size(); ++k)
      distance = std::max(distance, length(s.x[k] - reference.x[k]));
    EXPECT_LT(residual, previousResidual) << iterations << " iterations";
    EXPECT_LT(distance, previousDistance) << iterations << " iterations";
    previousResidual = residual, previousDistance = distance;
  }
  // Converged, the step solves the nonlinear backward-Euler equations (to rounding), which
  // the linearised implicit Euler (one Newton step) does not.
  State linearised = start;
  StepWorkspace ws;
  step(Integrator::ImplicitEuler, system, linearised, h, ws, {.relativeTolerance = 1e-14});
  const double linearisedResidual = backwardEulerResidual(system, start, linearised, h);
  const double convergedResidual = backwardEulerResidual(system, start, reference, h);
  const double scale = backwardEulerResidual(system, start, start, h);  // the residual of not moving
  EXPECT_LT(convergedResidual, 1e-9 * scale);
  EXPECT_GT(linearisedResidual, 1e3 * convergedResidual);
}

TEST(FastMassSpring, FactorIsCachedPerSystemAndStep) {
  const test::Patch patch = test::gridPatch(5, 5, 2.0f);
  auto system = test::patchSystem(patch, 0.1, 0.0, 1.0, {0}, {});
  State s = restState(patch.positions);
  StepWorkspace ws;
  EXPECT_TRUE(step(Integrator::FastMassSpring, system, s, 1e-3, ws).refactored);
  EXPECT_FALSE(step(Integrator::FastMassSpring, system, s, 1e-3, ws).refactored);
  EXPECT_TRUE(step(Integrator::FastMassSpring, system, s, 2e-3, ws).refactored);  // new h
  EXPECT_FALSE(step(Integrator::FastMassSpring, system, s, 2e-3, ws).refactored);
  system.springs.stiffness[3] *= 2.0;  // edited in place
  EXPECT_TRUE(step(Integrator::FastMassSpring, system, s, 2e-3, ws).refactored);
  system.invMasses[7] = 0.0;  // a new pin
  EXPECT_TRUE(step(Integrator::FastMassSpring, system, s, 2e-3, ws).refactored);
  StepWorkspace copy = ws;  // a copy starts without a factor
  EXPECT_TRUE(step(Integrator::FastMassSpring, system, s, 2e-3, copy).refactored);
  EXPECT_EQ(step(Integrator::FastMassSpring, system, s, 2e-3, ws, {.localGlobalIterations = 7})
                .localGlobalIterations,
            7);
}

TEST(FastMassSpring, NamedOnTheCommandLine) {
  EXPECT_EQ(integratorName(Integrator::FastMassSpring), "fast-mass-spring");
  EXPECT_EQ(parseIntegrator("fast-mass-spring"), Integrator::FastMassSpring);
}

TEST(FastMassSpring, SimulatorRefactorsOnlyWhenPinsOrGraspsChange) {
  // The simulator keys the factor on its own revision (bumped by setKinematic), not on a
  // fingerprint pass per step: frames refactor only after the kinematic set changed.
  const test::Patch patch = test::gridPatch(6, 6, 2.0f);
  auto system = test::patchSystem(patch, 0.1, 1e-5, 1.0, {0, 5}, {});
  SimulatorConfig config{.integrator = Integrator::FastMassSpring, .frameTime = 1.0 / 60.0, .substeps = 4};
  auto sim = Simulator::create(system, restState(patch.positions), config);
  ASSERT_TRUE(sim.ok());
  EXPECT_TRUE(sim->advanceFrame().refactored);
  EXPECT_FALSE(sim->advanceFrame().refactored);
  const std::uint32_t grasped[] = {14, 15};
  ASSERT_TRUE(sim->setKinematic(grasped).ok());
  const FrameReport graspFrame = sim->advanceFrame();
  EXPECT_TRUE(graspFrame.refactored);
  EXPECT_GT(graspFrame.factorMs, 0.0);
  EXPECT_FALSE(sim->advanceFrame().refactored);
  ASSERT_TRUE(sim->setKinematic({}).ok());
  EXPECT_TRUE(sim->advanceFrame().refactored);
  EXPECT_FALSE(sim->advanceFrame().refactored);
}

TEST(FastMassSpring, ToleranceEndsTheIterationsEarlyAtSmallSteps) {
  // At h = 0.1 ms (h^2 k / m = 0.02) the inertial prediction is nearly the step: a tolerance of 1e-3 ends
  // the iterations well before 50, and the result is within that tolerance of the full run.
  const test::Patch patch = test::gridPatch(7, 6, 2.0f);
  const auto system = test::patchSystem(patch, 0.05, 0.0, 1.0, {0, 6}, {});
  State start = restState(patch.positions);
  start.v = test::pseudoRandomVelocities(start.v.size(), 30.0);
  start.v[0] = start.v[6] = {};
  State early = start, full = start;
  StepWorkspace ws1, ws2;
  const StepStats stats = step(Integrator::FastMassSpring, system, early, 1e-4, ws1,
                               {.localGlobalIterations = 50, .localGlobalTolerance = 1e-3});
  step(Integrator::FastMassSpring, system, full, 1e-4, ws2, {.localGlobalIterations = 50});
  EXPECT_LT(stats.localGlobalIterations, 50);
  double largest = 0.0, error = 0.0;
  for (std::size_t k = 0; k < full.x.size(); ++k) {
    largest = std::max(largest, length(full.x[k] - start.x[k]));
    error = std::max(error, length(early.x[k] - full.x[k]));
  }
  EXPECT_GT(largest, 0.0);
  EXPECT_LT(error, 1e-2 * largest);
}

}  // namespace
}  // namespace tissue::sim
