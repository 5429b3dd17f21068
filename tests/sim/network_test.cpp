// Spring networks: surface building, masses, momentum of a free network, the hanging chain's
// static equilibrium, implicit Euler far above the explicit limit, bit-identical repeats.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "test_systems.h"
#include "tissue/sim/forces.h"
#include "tissue/sim/integrators.h"
#include "tissue/sim/mass.h"
#include "tissue/sim/simulator.h"
#include "tissue/sim/spring_network.h"
#include "tissue/sim/units.h"

namespace tissue::sim {
namespace {

TEST(SurfaceSprings, EdgeAndBendingSpringsOfAQuad) {
  const test::Patch quad = test::gridPatch(2, 2, 2.0f);
  SpringBuildReport report;
  auto springs = buildSurfaceSprings(quad.positions, quad.triangles,
                                     {.stiffness = 0.3, .bendingStiffness = 0.1, .damping = 0.0}, &report);
  ASSERT_TRUE(springs.ok()) << springs.error().message;
  EXPECT_EQ(report.edgeSprings, 5u);     // four sides and the diagonal
  EXPECT_EQ(report.bendingSprings, 1u);  // across the diagonal, between the other two corners
  EXPECT_EQ(report.boundaryEdges, 4u);
  EXPECT_EQ(springs->size(), 6u);
  EXPECT_DOUBLE_EQ(springs->stiffness[0], stiffnessFromNewtonPerMm(0.3));
}

TEST(SurfaceSprings, PerRestLengthLawDividesByRestLength) {
  const test::Patch quad = test::gridPatch(2, 2, 2.0f);
  auto springs = buildSurfaceSprings(quad.positions, quad.triangles,
                                     {.stiffness = 0.3, .law = StiffnessLaw::PerRestLength});
  ASSERT_TRUE(springs.ok());
  for (std::size_t e = 0; e < springs->size(); ++e)
    EXPECT_DOUBLE_EQ(springs->stiffness[e], stiffnessFromNewtonPerMm(0.3 / springs->restLength[e]));
}

TEST(SurfaceSprings, BadInputIsAnError) {
  const test::Patch quad = test::gridPatch(2, 2, 2.0f);
  const std::vector<Triangle> bad{{0, 1, 7}};
  EXPECT_FALSE(buildSurfaceSprings(quad.positions, bad, {}).ok());
  const std::vector<Float3> coincident{{0, 0, 0}, {0, 0, 0}, {1, 0, 0}};
  const std::vector<Triangle> tri{{0, 1, 2}};
  EXPECT_FALSE(buildSurfaceSprings(coincident, tri, {}).ok());
  EXPECT_FALSE(computeMasses(quad.positions, quad.triangles, {.total = 0.0, .arealDensity = 0.0}).ok());
}

TEST(Masses, LumpedAndUniformSumToTheTotal) {
  const test::Patch patch = test::gridPatch(4, 3, 1.5f);
  for (auto distribution : {MassDistribution::Lumped, MassDistribution::Uniform}) {
    auto m = computeMasses(patch.positions, patch.triangles, {.total = 7.0, .distribution = distribution});
    ASSERT_TRUE(m.ok());
    double sum = 0.0;
    for (double x : *m)
      sum += x;
    EXPECT_NEAR(sum, 7.0, 1e-12);
  }
  // Density: 0.01 g/mm^2 over a 4.5 x 3 mm patch.
  auto m = computeMasses(patch.positions, patch.triangles, {.total = 0.0, .arealDensity = 0.01});
  ASSERT_TRUE(m.ok());
  double sum = 0.0;
  for (double x : *m)
    sum += x;
  EXPECT_NEAR(sum, 0.01 * 4.5 * 3.0, 1e-9);
}

TEST(FreeNetwork, MomentumIsConservedToRounding) {
  // No gravity, no pins, no Rayleigh mass damping (it drags towards the rest frame); spring and
  // Rayleigh stiffness damping are internal forces and conserve momentum.
  const test::Patch patch = test::gridPatch(6, 5, 2.0f);
  const SystemConfig config{.gravity = {}, .rayleighMass = 0.0, .rayleighStiffness = 1e-4};
  const auto system = test::patchSystem(patch, 0.05, 1e-5, 3.0, {}, config);
  const double limit = 2.0 / test::largestOmega(system, restState(patch.positions).x);
  for (Integrator integrator :
       {Integrator::ExplicitEuler, Integrator::SymplecticEuler, Integrator::VelocityVerlet,
        Integrator::ImplicitEuler, Integrator::FastMassSpring}) {
    State s = restState(patch.positions);
    s.v = test::pseudoRandomVelocities(s.v.size(), 20.0);
    const Vec3d p0 = linearMomentum(system, s.v);
    double scale = 0.0;
    for (std::size_t k = 0; k < s.v.size(); ++k)
      scale += system.masses[k] * length(s.v[k]);
    StepWorkspace ws;
    for (int n = 0; n < 1000; ++n)
      step(integrator, system, s, 0.02 * limit, ws);
    const double drift = length(linearMomentum(system, s.v) - p0) / scale;
    // Implicit Euler conserves momentum up to its conjugate-gradient tolerance (1e-10); the fast
    // solver exactly (the rows of L sum to zero), up to the rounding of its sparse solves.
    const double tolerance = integrator == Integrator::ImplicitEuler    ? 1e-8
                             : integrator == Integrator::FastMassSpring ? 1e-10
                                                                        : 1e-12;
    EXPECT_LT(drift, tolerance) << integratorName(integrator);
  }
}

TEST(HangingChain, StaticEquilibriumMatchesTheAnalyticStretch) {
  // Vertex 0 pinned at the origin, N masses below it; link i carries the weight of every mass
  // from i down, so its length is L0 + g sum_{j >= i} m_j / k_i.
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

  std::vector<double> expectedY(kN + 1, 0.0);
  for (int i = 1; i <= kN; ++i) {
    double below = 0.0;
    for (int j = i; j <= kN; ++j)
      below += masses[j];
    const double k = stiffnessFromNewtonPerMm(0.05 + 0.01 * i);
    expectedY[i] = expectedY[i - 1] - (kL0 + kStandardGravity * below / k);
  }
  for (Integrator integrator : {Integrator::ImplicitEuler, Integrator::SymplecticEuler}) {
    State s;
    for (int i = 0; i <= kN; ++i)
      s.x.push_back({0.0, -kL0 * i, 0.0});
    s.v.assign(kN + 1, Vec3d{});
    StepWorkspace ws;
    const double h = integrator == Integrator::ImplicitEuler ? 0.01 : 0.5e-3;
    const int steps = integrator == Integrator::ImplicitEuler ? 3000 : 40000;
    for (int n = 0; n < steps; ++n)
      step(integrator, system, s, h, ws, {.relativeTolerance = 1e-13});
    for (int i = 0; i <= kN; ++i) {
      EXPECT_NEAR(s.x[i].y, expectedY[i], 1e-7) << integratorName(integrator) << " vertex " << i;
      EXPECT_NEAR(s.x[i].x, 0.0, 1e-12);
    }
  }
}

TEST(ImplicitEuler, StableAtHundredTimesTheExplicitLimit) {
  const test::Patch patch = test::gridPatch(8, 8, 2.0f);
  std::vector<std::uint32_t> pinned{0, 1, 2, 3, 4, 5, 6, 7};
  const auto system = test::patchSystem(patch, 0.1, 0.0, 2.0, pinned, {.gravity = {}});
  const double limit = 2.0 / test::largestOmega(system, restState(patch.positions).x);

  State start = restState(patch.positions);
  start.v = test::pseudoRandomVelocities(start.v.size(), 5.0);
  for (std::uint32_t p : pinned)
    start.v[p] = {};
  const double e0 = kineticEnergy(system, start.v);
  auto finalEnergy = [&](Integrator integrator, double h, int steps) {
    State s = start;
    StepWorkspace ws;
    for (int n = 0; n < steps; ++n)
      step(integrator, system, s, h, ws);
    return kineticEnergy(system, s.v) + elasticEnergy(system, s.x);
  };
  const double implicitEnergy = finalEnergy(Integrator::ImplicitEuler, 100.0 * limit, 200);
  EXPECT_TRUE(std::isfinite(implicitEnergy));
  EXPECT_LE(implicitEnergy, e0);
  // The limit is real: symplectic Euler is stable just below it and blows up just above it.
  EXPECT_LE(finalEnergy(Integrator::SymplecticEuler, 0.95 * limit, 3000), 100.0 * e0);
  EXPECT_FALSE(finalEnergy(Integrator::SymplecticEuler, 1.05 * limit, 3000) <= 1e6 * e0);  // or NaN
}

TEST(Determinism, RepeatedRunsAreBitIdentical) {
  const test::Patch patch = test::gridPatch(10, 10, 2.0f);
  std::vector<std::uint32_t> pinned{0, 9};
  const SystemConfig config{.rayleighMass = 0.5, .rayleighStiffness = 1e-4};
  auto run = [&](Integrator integrator) {
    SimulatorConfig simConfig{.integrator = integrator, .substeps = 8};
    // The recovery's wall-clock budget takes another path on a loaded machine: without it, the
    // run depends on its inputs alone, which is what this test is about.
    simConfig.recovery.frameBudgetMs = 0.0;
    auto sim = Simulator::create(test::patchSystem(patch, 0.05, 1e-5, 2.0, pinned, config),
                                 restState(patch.positions), simConfig);
    EXPECT_TRUE(sim.ok());
    for (int f = 0; f < 30; ++f)
      (void)sim->advanceFrame();
    return sim->state();
  };
  for (Integrator integrator : {Integrator::ImplicitEuler, Integrator::VelocityVerlet}) {
    const State a = run(integrator), b = run(integrator);
    ASSERT_EQ(a.x.size(), b.x.size());
    EXPECT_EQ(std::memcmp(a.x.data(), b.x.data(), a.x.size() * sizeof(Vec3d)), 0)
        << integratorName(integrator);
    EXPECT_EQ(std::memcmp(a.v.data(), b.v.data(), a.v.size() * sizeof(Vec3d)), 0)
        << integratorName(integrator);
    EXPECT_NE(a.x[55], restState(patch.positions).x[55]);  // it did move
  }
}

TEST(Determinism, TwoThreadsGiveTheSameBitsAsOne) {
  // Large enough for the spring and vector passes to split (100 x 100 vertices, ~59k springs).
  const test::Patch patch = test::gridPatch(100, 100, 1.0f);
  std::vector<std::uint32_t> pinned{0, 99};
  auto run = [&](Integrator integrator, int threads) {
    const SystemConfig config{.rayleighMass = 0.5, .rayleighStiffness = 1e-4, .threads = threads};
    const auto system = test::patchSystem(patch, 0.05, 1e-5, 20.0, pinned, config);
    // Implicit steps of a frame; explicit steps below the stability limit (about 1.4e-4 s).
    const bool implicit = integrator == Integrator::ImplicitEuler || integrator == Integrator::FastMassSpring;
    State s = restState(patch.positions);
    StepWorkspace ws;
    for (int n = 0; n < (implicit ? 2 : 10); ++n)
      step(integrator, system, s, implicit ? 1.0 / 60.0 : 5e-5, ws);
    return s;
  };
  for (Integrator integrator : {Integrator::ImplicitEuler, Integrator::FastMassSpring,
                                Integrator::SymplecticEuler, Integrator::VelocityVerlet}) {
    const State one = run(integrator, 1), two = run(integrator, 2);
    EXPECT_EQ(std::memcmp(one.x.data(), two.x.data(), one.x.size() * sizeof(Vec3d)), 0)
        << integratorName(integrator);
    EXPECT_EQ(std::memcmp(one.v.data(), two.v.data(), one.v.size() * sizeof(Vec3d)), 0)
        << integratorName(integrator);
    EXPECT_NE(one.x[5050], restState(patch.positions).x[5050]) << integratorName(integrator);  // it moved
  }
}

}  // namespace
}  // namespace tissue::sim
