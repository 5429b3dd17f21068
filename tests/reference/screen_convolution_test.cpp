// The CPU reference convolution on analytic cases: profile integrals, a uniform irradiance
// gives back the profile's total, objects never mix, an impulse gives back the profile.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "tissue/reference/screen_convolution.h"

namespace tissue::test {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;

// A 2D Gaussian per channel, variance v mm^2: exp(-r^2 / 2v) / (2 pi v), tabulated to 6 sigma.
reference::RadialProfile gaussianProfile(Float3 varianceMm2, float scale = 1.0f) {
  reference::RadialProfile p;
  const float rMax = 6.0f * std::sqrt(std::max({varianceMm2.x, varianceMm2.y, varianceMm2.z}));
  for (int i = 0; i <= 2000; ++i) {
    const float r = rMax * static_cast<float>(i) / 2000.0f;
    auto g = [&](float v) { return scale * std::exp(-r * r / (2.0f * v)) / (2.0f * kPi * v); };
    p.radiusMm.push_back(r);
    p.value.push_back({g(varianceMm2.x), g(varianceMm2.y), g(varianceMm2.z)});
  }
  return p;
}

// A flat grid facing +z, `h` mm between pixel centres, every pixel object `id` with `radiance`.
struct Grid {
  int size;
  std::vector<Float4> radiance, position;
  reference::ScreenBuffers buffers() const { return {size, size, radiance, position}; }
};

Grid flatGrid(int size, float h, Float3 rgb, float id) {
  Grid g{size, {}, {}};
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      g.radiance.push_back({rgb.x, rgb.y, rgb.z, id});
      g.position.push_back({static_cast<float>(x) * h, -static_cast<float>(y) * h, 0.0f, 100.0f});
    }
  }
  return g;
}

TEST(ProfileIntegral, IsExactForPiecewiseLinearProfiles) {
  const reference::RadialProfile flat{{0.0f, 2.0f}, {Float3{1.0f, 2.0f, 0.5f}, Float3{1.0f, 2.0f, 0.5f}}};
  const Float3 disc = reference::profileIntegral(flat, 1.0f);  // pi r^2 R
  EXPECT_NEAR(disc.x, kPi, 1e-5);
  EXPECT_NEAR(disc.y, 2.0f * kPi, 1e-5);
  // A cone R = 1 - r on [0, 1]: 2 pi (1/2 - 1/3) = pi / 3.
  const reference::RadialProfile cone{{0.0f, 1.0f}, {Float3{1.0f, 1.0f, 1.0f}, Float3{}}};
  EXPECT_NEAR(reference::profileIntegral(cone, 5.0f).z, kPi / 3.0f, 1e-5);
  // A Gaussian integrates to its scale; normalisation makes it 1.
  const auto g = gaussianProfile({1.0f, 2.0f, 0.5f}, 0.3f);
  EXPECT_NEAR(reference::profileIntegral(g, 100.0f).y, 0.3f, 1e-3);
  EXPECT_NEAR(reference::profileIntegral(reference::normalizedProfile(g), 100.0f).x, 1.0f, 1e-5);
}

TEST(ScreenConvolution, UniformIrradianceGivesBackTheProfilesTotal) {
  const auto profile = gaussianProfile({0.5f, 1.0f, 2.0f}, 0.4f);
  const Float3 total = reference::profileIntegral(profile, 100.0f);
  const Grid g = flatGrid(101, 0.25f, {2.0f, 1.0f, 3.0f}, 1.0f);
  const std::vector<reference::RadialProfile> profiles{{}, profile};
  auto out = reference::convolveScreen(g.buffers(), profiles);
  ASSERT_TRUE(out) << out.error().message;
  const Float3 centre = (*out)[50 * 101 + 50];
  EXPECT_NEAR(centre.x, 2.0f * total.x, 0.01f * 2.0f * total.x);
  EXPECT_NEAR(centre.y, 1.0f * total.y, 0.01f * total.y);
  EXPECT_NEAR(centre.z, 3.0f * total.z, 0.01f * 3.0f * total.z);
  // At the grid's edge only about half the profile lies on the surface.
  EXPECT_LT((*out)[50 * 101].y, 0.6f * centre.y);
}

TEST(ScreenConvolution, AnImpulseGivesBackTheProfile) {
  const auto profile = gaussianProfile({1.0f, 1.0f, 1.0f});
  Grid g = flatGrid(61, 0.2f, {0.0f, 0.0f, 0.0f}, 1.0f);
  g.radiance[30 * 61 + 30] = {1.0f, 1.0f, 1.0f, 1.0f};  // one pixel of 0.04 mm^2
  const std::vector<reference::RadialProfile> profiles{{}, profile};
  auto out = reference::convolveScreen(g.buffers(), profiles);
  ASSERT_TRUE(out);
  for (const int d : {5, 10}) {  // 1 and 2 mm away: R(r) times the pixel's area
    const float r = 0.2f * static_cast<float>(d);
    const float expected = std::exp(-r * r / 2.0f) / (2.0f * kPi) * 0.04f;
    EXPECT_NEAR((*out)[30 * 61 + 30 + d].x, expected, 0.01f * expected) << "d = " << d;
  }
}

TEST(ScreenConvolution, ObjectsNeverMix) {
  Grid g = flatGrid(40, 0.25f, {1.0f, 1.0f, 1.0f}, 1.0f);
  for (int y = 0; y < 40; ++y)
    for (int x = 20; x < 40; ++x)
      g.radiance[y * 40 + x] = {0.0f, 0.0f, 0.0f, 2.0f};  // right half: another, dark object
  const auto profile = gaussianProfile({1.0f, 1.0f, 1.0f});
  const std::vector<reference::RadialProfile> profiles{{}, profile, profile};
  auto out = reference::convolveScreen(g.buffers(), profiles);
  ASSERT_TRUE(out);
  EXPECT_EQ((*out)[20 * 40 + 20].x, 0.0f);  // the dark object's first column stays dark
  EXPECT_GT((*out)[20 * 40 + 19].x, 0.3f);  // the bright one keeps its own light
  // Bad input is an Error, not a crash.
  EXPECT_FALSE(reference::convolveScreen({40, 41, g.radiance, g.position}, profiles));
}

}  // namespace
}  // namespace tissue::test
