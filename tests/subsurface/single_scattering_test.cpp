// Ray-marched single scattering against the closed form of a flat layered slab, and the layer
// model at known depths (François et al. 2006 eq. 3, Algorithms 1-2; Norberg 2010 eq. 13-14).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "tissue/subsurface/flat_slab.h"
#include "tissue/subsurface/layer_stack.h"
#include "tissue/subsurface/single_scattering.h"
#include "tissue/subsurface/triangle_bvh.h"

namespace tissue::subsurface {
namespace {

Float3 unit(float x, float y, float z) {
  const float l = std::sqrt(x * x + y * y + z * z);
  return {x / l, y / l, z / l};
}

// A stack whose single RGBA map is constant: boundaries at `b` (0..1) times `scaleMm`.
LayerStack constantStack(std::array<std::uint8_t, 4> b, float scaleMm,
                         std::vector<LayerCoefficients> layers) {
  Image8 map(2, 2, 4);
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 2; ++x)
      for (int c = 0; c < 4; ++c)
        map.at(x, y)[c] = b[c];
  LayerStack stack;
  stack.layers = std::move(layers);
  stack.depthScaleMm = scaleMm;
  stack.maps = *subsurfaceMapsFromImages(std::span<const Image8>(&map, 1));
  return stack;
}

// The flat surface z = 0, outward +z, seen at P = origin.
ShadingPoint flatPoint(Float3 toEye) {
  ShadingPoint p;
  p.position = {0, 0, 0};
  p.toEye = toEye;
  p.normal = {0, 0, 1};
  p.plane = {0, 0, 1, 0};
  p.tangent = {1, 0, 0};
  p.bitangent = {0, 1, 0};
  p.uv = {0.5f, 0.5f};
  return p;
}

// A light far along `dir` (no falloff, so only its direction matters up to parallax).
Light farLight(Float3 dir) {
  return {{dir.x * 1e6f, dir.y * 1e6f, dir.z * 1e6f}, {1, 1, 1}};
}

double maxRelativeError(Float3 a, Float3 b) {
  return std::max({std::abs(a.x - b.x) / b.x, std::abs(a.y - b.y) / b.y, std::abs(a.z - b.z) / b.z});
}

TEST(FlatSlab, OneLayerRayMarchMatchesTheAnalyticIntegralAndConverges) {
  LayerStack stack;
  stack.layers = {{{1.0f, 1.0f, 2.0f}, {1.5f, 1.5f, 2.5f}, 0.8f}};  // François Table 1, organs
  const Float3 toEye = unit(0.3f, 0.1f, 1.0f), toLight = unit(-0.5f, 0.2f, 1.0f);
  const Light light = farLight(toLight);
  MarchSettings s;
  s.depthMaxMm = 3.0f;
  s.attenuationThreshold = 0.0f;
  const Float3 exact = flatSlabSingleScattering(stack.layers, {}, toEye, toLight, s.depthMaxMm);
  double previous = 1.0;
  for (int n : {10, 40, 160}) {
    s.samples = n;
    const Float3 marched = marchSingleScattering(flatPoint(toEye), stack, {&light, 1}, s, 0.5f).radiance;
    const double err = maxRelativeError(marched, exact);
    EXPECT_LT(err, previous / 8.0) << n << " samples: the midpoint rule converges as 1/n^2";
    previous = err;
  }
  EXPECT_LT(previous, 1e-3);
}

TEST(FlatSlab, FiveLayersOfConstantDepthMatchTheAnalyticIntegral) {
  const std::vector<LayerCoefficients> layers = {{{2.0f, 1.0f, 1.0f}, {2.6f, 1.6f, 1.6f}, 0.25f},
                                                 {{3.7f, 4.4f, 5.05f}, {3.732f, 4.57f, 5.53f}, 0.0f},
                                                 {{6.0f, 3.0f, 2.0f}, {6.6f, 3.6f, 2.6f}, 0.4f},
                                                 {{6.0f, 3.0f, 2.0f}, {6.6f, 3.6f, 2.6f}, 0.4f},
                                                 {{1.0f, 1.0f, 2.0f}, {1.5f, 1.5f, 2.5f}, 0.8f}};
  const LayerStack stack = constantStack({51, 102, 153, 204}, 2.0f, layers);  // 0.4, 0.8, 1.2, 1.6 mm
  const float bounds[] = {0.4f, 0.8f, 1.2f, 1.6f};
  MarchSettings s;
  s.depthMaxMm = 2.5f;
  s.attenuationThreshold = 0.0f;
  s.samples = 2000;
  for (const Float3& toLight : {unit(0, 0, 1), unit(0.6f, 0, 1), unit(-1, 0.5f, 0.4f)}) {
    const Float3 toEye = unit(-0.2f, 0.3f, 1.0f);
    const Light light = farLight(toLight);
    const Float3 exact = flatSlabSingleScattering(layers, bounds, toEye, toLight, s.depthMaxMm);
    const Float3 marched = marchSingleScattering(flatPoint(toEye), stack, {&light, 1}, s, 0.5f).radiance;
    // Layer boundaries fall between samples: first-order error ~ step / layer.
    EXPECT_LT(maxRelativeError(marched, exact), 3e-3);
  }
}

TEST(FlatSlab, MeshModeOnAFlatMeshEqualsPlaneMode) {
  LayerStack stack;
  stack.layers = {{{1.0f, 1.0f, 2.0f}, {1.5f, 1.5f, 2.5f}, 0.8f}};
  const std::vector<Float3> quad = {{-500, -500, 0}, {500, -500, 0}, {500, 500, 0}, {-500, 500, 0}};
  const std::vector<Triangle> tris = {{0, 1, 2}, {0, 2, 3}};
  const TriangleBvh bvh(quad, tris);
  const Float3 toEye = unit(0.4f, 0.0f, 1.0f);
  const Light light = {{30.0f, 10.0f, 40.0f}, {1, 1, 1}};  // near: the direction varies along the ray
  MarchSettings s;
  s.samples = 64;
  s.attenuationThreshold = 0.0f;
  const Float3 planes = marchSingleScattering(flatPoint(toEye), stack, {&light, 1}, s, 0.5f).radiance;
  const Float3 mesh = marchSingleScattering(flatPoint(toEye), stack, {&light, 1}, s, 0.5f, &bvh).radiance;
  EXPECT_LT(maxRelativeError(planes, mesh), 1e-6);
}

TEST(SingleScattering, LightBehindTheSurfacePlaneGivesNothingAndLightsAdd) {
  LayerStack stack;
  stack.layers = {{{1.0f, 1.0f, 2.0f}, {1.5f, 1.5f, 2.5f}, 0.8f}};
  MarchSettings s;
  const Light below = farLight(unit(0.2f, 0.0f, -1.0f));
  const Float3 none = marchSingleScattering(flatPoint({0, 0, 1}), stack, {&below, 1}, s, 0.5f).radiance;
  EXPECT_EQ(none.x + none.y + none.z, 0.0f);
  const Light two[] = {farLight(unit(0.5f, 0, 1)), farLight(unit(-0.3f, 0.4f, 1))};
  const Float3 a = marchSingleScattering(flatPoint({0, 0, 1}), stack, {&two[0], 1}, s, 0.5f).radiance;
  const Float3 b = marchSingleScattering(flatPoint({0, 0, 1}), stack, {&two[1], 1}, s, 0.5f).radiance;
  const Float3 ab = marchSingleScattering(flatPoint({0, 0, 1}), stack, two, s, 0.5f).radiance;
  EXPECT_NEAR(ab.x, a.x + b.x, 1e-5f * ab.x);
}

TEST(SingleScattering, EarlyStopEndsTheMarchOnceAttenuationFallsBelowTheThreshold) {
  // 0.2 mm of organ tissue over blood: light dies out in the blood long before M_max.
  const LayerCoefficients organ{{1.0f, 1.0f, 2.0f}, {1.5f, 1.5f, 2.5f}, 0.8f};
  const LayerCoefficients blood{{6.0f, 3.0f, 2.0f}, {6.6f, 6.6f, 6.6f}, 0.4f};  // grey extinction
  const LayerStack stack = constantStack({26, 255, 255, 255}, 2.0f, {organ, blood, blood, blood, blood});
  const Light light = farLight(unit(0, 0, 1));
  MarchSettings s;
  s.samples = 100;
  s.depthMaxMm = 10.0f;
  s.attenuationThreshold = 0.0f;
  const MarchResult full = marchSingleScattering(flatPoint({0, 0, 1}), stack, {&light, 1}, s, 0.5f);
  EXPECT_EQ(full.samplesUsed, 100);
  s.attenuationThreshold = 1e-2f;
  const MarchResult stopped = marchSingleScattering(flatPoint({0, 0, 1}), stack, {&light, 1}, s, 0.5f);
  // M_max shrinks to -ln(0.01) / 1.5 = 3.07 mm; the red channel, exp(-1.5 0.204 - 6.6 (t - 0.204)),
  // reaches 0.01 at t = 0.855 mm (28% of it).
  EXPECT_GT(stopped.samplesUsed, 20);
  EXPECT_LT(stopped.samplesUsed, 40);
  // Reference with the same M_max and no stop: the dropped tail is small.
  s.attenuationThreshold = 0.0f;
  s.depthMaxMm = float(-std::log(1e-2) / 1.5);
  const Float3 tail = marchSingleScattering(flatPoint({0, 0, 1}), stack, {&light, 1}, s, 0.5f).radiance;
  EXPECT_LT(maxRelativeError(stopped.radiance, tail), 0.02);
}

TEST(Adaptive, MarchLengthFollowsTheRoundTripAndGrazingViewsGetMoreSamples) {
  // One layer over a fine (4096-texel, 0.02 mm) map whose boundaries lie deep below.
  const LayerCoefficients organ{{1.0f, 1.0f, 2.0f}, {1.5f, 1.5f, 2.5f}, 0.8f};
  LayerStack stack;
  stack.layers.assign(5, organ);
  stack.maps.width = 4096;
  stack.maps.height = 1;
  stack.maps.mapCount = 1;
  stack.maps.depths.assign(4096 * 4, 1.0f);
  MarchSettings march;
  AdaptiveSettings adaptive;
  // Head-on: the round trip crosses 2 sigma_min t, so t = -ln(0.03) / (2 * 1.5) = 1.169 mm < 3 mm.
  const AdaptiveChoice frontal = adaptiveMarch(flatPoint({0, 0, 1}), stack, march, adaptive, 0.05f);
  EXPECT_NEAR(frontal.lengthMm, -std::log(0.03) / 3.0, 1e-5);
  EXPECT_EQ(frontal.samples, int(std::ceil(double(frontal.lengthMm / adaptive.depthResolutionMm) - 1e-4)));
  // At 75 degrees the march drifts sideways across texels and needs more samples.
  const AdaptiveChoice grazing =
      adaptiveMarch(flatPoint(unit(0.966f, 0.0f, 0.259f)), stack, march, adaptive, 0.05f);
  EXPECT_GT(grazing.samples, frontal.samples);
  EXPECT_LE(grazing.samples, adaptive.maxSamples);
  // A large pixel footprint (far away) relaxes the sideways criterion.
  const AdaptiveChoice far =
      adaptiveMarch(flatPoint(unit(0.966f, 0.0f, 0.259f)), stack, march, adaptive, 5.0f);
  EXPECT_LT(far.samples, grazing.samples);
}

TEST(LayerStack, LookupAtKnownDepths) {
  // Texel (0, 0) (file row 0: v near 1) has boundaries 0.1, 0.3, 0.3, 0.9 of 2 mm; texel (1, 0) 0.2.. .
  Image8 map(2, 1, 4);
  const std::uint8_t left[4] = {51, 153, 153, 255}, right[4] = {102, 102, 204, 255};
  for (int c = 0; c < 4; ++c)
    map.at(0, 0)[c] = left[c], map.at(1, 0)[c] = right[c];
  LayerStack stack;
  stack.layers.assign(5, LayerCoefficients{});
  stack.depthScaleMm = 2.0f;
  stack.maps = *subsurfaceMapsFromImages(std::span<const Image8>(&map, 1));
  ASSERT_TRUE(validateLayerStack(stack).ok());
  const Boundaries b = sampleBoundaries(stack, {0.25f, 0.5f});  // texel (0, 0) centre
  ASSERT_EQ(b.count, 4);
  EXPECT_NEAR(b.depthMm[0], 0.4f, 1e-6f);
  EXPECT_NEAR(b.depthMm[1], 1.2f, 1e-6f);
  EXPECT_EQ(findLayer(b, 0.0f), 0);
  EXPECT_EQ(findLayer(b, 0.39f), 0);
  EXPECT_EQ(findLayer(b, 0.41f), 1);
  EXPECT_EQ(findLayer(b, 1.21f), 3) << "layer 2 has zero thickness here and is skipped";
  EXPECT_EQ(findLayer(b, 2.5f), 4);
  EXPECT_NEAR(layerThicknessMm(b, 2), 0.0f, 1e-6f);
  EXPECT_TRUE(std::isinf(layerThicknessMm(b, 4)));
  // Half way between the texel centres the depths are the mean (GL_LINEAR).
  const Boundaries mid = sampleBoundaries(stack, {0.5f, 0.5f});
  EXPECT_NEAR(mid.depthMm[0], 0.6f, 1e-6f);
  EXPECT_NEAR(mid.depthMm[2], 1.4f, 1e-6f);
  EXPECT_NEAR(sampleBoundaries(stack, {-3.0f, 0.5f}).depthMm[0], 0.4f, 1e-6f) << "clamped to the edge";
}

TEST(LayerStack, ValidationNamesTheProblem) {
  LayerStack stack;
  stack.layers.assign(3, LayerCoefficients{});
  Image8 map(1, 1, 4);
  stack.maps = *subsurfaceMapsFromImages(std::span<const Image8>(&map, 1));
  const auto wrongCount = validateLayerStack(stack);
  ASSERT_FALSE(wrongCount.ok());
  EXPECT_NE(wrongCount.error().message.find("4N + 1"), std::string::npos);
  stack.layers.assign(5, LayerCoefficients{});
  stack.layers[2].sigma_s = {9, 9, 9};
  ASSERT_FALSE(validateLayerStack(stack).ok());
  const Image8 rgb(1, 1, 3);
  EXPECT_FALSE(subsurfaceMapsFromImages(std::span<const Image8>(&rgb, 1)).ok());
}

TEST(PixelJitter, UniformAndDecorrelated) {
  double sum = 0.0, sumSq = 0.0, lag = 0.0;
  const int n = 256;
  for (unsigned y = 0; y < n; ++y)
    for (unsigned x = 0; x < n; ++x) {
      const double v = pixelJitter(x, y);
      ASSERT_GE(v, 0.0);
      ASSERT_LT(v, 1.0);
      sum += v;
      sumSq += v * v;
      lag += (v - 0.5) * (double(pixelJitter(x + 1, y)) - 0.5);
    }
  const double count = double(n) * n;
  EXPECT_NEAR(sum / count, 0.5, 0.01);
  EXPECT_NEAR(sumSq / count - 0.25, 1.0 / 12.0, 0.01) << "E[v^2] - 1/4 = 1/12 for U(0, 1)";
  EXPECT_NEAR(lag / count, 0.0, 0.005) << "neighbouring pixels are uncorrelated";
  EXPECT_NE(pixelJitter(3, 4, 0), pixelJitter(3, 4, 1));
}

}  // namespace
}  // namespace tissue::subsurface
