// Christensen-Burley normalized diffusion against shared/reference/burley.md.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "tissue/optics/burley.h"

namespace tissue::optics {
namespace {

// Integral of R(r) 2 pi r dr over [0, rMax]: the integrand is finite at 0, Simpson's rule.
double integrateProfile(double d, double rMax, int intervals = 400000) {
  const double h = rMax / intervals;
  auto f = [&](double r) {
    return r == 0.0 ? 2.0 / (8.0 * d) * 2.0 : burleyProfile(r, d, 1.0) * 2.0 * std::numbers::pi * r;
  };
  double sum = 0;
  for (int i = 0; i <= intervals; ++i)
    sum += ((i == 0 || i == intervals) ? 1.0 : (i % 2 ? 4.0 : 2.0)) * f(i * h);
  return sum * h / 3.0;
}

TEST(Burley, CheckValuesOfTheProfile) {
  const double r[] = {0.1, 0.5, 1, 2, 5};
  const double v[] = {0.744866, 0.115627, 0.0431473, 0.0129065, 0.00155664};
  for (int i = 0; i < 5; ++i)
    EXPECT_NEAR(burleyProfile(r[i], 1.0, 1.0), v[i], 1e-5 * v[i]);
  EXPECT_NEAR(burleyProfile(1.0, 1.0, 0.5), 0.5 * burleyProfile(1.0, 1.0, 1.0), 1e-16);  // linear in A
}

TEST(Burley, CheckValuesOfTheCdfAndItsMedian) {
  EXPECT_NEAR(burleyCdf(1, 1), 0.370632, 1e-6);
  EXPECT_NEAR(burleyCdf(3, 1), 0.711644, 1e-6);
  EXPECT_NEAR(burleyCdf(10, 1), 0.973233, 1e-6);
  EXPECT_NEAR(burleyCdf(16, 1), 0.9963790094, 1e-10);
  EXPECT_NEAR(burleyCdf(1.552183, 1), 0.5, 1e-6);
  EXPECT_NEAR(burleySampleRadius(0.5, 2.0), 2.0 * 1.552183, 1e-5);
  for (double u : {1e-6, 0.1, 0.37, 0.9, 0.999999})
    EXPECT_NEAR(burleyCdf(burleySampleRadius(u, 0.7), 0.7), u, 1e-12);
}

TEST(Burley, ProfileIntegratesToOneAndMatchesItsCdf) {
  const double d = 0.8;
  EXPECT_NEAR(integrateProfile(d, 80.0 * d), 1.0, 1e-6);
  for (double r : {0.5, 2.0, 6.0})
    EXPECT_NEAR(integrateProfile(d, r, 200000), burleyCdf(r, d), 1e-7);
}

TEST(Burley, ScalingFactors) {
  EXPECT_NEAR(burleyScaling(0.8, BurleyFit::SearchlightMfp), 1.05, 1e-12);
  EXPECT_NEAR(burleyScaling(0.3, BurleyFit::SearchlightMfp), 1.85 - 0.3 + 7 * 0.125, 1e-12);
  EXPECT_NEAR(burleyScaling(0.8, BurleyFit::DiffuseMfp), 1.1, 1e-12);
  EXPECT_NEAR(burleyScaling(0.33, BurleyFit::SearchlightDiffuseMfp), 3.5, 1e-12);
  EXPECT_NEAR(burleyScaling(1.0, BurleyFit::SearchlightDiffuseMfp), 3.5 + 100 * std::pow(0.67, 4), 1e-12);
}

}  // namespace
}  // namespace tissue::optics
