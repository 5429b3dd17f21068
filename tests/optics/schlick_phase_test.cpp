// Schlick phase function against shared/reference/phase_functions.md.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "tissue/optics/schlick_phase.h"

namespace tissue::optics {
namespace {

// 2 pi times the integral of f(mu) p(mu) over mu in [-1, 1], midpoint rule.
template <class F>
double sphereIntegral(double k, F f) {
  const int n = 400000;
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    const double mu = -1.0 + (i + 0.5) * 2.0 / n;
    sum += f(mu) * schlickPhase(mu, k);
  }
  return sum * 2.0 / n * 2.0 * std::numbers::pi;
}

TEST(SchlickPhase, NormalisedOverTheSphere) {
  for (double g : {-0.5, 0.0, 0.25, 0.4, 0.8, 0.9}) {
    const double k = schlickKFromG(g);
    EXPECT_NEAR(sphereIntegral(k, [](double) { return 1.0; }), 1.0, 2e-4) << "g " << g;
  }
}

TEST(SchlickPhase, MeanCosineMatchesReferenceValues) {
  const double g[] = {0.3, 0.75, 0.9};
  const double mean[] = {0.313455, 0.817073, 0.971078};
  for (int i = 0; i < 3; ++i) {
    const double k = schlickKFromG(g[i]);
    EXPECT_NEAR(schlickMeanCosine(k), mean[i], 2e-6) << "g " << g[i];
    EXPECT_NEAR(sphereIntegral(k, [](double mu) { return mu; }), mean[i], 2e-3) << "g " << g[i];
  }
}

TEST(SchlickPhase, PositiveKScattersForwardAlongTheDirectionOfTravel) {
  const double k = schlickKFromG(0.8);
  EXPECT_GT(schlickPhase(1.0, k), 100.0 * schlickPhase(-1.0, k));
  EXPECT_GT(schlickPhase(-1.0, -k), 100.0 * schlickPhase(1.0, -k));
  EXPECT_NEAR(schlickPhase(0.3, 0.0), 1.0 / (4.0 * std::numbers::pi), 1e-12);
}

TEST(SchlickPhase, KIsClampedBelowOneWhereTheDensityStopsBeingNormalisable) {
  EXPECT_LE(schlickKFromG(0.95), kSchlickMaxK);
  EXPECT_GE(schlickKFromG(-0.95), -kSchlickMaxK);
  EXPECT_LT(kSchlickMaxK, 1.0);
}

}  // namespace
}  // namespace tissue::optics
