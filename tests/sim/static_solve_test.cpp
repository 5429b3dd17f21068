// Static equilibrium against the analytic hanging chain.
#include "tissue/sim/static_solve.h"

#include <gtest/gtest.h>

#include "tissue/sim/units.h"

namespace tissue::sim {
namespace {

TEST(StaticSolve, HangingChainMatchesTheAnalyticExtensions) {
  // n masses m on n springs k (rest 10 mm) hanging from a pinned top vertex; spring s (from the
  // top) carries the weight of the masses below it: extension = (n - s) m g / k.
  const int n = 12;
  const double m = 0.5, kNPerMm = 0.02, rest = 10.0;
  SpringNetwork springs;
  for (int s = 0; s < n; ++s)
    addSpring(springs, s, s + 1, rest, kNPerMm, 0.0);
  ASSERT_TRUE(finalizeSpringNetwork(springs, n + 1).ok());
  const std::uint32_t pinned[] = {0};
  auto system = makeSystem(std::move(springs), std::vector<double>(n + 1, m), pinned,
                           {.gravity = {0.0, -kStandardGravity, 0.0}});
  ASSERT_TRUE(system.ok());
  // Start slanted and unstretched, so the solve has to swing and stretch the chain.
  std::vector<Vec3d> x(n + 1);
  for (int v = 0; v <= n; ++v)
    x[v] = {0.6 * rest * v, -0.8 * rest * v, 0.0};
  const auto report = solveStatic(*system, x, {.toleranceN = 1e-9});
  ASSERT_TRUE(report.converged) << report.residualN << " N after " << report.iterations;
  double y = 0.0;
  const double k = stiffnessFromNewtonPerMm(kNPerMm);
  for (int v = 1; v <= n; ++v) {
    y -= rest + (n - v + 1) * m * kStandardGravity / k;
    EXPECT_NEAR(x[v].y, y, 1e-6) << "vertex " << v;
    EXPECT_NEAR(x[v].x, 0.0, 1e-6) << "vertex " << v;
  }
  EXPECT_LE(maxFreeForceN(*system, x), 1e-9);
}

}  // namespace
}  // namespace tissue::sim
