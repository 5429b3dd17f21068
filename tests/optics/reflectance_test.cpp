// The split reflectance of a semi-infinite medium (optics/reflectance.h): its single-scattering
// integral against closed forms, energy (single + multiple below 1 for white light, the part that
// enters), and the sum against the 1D Monte Carlo (MCML's model) for the data liver's bands.
#include "tissue/optics/reflectance.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "tissue/optics/dipole.h"
#include "tissue/optics/monte_carlo.h"
#include "tissue/optics/phase_function.h"

namespace tissue::optics {
namespace {

TEST(Reflectance, SingleScatteringOfAnIsotropicIndexMatchedHalfSpaceHasItsClosedForm) {
  // g = 0, eta = 1: R = alpha / (4 pi) 2 pi int_0^1 mu / (1 + mu) dmu = (alpha / 2) (1 - ln 2).
  const double alpha = 0.8;
  EXPECT_NEAR(singleScatteringReflectance(0.2, 0.8, 0.0, 1.0), 0.5 * alpha * (1.0 - std::log(2.0)), 1e-6);
  // At normal view: alpha p(-1) / 2 = alpha / (8 pi) (Schlick k(0) = 0 is isotropic).
  EXPECT_NEAR(singleScatteringNormalRadiance(0.2, 0.8, 0.0, 1.0), alpha / (8.0 * std::numbers::pi), 1e-12);
}

TEST(Reflectance, ForwardScatteringAndFresnelLowerTheSingleScatteredPart) {
  EXPECT_LT(singleScatteringReflectance(0.1, 9.0, 0.9, 1.0), singleScatteringReflectance(0.1, 9.0, 0.0, 1.0));
  EXPECT_LT(singleScatteringReflectance(0.1, 9.0, 0.9, 1.4), singleScatteringReflectance(0.1, 9.0, 0.9, 1.0));
  EXPECT_DOUBLE_EQ(entryFresnel(1.0, 0.3), 0.0);
  EXPECT_NEAR(entryFresnel(1.5, 1.0), 0.04, 1e-9);  // ((1.5 - 1) / (1.5 + 1))^2
}

TEST(Reflectance, SingleAndMultipleStayBelowTheEnteringLightForWhiteLight) {
  // Without absorption all that entered comes back (the sum reaches 1 - F(0)); never more.
  for (double eta : {1.0, 1.33, 1.38, 1.5}) {
    for (double g : {0.0, 0.5, 0.9, 0.97}) {
      for (double albedo : {0.5, 0.9, 0.99, 0.999, 1.0}) {
        const Reflectance r = semiInfiniteReflectance(10.0 * (1.0 - albedo), 10.0 * albedo, g, eta);
        EXPECT_GT(r.single, 0.0);
        EXPECT_GT(r.multiple, 0.0);
        EXPECT_LE(r.total(), 1.0 - entryFresnel(eta, 1.0) + 1e-12)
            << "eta " << eta << " g " << g << " albedo " << albedo;
      }
    }
  }
}

// The data liver's parenchyma (data/materials/liver.json, from Jacques 2013 and the blood
// model of shared/reference/liver_properties.md) per band: the sum against the 1D Monte Carlo.
struct Band {
  double sigmaA, sigmaS, g, tolerance;
};

TEST(Reflectance, TheSumAgainstMonteCarloForTheLiverBands) {
  // The dipole is a diffusion model: at the red band's reduced albedo 0.87 it is 21 % above the
  // Monte Carlo; at green's and blue's 0.17-0.21 with g = 0.9 it is 3-4x above (diffusion spreads
  // light that, scattering forwards, goes deep and is absorbed). The bounds pin that known gap
  // (docs/RESULTS.md, "Consistent materials"): the model is never darker than the transport,
  // and no more than `tolerance` times brighter.
  const Band bands[] = {{0.1129, 7.7285, 0.9, 1.3}, {4.2687, 8.4860, 0.9, 4.0}, {3.4961, 9.4751, 0.9, 4.0}};
  const double eta = 1.38;
  for (const Band& b : bands) {
    LayeredMedium medium;
    medium.layers = {Layer{eta, b.sigmaA, b.sigmaS, b.g, kInfiniteThickness}};
    MonteCarloSettings settings;
    settings.photons = 100000;
    settings.seed = 7;
    auto mc = simulateMonteCarlo(medium, settings);
    ASSERT_TRUE(mc.ok()) << mc.error().message;
    const Reflectance r = semiInfiniteReflectance(b.sigmaA, b.sigmaS, b.g, eta);
    std::printf("mu_a %.4f mu_s %.4f: single %.5f multiple %.5f total %.5f, Monte Carlo %.5f +- %.5f\n",
                b.sigmaA, b.sigmaS, r.single, r.multiple, r.total(), mc->rd, mc->rdStderr);
    EXPECT_GT(r.total(), mc->rd - 3.0 * mc->rdStderr);
    EXPECT_LT(r.total(), b.tolerance * (mc->rd + 3.0 * mc->rdStderr));
  }
}

}  // namespace
}  // namespace tissue::optics
