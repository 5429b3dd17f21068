// CPU images: camera rays, interpolation and the march together, against the flat-slab closed form.
#include <gtest/gtest.h>

#include "flat_quad.h"

#include <cmath>
#include <vector>

#include "tissue/subsurface/flat_slab.h"
#include "tissue/subsurface/reference_image.h"

namespace tissue::subsurface {
namespace {

using Quad = test::FlatQuad;

TEST(ReferenceImage, UvScaleOfAQuad) {
  const Quad q;
  EXPECT_NEAR(uvPerMmOf(q.positions, q.uvs, q.triangles), 0.01f, 1e-7f);
}

TEST(ReferenceImage, FlatQuadSeenHeadOnMatchesTheClosedFormInEveryPixel) {
  const Quad q;
  LayerStack stack;
  stack.layers = {{{1.0f, 1.0f, 2.0f}, {1.5f, 1.5f, 2.5f}, 0.8f}};
  const Light light{{0.0f, 0.0f, 1e7f}, {1, 1, 1}};
  PinholeCamera camera;
  camera.eye = {0, 0, 1e4f};  // far: nearly parallel rays, one view direction
  camera.verticalFovDeg = 0.3f;
  CpuImageSettings s;
  s.width = 24;
  s.height = 18;
  s.jitter = false;
  s.march.samples = 200;
  s.march.attenuationThreshold = 0.0f;
  for (EntryMode mode : {EntryMode::Planes, EntryMode::Mesh}) {
    s.entry = mode;
    const RadianceImage image = renderSingleScatteringCpu(q.view(), stack, {&light, 1}, camera, s);
    const Float3 exact = flatSlabSingleScattering(stack.layers, {}, {0, 0, 1}, {0, 0, 1}, s.march.depthMaxMm);
    for (std::size_t i = 0; i < image.radiance.size(); ++i) {
      ASSERT_TRUE(image.covered[i]);
      EXPECT_NEAR(image.radiance[i].z, exact.z, 1e-3f * exact.z);
      EXPECT_EQ(image.samples[i], 200);
    }
  }
}

TEST(ReferenceImage, DisplayTransformAndRms) {
  RadianceImage r;
  r.width = 2;
  r.height = 1;
  r.radiance = {{1, 1, 1}, {0, 0, 0}};
  r.covered = {1, 0};
  const Image8 a = toDisplay(r, 1.0f, {0, 0, 0});
  EXPECT_EQ(a.at(0, 0)[0], 188);  // Reinhard 0.5, sRGB 0.7354
  EXPECT_EQ(a.at(1, 0)[1], 0);
  Image8 b = a;
  b.at(0, 0)[0] = 188 - 51;  // 0.2 on one of six values
  EXPECT_NEAR(displayRms(a, b), 0.2 / std::sqrt(6.0), 1e-9);
  const std::uint8_t mask[] = {1, 0};
  EXPECT_NEAR(displayRms(a, b, mask), 0.2 / std::sqrt(3.0), 1e-9);
}

TEST(ReferenceImage, RelativeRadianceRmsIsScaleFreeAndMasked) {
  const std::vector<Float3> reference = {{1.0f, 2.0f, 3.0f}, {0.5f, 0.5f, 0.5f}, {4.0f, 0.0f, 1.0f}};
  std::vector<Float3> brighter;
  for (const Float3& r : reference)
    brighter.push_back({1.1f * r.x, 1.1f * r.y, 1.1f * r.z});
  EXPECT_EQ(relativeRadianceRms(reference, reference), 0.0);
  EXPECT_NEAR(relativeRadianceRms(brighter, reference), 0.1, 1e-6) << "10% brighter everywhere";
  // Only the masked pixel counts: an error elsewhere does not show.
  std::vector<Float3> wrongElsewhere = reference;
  wrongElsewhere[0] = {9.0f, 9.0f, 9.0f};
  const std::vector<std::uint8_t> mask = {0, 1, 1};
  EXPECT_EQ(relativeRadianceRms(wrongElsewhere, reference, mask), 0.0);
  EXPECT_GT(relativeRadianceRms(wrongElsewhere, reference), 1.0);
  // Mismatched sizes and a black reference have no answer.
  EXPECT_EQ(relativeRadianceRms(std::span(reference).first(2), reference), -1.0);
  const std::vector<Float3> black(3, Float3{0.0f, 0.0f, 0.0f});
  EXPECT_EQ(relativeRadianceRms(reference, black), -1.0);
}

}  // namespace
}  // namespace tissue::subsurface
