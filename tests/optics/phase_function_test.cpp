// Henyey-Greenstein against shared/reference/phase_functions.md.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "tissue/optics/phase_function.h"

namespace tissue::optics {
namespace {

TEST(HenyeyGreenstein, CheckValues) {
  const double g[] = {0.3, 0.75, 0.9, -0.5};
  const double forward[] = {0.211124, 2.22817, 15.1197, 0.0176839};
  const double backward[] = {0.0329611, 0.00649612, 0.00220436, 0.477465};
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(henyeyGreenstein(1.0, g[i]), forward[i], 1e-5 * forward[i]);
    EXPECT_NEAR(henyeyGreenstein(-1.0, g[i]), backward[i], 1e-5 * backward[i]);
  }
}

TEST(HenyeyGreenstein, NormalisedWithMeanCosineG) {
  for (double g : {-0.5, 0.0, 0.3, 0.9}) {
    // 2 pi times the integral over cos t in [-1, 1], midpoint rule.
    const int n = 200000;
    double norm = 0, mean = 0;
    for (int i = 0; i < n; ++i) {
      const double mu = -1.0 + (i + 0.5) * 2.0 / n;
      norm += henyeyGreenstein(mu, g) * 2.0 / n * 2.0 * std::numbers::pi;
      mean += mu * henyeyGreenstein(mu, g) * 2.0 / n * 2.0 * std::numbers::pi;
    }
    EXPECT_NEAR(norm, 1.0, 1e-6) << g;
    EXPECT_NEAR(mean, g, 1e-6) << g;
  }
}

TEST(HenyeyGreenstein, SamplingHasMeanCosineGAndScattersForwardForPositiveG) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (double g : {-0.5, 0.0, 0.3, 0.75, 0.9}) {
    const int n = 1000000;
    double sum = 0, sum2 = 0;
    for (int i = 0; i < n; ++i) {
      const double mu = sampleHenyeyGreenstein(g, uniform(rng));
      ASSERT_GE(mu, -1.0);
      ASSERT_LE(mu, 1.0);
      sum += mu;
      sum2 += mu * mu;
    }
    const double mean = sum / n;
    const double stderrMean = std::sqrt((sum2 / n - mean * mean) / n);
    EXPECT_NEAR(mean, g, 4.0 * stderrMean) << g;
  }
  // xi = 1 gives cos t = 1 (straight on) for g > 0; xi = 0 gives cos t = -1.
  EXPECT_NEAR(sampleHenyeyGreenstein(0.8, 1.0), 1.0, 1e-12);
  EXPECT_NEAR(sampleHenyeyGreenstein(0.8, 0.0), -1.0, 1e-12);
}

}  // namespace
}  // namespace tissue::optics
