// Monte Carlo transport against the published cases of shared/reference/monte_carlo_validation.md
// (coefficients there in cm^-1 and cm; here in mm^-1 and mm), and its determinism.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "tissue/optics/fresnel.h"
#include "tissue/optics/monte_carlo.h"

namespace tissue::optics {
namespace {

constexpr std::int64_t kPhotons = 1000000;  // standard error near 2.5e-4 on Rd
// A published Monte Carlo figure has its own error: MCML with 1e6 photons ~2.3e-4 (the file's note).
constexpr double kMcmlReferenceStderr = 2.3e-4;

MonteCarloResult run(const LayeredMedium& medium, std::int64_t photons = kPhotons, std::uint64_t seed = 7) {
  MonteCarloSettings s;
  s.photons = photons;
  s.seed = seed;
  s.grid = {.drMm = 0.01, .bins = 200};
  auto result = simulateMonteCarlo(medium, s);
  EXPECT_TRUE(result.ok()) << (result.ok() ? "" : result.error().message);
  return result.ok() ? *result : MonteCarloResult{};
}

// |value - reference| within 3 combined standard errors (ours and the reference's).
void expectWithin3Sigma(const char* what, double value, double stderrOurs, double reference,
                        double stderrRef) {
  const double sigma = std::sqrt(stderrOurs * stderrOurs + stderrRef * stderrRef);
  std::printf("  %-8s %.5f +- %.5f   reference %.5f   (%.1f sigma)\n", what, value, stderrOurs, reference,
              (value - reference) / sigma);
  EXPECT_NEAR(value, reference, 3.0 * sigma) << what;
}

LayeredMedium slab(double n, double mua, double mus, double g, double thickness) {
  return {.ambientAbove = 1.0, .ambientBelow = 1.0, .layers = {{n, mua, mus, g, thickness}}};
}

TEST(MonteCarlo, CaseAMatchedSlabMatchesVanDeHulst) {
  const auto r = run(slab(1.0, 1.0, 9.0, 0.75, 0.2));
  std::printf("Case A (%lld photons, %.2f s):\n", static_cast<long long>(r.photons), r.seconds);
  expectWithin3Sigma("Rd", r.rd, r.rdStderr, 0.09739, 0.0);  // van de Hulst 1980, exact
  expectWithin3Sigma("Tt", r.tt, r.ttStderr, 0.66096, 0.0);
  EXPECT_EQ(r.specular, 0.0);
  EXPECT_EQ(r.cappedPhotons, 0);  // every photon ends as MCML's do: the hop cap changes nothing
  // Conservation: every launched weight is reflected, transmitted or absorbed.
  EXPECT_NEAR(r.rd + r.tt + r.absorbed[0], 1.0, 1e-5);  // roulette conserves weight on average
}

TEST(MonteCarlo, CaseBHalfSpaceMatchesGiovanelli) {
  const auto r = run(slab(1.5, 1.0, 9.0, 0.0, kInfiniteThickness));
  std::printf("Case B (%lld photons, %.2f s):\n", static_cast<long long>(r.photons), r.seconds);
  EXPECT_NEAR(r.specular, 0.04, 1e-12);
  // Giovanelli 1955: total 0.2600 with the 0.04 specular, quoted to 4 digits (+-5e-5 rounding).
  expectWithin3Sigma("Rd", r.rd, r.rdStderr, 0.2200, 5e-5);
  EXPECT_EQ(r.tt, 0.0);
  EXPECT_EQ(r.cappedPhotons, 0);  // every photon ends as MCML's do: the hop cap changes nothing
}

TEST(MonteCarlo, CaseCMismatchedSlabMatchesMcml) {
  const auto r = run(slab(1.5, 1.0, 9.0, 0.0, 0.2));
  std::printf("Case C (%lld photons, %.2f s):\n", static_cast<long long>(r.photons), r.seconds);
  expectWithin3Sigma("Rd", r.rd, r.rdStderr, 0.213348, kMcmlReferenceStderr);  // MCML 1e6 photons
  expectWithin3Sigma("Tt", r.tt, r.ttStderr, 0.288811, kMcmlReferenceStderr);
  std::printf("  adding-doubling: Rd 0.21309, Tt 0.28881\n");
}

TEST(MonteCarlo, CaseDThreeLayersMatchesMcml) {
  LayeredMedium m{
      .ambientAbove = 1.0,
      .ambientBelow = 1.0,
      .layers = {{1.37, 0.1, 10.0, 0.9, 1.0}, {1.37, 0.1, 1.0, 0.0, 1.0}, {1.37, 0.2, 1.0, 0.7, 2.0}}};
  const auto r = run(m);
  std::printf("Case D (%lld photons, %.2f s):\n", static_cast<long long>(r.photons), r.seconds);
  EXPECT_NEAR(r.specular, 0.0243729, 1e-7);
  expectWithin3Sigma("Rd", r.rd, r.rdStderr, 0.237544, kMcmlReferenceStderr);  // MCML 1e6 photons
  expectWithin3Sigma("Tt", r.tt, r.ttStderr, 0.0964896, kMcmlReferenceStderr);
  std::printf("  absorbed per layer %.4f / %.4f / %.4f (MCML 0.2612 / 0.1488 / 0.2316)\n", r.absorbed[0],
              r.absorbed[1], r.absorbed[2]);
  const double absorbedRef[3] = {0.2612, 0.1488, 0.2316};
  for (int l = 0; l < 3; ++l)
    EXPECT_NEAR(r.absorbed[static_cast<std::size_t>(l)], absorbedRef[l], 0.002);
  EXPECT_NEAR(r.specular + r.rd + r.tt + r.absorbed[0] + r.absorbed[1] + r.absorbed[2], 1.0, 1e-5);
  EXPECT_EQ(r.cappedPhotons, 0);
}

TEST(MonteCarlo, RadialProfileIntegratesToTheTotal) {
  // Case A on a grid wide enough (4 mm) to catch nearly all light: sum of R_d(r) * ring area = Rd.
  MonteCarloSettings s;
  s.photons = 100000;
  s.grid = {.drMm = 0.02, .bins = 200};
  auto r = simulateMonteCarlo(slab(1.0, 1.0, 9.0, 0.75, 0.2), s);
  ASSERT_TRUE(r.ok());
  double rd = 0, tt = 0;
  for (int i = 0; i < s.grid.bins; ++i) {
    rd += r->rdRadial[static_cast<std::size_t>(i)] * s.grid.area(i);
    tt += r->ttRadial[static_cast<std::size_t>(i)] * s.grid.area(i);
  }
  EXPECT_NEAR(rd, r->rd, 1e-3 * r->rd);
  // The unscattered beam leaves in ring 0; its weight exp(-2) sits inside the radial T too.
  EXPECT_NEAR(tt, r->tt, 1e-3 * r->tt);
  EXPECT_GT(r->ttRadial[0] * s.grid.area(0), std::exp(-2.0));
  EXPECT_NEAR(s.grid.radius(0), 2.0 / 3.0 * 0.02, 1e-15);
}

TEST(MonteCarlo, SameSeedGivesIdenticalResultsForAnyThreadCount) {
  const auto medium = slab(1.4, 0.5, 5.0, 0.8, 1.0);
  MonteCarloSettings s;
  s.photons = 20000;
  s.seed = 42;
  s.threads = 2;
  auto a = simulateMonteCarlo(medium, s);
  auto b = simulateMonteCarlo(medium, s);
  s.threads = 1;
  auto c = simulateMonteCarlo(medium, s);
  s.seed = 43;
  auto d = simulateMonteCarlo(medium, s);
  ASSERT_TRUE(a.ok() && b.ok() && c.ok() && d.ok());
  EXPECT_EQ(a->rd, b->rd);
  EXPECT_EQ(a->tt, b->tt);
  EXPECT_EQ(a->rdRadial, b->rdRadial);
  EXPECT_EQ(a->rd, c->rd);
  EXPECT_EQ(a->ttRadial, c->ttRadial);
  EXPECT_EQ(a->absorbed, c->absorbed);
  EXPECT_NE(a->rd, d->rd);
}

TEST(MonteCarlo, NonAbsorbingHalfSpaceEndsWithCappedPhotonsCounted) {
  // mua = 0: a photon ends only by escaping, and the escape time of a random walk has an infinite
  // mean; issue 14 saw this run without end. The hop cap drops the rare long walks and counts them.
  MonteCarloSettings s;
  s.photons = 2000;
  s.maxInteractions = 10000;
  s.grid = {.drMm = 0.1, .bins = 50};
  auto r = simulateMonteCarlo(slab(1.4, 0.0, 10.0, 0.9, kInfiniteThickness), s);
  ASSERT_TRUE(r.ok()) << r.error().message;
  std::printf("  mua = 0: %lld of %lld photons capped at %lld hops, weight %.4f, Rd %.4f\n",
              static_cast<long long>(r->cappedPhotons), static_cast<long long>(r->photons),
              static_cast<long long>(s.maxInteractions), r->cappedWeight, r->rd);
  // P(N > n) ~ n^-1/2 for the escape time: some photons of 2000 walk beyond 1e4 hops.
  EXPECT_GT(r->cappedPhotons, 0);
  EXPECT_LT(r->cappedPhotons, r->photons / 10);
  EXPECT_EQ(r->absorbed[0], 0.0);
  // Nothing is absorbed and nothing roulettes: what is not reflected is exactly the capped weight.
  EXPECT_NEAR(r->specular + r->rd + r->cappedWeight, 1.0, 1e-9);
  s.maxInteractions = 0;
  EXPECT_FALSE(simulateMonteCarlo(slab(1.4, 0.0, 10.0, 0.9, kInfiniteThickness), s).ok());
}

TEST(MonteCarlo, RejectsBadSettingsAndMedia) {
  MonteCarloSettings s;
  s.batches = 1;
  EXPECT_FALSE(simulateMonteCarlo(slab(1.4, 0.1, 1.0, 0.0, 1.0), s).ok());
  EXPECT_FALSE(simulateMonteCarlo(slab(1.4, 0.1, 1.0, 1.0, 1.0), {}).ok());  // g = 1
  EXPECT_FALSE(simulateMonteCarlo(LayeredMedium{}, {}).ok());                // no layers
}

TEST(Fresnel, NormalIncidenceTotalInternalReflectionAndMatchedIndices) {
  EXPECT_NEAR(fresnelReflectance(1.0, 1.5, 1.0).reflectance, 0.04, 1e-12);
  EXPECT_NEAR(fresnelReflectance(1.5, 1.0, 1.0).reflectance, 0.04, 1e-12);
  // Critical angle from 1.5 to 1.0: sin = 2/3, cos = 0.745; just below it, total reflection.
  EXPECT_EQ(fresnelReflectance(1.5, 1.0, 0.74).reflectance, 1.0);
  EXPECT_LT(fresnelReflectance(1.5, 1.0, 0.76).reflectance, 1.0);
  EXPECT_EQ(fresnelReflectance(1.3, 1.3, 0.3).reflectance, 0.0);
  // Snell: n1 sin i = n2 sin t.
  const auto f = fresnelReflectance(1.0, 1.5, 0.6);
  EXPECT_NEAR(1.0 * 0.8, 1.5 * std::sqrt(1.0 - f.cosTransmitted * f.cosTransmitted), 1e-12);
  // Brewster-free sanity: reflectance grows towards grazing incidence.
  EXPECT_GT(fresnelReflectance(1.0, 1.5, 0.1).reflectance, fresnelReflectance(1.0, 1.5, 0.9).reflectance);
}

}  // namespace
}  // namespace tissue::optics
