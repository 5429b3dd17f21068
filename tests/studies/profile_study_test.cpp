// The profile choice: the Monte Carlo arm against the published slab case (van de Hulst 1980 /
// MCML manual Table 6.1; shared/reference/monte_carlo_validation.md, case A), and the analytic
// arms against their own totals and each other.
#include "tissue/studies/profile_study.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace tissue::studies {
namespace {

optics::LayeredMedium halfSpace(double n, double mua, double mus, double g) {
  optics::LayeredMedium m;
  m.layers.push_back({n, mua, mus, g, optics::kInfiniteThickness});
  return m;
}

// Integral of R_d(r) over the rings: sum R_d(r_i) * area_i.
double ringIntegral(const ChannelProfile& p, const optics::RadialGrid& grid) {
  double sum = 0.0;
  for (int i = 0; i < grid.bins; ++i)
    sum += p.rdRadial[std::size_t(i)] * grid.area(i);
  return sum;
}

TEST(ProfileStudy, ParsesTheFourMethods) {
  EXPECT_EQ(parseProfileMethod("mc"), ProfileMethod::MonteCarlo);
  EXPECT_EQ(parseProfileMethod("dipole"), ProfileMethod::Dipole);
  EXPECT_EQ(parseProfileMethod("multipole"), ProfileMethod::Multipole);
  EXPECT_EQ(parseProfileMethod("burley"), ProfileMethod::Burley);
  EXPECT_FALSE(parseProfileMethod("Dipole").has_value());
}

TEST(ProfileStudy, MonteCarloMatchesVanDeHulstSlab) {
  // Case A: n = 1 both sides, mu_a = 1 /mm, mu_s = 9 /mm, g = 0.75, 0.2 mm: Rd 0.09739, Tt 0.66096.
  optics::LayeredMedium slab;
  slab.layers.push_back({1.0, 1.0, 9.0, 0.75, 0.2});
  ProfileConfig config;
  config.method = ProfileMethod::MonteCarlo;
  config.photons = 200000;
  config.threads = 2;
  auto p = profileChannel(slab, {0.01, 50}, config);
  ASSERT_TRUE(p) << p.error().message;
  // 2e5 photons: standard error ~5e-4; 4 sigma bands.
  EXPECT_NEAR(p->rd, 0.09739, 4.0 * p->rdStderr + 2e-4);
  EXPECT_NEAR(p->tt, 0.66096, 4.0 * p->ttStderr + 2e-4);
  EXPECT_DOUBLE_EQ(p->specular, 0.0);  // matched index
  EXPECT_EQ(p->photons, 200000);
}

TEST(ProfileStudy, DipoleProfileIntegratesToItsTotal) {
  // Skin-like half space (Jensen 2001 units, mm^-1); the default grid spans 6 diffusion lengths,
  // where the profile has fallen by e^-6, so the rings hold nearly all of the total R_d.
  const auto m = halfSpace(1.3, 0.032, 7.4, 0.0);
  const double rMax = defaultProfileRadiusMm(m);
  const optics::RadialGrid grid{rMax / 400, 400};
  ProfileConfig config;
  auto p = profileChannel(m, grid, config);
  ASSERT_TRUE(p);
  ASSERT_EQ(p->rdRadial.size(), 400u);
  for (std::size_t i = 1; i < p->rdRadial.size(); ++i)
    EXPECT_LE(p->rdRadial[i], p->rdRadial[i - 1]) << i;  // monotone in r
  EXPECT_NEAR(ringIntegral(*p, grid), p->rd, 0.03 * p->rd);
  EXPECT_NEAR(p->specular, std::pow(0.3 / 2.3, 2), 1e-12);
}

TEST(ProfileStudy, ThickMultipoleIsTheDipoleAndBurleyKeepsItsAlbedo) {
  const auto half = halfSpace(1.3, 0.032, 7.4, 0.0);
  optics::LayeredMedium thick = half;
  thick.layers[0].thickness = 1000.0;  // ~ 300 diffusion lengths
  const optics::RadialGrid grid{defaultProfileRadiusMm(half) / 100, 100};
  ProfileConfig dipole, multipole, burley;
  multipole.method = ProfileMethod::Multipole;
  burley.method = ProfileMethod::Burley;
  auto d = profileChannel(half, grid, dipole);
  auto m = profileChannel(thick, grid, multipole);
  auto b = profileChannel(half, grid, burley);
  ASSERT_TRUE(d && m && b);
  EXPECT_NEAR(m->rd, d->rd, 1e-3 * d->rd);
  EXPECT_LT(m->tt, 1e-6);  // nothing crosses 1000 mm
  EXPECT_DOUBLE_EQ(b->rd, d->rd);
  // Burley's profile is normalised to its albedo: its rings integrate to the dipole's total
  // (on a grid reaching past its slower exponential, e^(-r/3d)).
  const optics::RadialGrid wide{5.0 * defaultProfileRadiusMm(half) / 2000, 2000};
  auto bw = profileChannel(half, wide, burley);
  ASSERT_TRUE(bw);
  // 2 %: ring 0 holds the profile's 1/r peak, which a representative radius under-counts.
  EXPECT_NEAR(ringIntegral(*bw, wide), bw->rd, 0.02 * bw->rd);
  EXPECT_FALSE(multipoleUnreliable(thick));
  optics::LayeredMedium thin = half;
  thin.layers[0].thickness = 0.05;  // below 1/sigma_t' = 0.135 mm
  EXPECT_TRUE(multipoleUnreliable(thin));
}

TEST(ProfileStudy, RefusesAnEmptyMedium) {
  EXPECT_FALSE(profileChannel(optics::LayeredMedium{}, {0.01, 10}, ProfileConfig{}));
}

TEST(ProfileStudy, ChannelsShareOneGridAndThinSlabsWarnTheMultipole) {
  const std::vector<optics::LayeredMedium> media = {halfSpace(1.4, 0.01, 1.0, 0.8),
                                                    halfSpace(1.4, 0.1, 2.0, 0.8)};
  ProfileStudyConfig config;
  config.bins = 50;
  auto study = studyProfile(media, config);
  ASSERT_TRUE(study) << study.error().message;
  ASSERT_EQ(study->channels.size(), 2u);
  EXPECT_TRUE(study->warnings.empty());
  // The grid reaches the farther of the two default radii (the less absorbing medium's).
  EXPECT_NEAR(study->grid.drMm * 50,
              std::max(defaultProfileRadiusMm(media[0]), defaultProfileRadiusMm(media[1])), 1e-9);
  for (const auto& c : study->channels)
    EXPECT_EQ(c.rdRadial.size(), 50u);
  EXPECT_GT(study->channels[0].rd, study->channels[1].rd);  // less absorption reflects more
  const std::string json = profileStudyJson(*study, false);
  for (const char* key : {"\"Rd\"", "\"profile_us\"", "\"radial_bins\": 50"})
    EXPECT_NE(json.find(key), std::string::npos) << key;
  EXPECT_EQ(json.find("\"photons\""), std::string::npos);

  optics::LayeredMedium slab;
  slab.layers.push_back({1.4, 0.01, 1.0, 0.8, 0.1});  // 0.1 mm < 1/sigma_t' = 5 mm
  config.profile.method = ProfileMethod::Multipole;
  auto thin = studyProfile({slab}, config);
  ASSERT_TRUE(thin) << thin.error().message;
  EXPECT_EQ(thin->warnings.size(), 1u);
  EXPECT_FALSE(studyProfile({}, config));
}

}  // namespace
}  // namespace tissue::studies
