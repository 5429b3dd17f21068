// The sim-bench pieces: the Gershgorin bound on omega_max (exact for two equal masses on one
// spring, omega^2 = 2k/m; an upper bound otherwise), the patch's size, and the timings' bookkeeping.
#include "tissue/studies/sim_bench.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "tissue/sim/spring_network.h"

namespace tissue::studies {
namespace {

sim::MassSpringSystem twoMasses(double m1, double m2, double kNPerMm) {
  sim::SpringNetwork net;
  sim::addSpring(net, 0, 1, 10.0, kNPerMm, 0.0);
  EXPECT_TRUE(sim::finalizeSpringNetwork(net, 2));
  auto system = sim::makeSystem(std::move(net), {m1, m2}, {}, {});
  EXPECT_TRUE(system);
  return std::move(*system);
}

TEST(SimBench, OmegaBoundIsExactForEqualMassesAndAboveOtherwise) {
  const auto equal = twoMasses(2.0, 2.0, 0.1);
  const double k = equal.springs.stiffness[0];  // g/s^2
  EXPECT_NEAR(omegaBound(equal), std::sqrt(2.0 * k / 2.0), 1e-9 * std::sqrt(k));
  // Unequal masses: the true omega is sqrt(k (1/m1 + 1/m2)).
  const auto unequal = twoMasses(1.0, 9.0, 0.1);
  const double truth = std::sqrt(k * (1.0 / 1.0 + 1.0 / 9.0));
  EXPECT_GE(omegaBound(unequal), truth);
  EXPECT_LT(omegaBound(unequal), 1.5 * truth);
}

TEST(SimBench, PatchHasAboutTheSpringsAskedFor) {
  for (const std::size_t target : {std::size_t{1000}, std::size_t{10000}}) {
    auto patch = makeBenchPatch(target, 1);
    ASSERT_TRUE(patch) << patch.error().message;
    EXPECT_NEAR(double(patch->system.springs.size()), double(target), 0.25 * double(target));
    EXPECT_EQ(patch->rest.x.size(), patch->system.vertexCount());
    // The x = 0 column is pinned: side vertices with zero inverse mass.
    const auto side = std::size_t(std::lround(std::sqrt(double(patch->system.vertexCount()))));
    std::size_t pinned = 0;
    for (double w : patch->system.invMasses)
      pinned += w == 0.0 ? 1 : 0;
    EXPECT_EQ(pinned, side);
  }
}

TEST(SimBench, TimingsCoverTheFrame) {
  auto patch = makeBenchPatch(1000, 1);
  ASSERT_TRUE(patch);
  IntegratorBenchConfig config;
  config.budgetMs = 5.0;
  config.maxTimedSteps = 10;
  const double h = 0.9 * 2.0 / omegaBound(patch->system);
  const IntegratorTiming t = timeIntegrator(sim::Integrator::SymplecticEuler, *patch, h, config);
  EXPECT_GE(t.stepsTimed, 1);
  EXPECT_LE(t.stepsTimed, 10);
  EXPECT_LE(t.msPerStepBest, t.msPerStep);
  // Enough substeps to cover 1/60 s, and not one more.
  EXPECT_GE(t.substepsPerFrame * h, config.frameTimeS - 1e-12);
  EXPECT_LT((t.substepsPerFrame - 1) * h, config.frameTimeS);
  const ForcePassTiming f = timeForcePass(*patch, 1);
  EXPECT_EQ(f.springs, patch->system.springs.size());
  EXPECT_LE(f.msBest, f.ms);
}

TEST(SimBench, EveryIntegratorOnEachPatchAndTheFastSolverSkippedAboveItsLimit) {
  SimBenchConfig config;
  config.maxSprings = 1000;
  config.threads = 2;
  config.fastSolverMaxSprings = 500;  // below the 1000-spring patch
  auto bench = runSimBench(config);
  ASSERT_TRUE(bench) << bench.error().message;
  ASSERT_EQ(bench->results.size(), 5u);
  for (const auto& t : bench->results) {
    const bool fast = t.integrator == sim::Integrator::FastMassSpring;
    EXPECT_EQ(t.skipped.empty(), !fast);
    if (!fast) {
      EXPECT_GT(t.msPerStep, 0.0);
    }
  }
  ASSERT_EQ(bench->forcePass.size(), 2u);  // 1 thread and 2
  EXPECT_FALSE(bench->framePath || bench->scenario);
  const std::string json = simBenchJson(*bench);
  for (const char* key : {"\"results\"", "\"force_pass\"", "\"skipped\"", "\"integrator\": \"verlet\""})
    EXPECT_NE(json.find(key), std::string::npos) << key;
  EXPECT_NE(simBenchText(*bench).find("skipped: factor too large"), std::string::npos);
}

}  // namespace
}  // namespace tissue::studies
