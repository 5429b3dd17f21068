// Texture-space diffusion maths on known inputs: depth-based map size (Jimenez et al. eq. 3-4),
// eye-space clip planes (eq. 5-6) against clip-space containment, UV stretch, Gaussian sums and
// blur taps, and the CPU reference convolution (energy of a uniformly lit patch, point source).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "tissue/render/texture_space_math.h"
#include "tissue/render/texture_space_reference.h"

namespace tissue::render {
namespace {

/// d'Eon & Luebke's skin Gaussians (../shared/reference/deon_skin_gaussians.tsv).
std::vector<ProfileGaussian> deonSkin() {
  return {{0.0064f, {0.233f, 0.455f, 0.649f}}, {0.0484f, {0.100f, 0.336f, 0.344f}},
          {0.187f, {0.118f, 0.198f, 0.0f}},    {0.567f, {0.113f, 0.007f, 0.007f}},
          {1.99f, {0.358f, 0.004f, 0.0f}},     {7.41f, {0.078f, 0.0f, 0.0f}}};
}

TEST(TextureSpaceMath, DepthBasedSizeFollowsEquations3And4) {
  // The paper's d_ref = 4.5 and T_max = 2048.
  EXPECT_FLOAT_EQ(irradianceMapScale(9.0f, 4.5f), 0.5f);
  EXPECT_FLOAT_EQ(irradianceMapScale(2.0f, 4.5f), 1.0f);  // closer than d_ref: full size
  EXPECT_FLOAT_EQ(irradianceMapScale(45.0f, 4.5f), 0.1f);
  EXPECT_EQ(irradianceMapSize(0.5f, 2048), 1024);
  EXPECT_EQ(irradianceMapSize(0.1f, 2048), 205);  // ceil(204.8)
  EXPECT_EQ(irradianceMapSize(1e-4f, 2048), 16);  // floor of the map size
  EXPECT_EQ(irradianceMapSize(1.0f, 2048), 2048);
  // Fig. 4: the nearest corner of [-1, 1]^3 seen from (10, 0, 0) is (1, +-1, +-1).
  EXPECT_NEAR(nearestBoxCornerDistance({10, 0, 0}, {-1, -1, -1}, {1, 1, 1}), std::sqrt(83.0f), 1e-5f);
  EXPECT_NEAR(nearestBoxCornerDistance({3, 4, 1}, {0, 0, 0}, {1, 1, 1}), std::sqrt(4.0f + 9.0f), 1e-5f);
}

/// A symmetric perspective projection (gluPerspective), column-major.
Mat4 perspective(float fovYDeg, float aspect, float n, float f) {
  const float t = 1.0f / std::tan(fovYDeg * std::numbers::pi_v<float> / 360.0f);
  Mat4 m{};
  m[0] = t / aspect;
  m[5] = t;
  m[10] = (f + n) / (n - f);
  m[11] = -1.0f;
  m[14] = 2.0f * f * n / (n - f);
  return m;
}

TEST(TextureSpaceMath, EyeSpacePlanesClipLikeClipSpace) {
  const Mat4 p = perspective(90.0f, 1.5f, 1.0f, 100.0f);
  const auto planes = eyeSpaceFrustumPlanes(p);
  // Known points: 90 degrees vertical, aspect 1.5, so |y| <= -z and |x| <= 1.5 (-z).
  EXPECT_TRUE(insideFrustum(planes, {0, 0, -5}));
  EXPECT_TRUE(insideFrustum(planes, {7.4f, 4.9f, -5}));
  EXPECT_FALSE(insideFrustum(planes, {7.6f, 0, -5}));
  EXPECT_FALSE(insideFrustum(planes, {0, 5.1f, -5}));
  EXPECT_FALSE(insideFrustum(planes, {0, 0, -0.5f}));    // before the near plane
  EXPECT_FALSE(insideFrustum(planes, {0, 0, -101.0f}));  // beyond the far plane
  EXPECT_FALSE(insideFrustum(planes, {0, 0, 5}));        // behind the eye
  // Random points: eq. 6 in eye space agrees with -w <= x, y, z <= w in clip space.
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  int agree = 0, inside = 0;
  for (int i = 0; i < 2000; ++i) {
    const Float3 e{u(rng) * 150.0f, u(rng) * 100.0f, u(rng) * 60.0f - 55.0f};
    float c[4];
    for (int r = 0; r < 4; ++r)
      c[r] = p[std::size_t(r)] * e.x + p[std::size_t(4 + r)] * e.y + p[std::size_t(8 + r)] * e.z +
             p[std::size_t(12 + r)];
    const bool clipInside = std::abs(c[0]) <= c[3] && std::abs(c[1]) <= c[3] && std::abs(c[2]) <= c[3];
    agree += clipInside == insideFrustum(planes, e);
    inside += clipInside;
  }
  EXPECT_EQ(agree, 2000);
  EXPECT_GT(inside, 100);
  // D > 1 widens the frustum (a margin for light scattered in from off screen).
  const auto wide = eyeSpaceFrustumPlanes(p, 1.2f);
  EXPECT_TRUE(insideFrustum(wide, {7.6f, 0, -5}));
}

TEST(TextureSpaceMath, StretchOfUndeformedAndStretchedPatch) {
  // A 40 x 20 mm patch mapped to [0, 1]^2: 40 mm per u, 20 mm per v.
  const std::array<Float2, 3> uv = {Float2{0, 0}, Float2{1, 0}, Float2{0, 1}};
  const Float2 rest = uvStretch({Float3{0, 0, 0}, Float3{40, 0, 0}, Float3{0, 20, 0}}, uv);
  EXPECT_NEAR(rest.x, 40.0f, 1e-4f);
  EXPECT_NEAR(rest.y, 20.0f, 1e-4f);
  // Stretched by 1.5 along x and turned in space: 60 and 20.
  const float c = std::cos(0.7f), s = std::sin(0.7f);
  const Float2 stretched = uvStretch({Float3{0, 0, 0}, Float3{60 * c, 0, 60 * s}, Float3{0, 20, 0}}, uv);
  EXPECT_NEAR(stretched.x, 60.0f, 1e-4f);
  EXPECT_NEAR(stretched.y, 20.0f, 1e-4f);
  // A shear in UV does not change |dP/du| of the same surface: (0,0)->(1,0), (0.5,1).
  const Float2 sheared = uvStretch({Float3{0, 0, 0}, Float3{40, 0, 0}, Float3{20, 20, 0}},
                                   {Float2{0, 0}, Float2{1, 0}, Float2{0.5f, 1}});
  EXPECT_NEAR(sheared.x, 40.0f, 1e-4f);
  EXPECT_NEAR(sheared.y, 20.0f, 1e-4f);
}

TEST(TextureSpaceMath, GaussianSumIntegratesToItsWeights) {
  const auto skin = deonSkin();
  double total[3] = {0, 0, 0};
  const double dr = 0.0005;
  for (double r = 0.5 * dr; r < 30.0; r += dr) {
    const Float3 v = evaluateGaussianSum(skin, float(r));
    total[0] += 2 * std::numbers::pi * r * double(v.x) * dr;
    total[1] += 2 * std::numbers::pi * r * double(v.y) * dr;
    total[2] += 2 * std::numbers::pi * r * double(v.z) * dr;
  }
  EXPECT_NEAR(total[0], 1.0, 2e-3);  // each column of d'Eon's table sums to 1
  EXPECT_NEAR(total[1], 1.0, 2e-3);
  EXPECT_NEAR(total[2], 1.0, 2e-3);
  const auto steps = incrementalVariances(skin);
  double sum = 0.0;
  for (float v : steps)
    sum += double(v);
  EXPECT_NEAR(sum, 7.41, 1e-5);
  EXPECT_NEAR(steps[1], 0.0484 - 0.0064, 1e-6);
}

TEST(TextureSpaceMath, BlurTapsAreANormalisedUnitGaussian) {
  for (int half : {3, 5, 8}) {
    const auto taps = gaussianBlurTaps(half);
    ASSERT_EQ(taps.size(), std::size_t(2 * half + 1));
    double w = 0.0, var = 0.0;
    for (const BlurTap& t : taps)
      w += double(t.weight), var += double(t.weight * t.offsetSigma * t.offsetSigma);
    EXPECT_NEAR(w, 1.0, 1e-6);
    EXPECT_NEAR(var, 1.0, 0.03) << half;  // truncation at 3 sigma and sampling
  }
}

TEST(TextureSpaceReference, UniformPatchKeepsItsIrradianceAndAPointGivesTheProfile) {
  RadialProfileTable table;
  const auto skin = deonSkin();
  for (int i = 0; i <= 2000; ++i) {
    table.radiusMm.push_back(0.01f * float(i));
    table.value.push_back(evaluateGaussianSum(skin, table.radiusMm.back()));
  }
  // A 60 x 60 mm patch sampled every 0.1 mm, irradiance (1, 0.5, 0.25).
  SurfaceSamples patch;
  const float h = 0.1f;
  for (int j = 0; j < 600; ++j)
    for (int i = 0; i < 600; ++i) {
      patch.positionMm.push_back({(float(i) + 0.5f) * h - 30.0f, (float(j) + 0.5f) * h - 30.0f, 0.0f});
      patch.areaMm2.push_back(h * h);
      patch.irradiance.push_back({1.0f, 0.5f, 0.25f});
    }
  const std::vector<Float3> centre = {{0.05f, 0.05f, 0.0f}};
  const auto m = convolveOverSurface(patch, centre, table, 20.0f);
  // Within 5%: the samples' disks do not tile the plane exactly, which matters where the grid
  // spacing is near the narrowest sigma (0.08 mm; blue is almost all narrow terms).
  EXPECT_NEAR(m[0].x, 1.0f, 0.05f);
  EXPECT_NEAR(m[0].y, 0.5f, 0.025f);
  EXPECT_NEAR(m[0].z, 0.25f, 0.0125f);
  // One small sample (0.01 mm^2) at the origin: M(r) = R(r) E A where R is smooth (r = 3 mm,
  // only the wide Gaussians left), and nothing beyond the cutoff.
  SurfaceSamples point{{{0, 0, 0}}, {0.01f}, {{1, 1, 1}}};
  const std::vector<Float3> at = {{0.0f, 3.0f, 0.0f}, {0.0f, 0.0f, 25.0f}};
  const auto mp = convolveOverSurface(point, at, table, 20.0f);
  const Float3 r = evaluateProfile(table, 3.0f);
  EXPECT_NEAR(mp[0].x, 0.01f * r.x, 0.002f * 0.01f * r.x);
  EXPECT_EQ(mp[1], Float3{});
  // A coarse patch (1 mm texels, wider than the narrow Gaussians) still keeps the energy.
  SurfaceSamples coarse;
  for (int j = 0; j < 60; ++j)
    for (int i = 0; i < 60; ++i) {
      coarse.positionMm.push_back({float(i) - 29.5f, float(j) - 29.5f, 0.0f});
      coarse.areaMm2.push_back(1.0f);
      coarse.irradiance.push_back({1.0f, 1.0f, 1.0f});
    }
  const std::vector<Float3> middle = {{0.5f, 0.5f, 0.0f}};
  const auto mc = convolveOverSurface(coarse, middle, table, 20.0f);
  EXPECT_NEAR(mc[0].x, 1.0f, 0.05f);
  EXPECT_NEAR(mc[0].y, 1.0f, 0.05f);
  EXPECT_NEAR(mc[0].z, 1.0f, 0.05f);
}

TEST(TextureSpaceMath, UvDensityIsTheSquareRootOfUvAreaOverSurfaceArea) {
  // A 40 x 10 mm rectangle mapped onto [0, 0.5]^2 (tilted out of z = 0: any orientation works).
  const std::vector<Float3> p = {{0, 0, 0}, {40, 0, 0}, {40, 6, 8}, {0, 6, 8}};
  const std::vector<Float2> uv = {{0, 0}, {0.5f, 0}, {0.5f, 0.5f}, {0, 0.5f}};
  const std::vector<Triangle> t = {{0, 1, 2}, {0, 2, 3}};
  EXPECT_NEAR(uvDensity(p, uv, t), std::sqrt(0.25f / 400.0f), 1e-6f);
  EXPECT_EQ(uvDensity(p, uv, {}), 0.0f);  // no area
}

}  // namespace
}  // namespace tissue::render
