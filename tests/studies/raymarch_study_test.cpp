// The ray-march failure study on a flat quad, where eq. 14's fitted planes are the surface: the
// plane entry equals the mesh entry (no error), few samples do err, a head-on view has no grazing
// pixels (-1), and the difference image is |a - b| x gain, clamped.
#include "tissue/studies/raymarch_study.h"

#include <gtest/gtest.h>

#include "../subsurface/flat_quad.h"

#include <vector>

namespace tissue::studies {
namespace {

using Quad = test::FlatQuad;

TEST(RayMarchStudy, PlanesAreExactOnAFlatQuad) {
  const Quad q;
  subsurface::LayerStack stack;
  stack.layers = {{{1.0f, 1.0f, 2.0f}, {1.5f, 1.5f, 2.5f}, 0.8f}};
  const subsurface::Light light{{20.0f, 10.0f, 300.0f}, {1, 1, 1}};
  subsurface::PinholeCamera camera;
  camera.eye = {0, 0, 150};  // head-on: every N.V near 1
  camera.verticalFovDeg = 20.0f;
  RayMarchStudyConfig config;
  config.width = 32;
  config.height = 24;
  config.referenceSamples = 50;
  config.fewSamples = 3;
  const RayMarchStudy s = studyRayMarch(q.view(), stack, {&light, 1}, camera, config);
  EXPECT_LT(s.planes.all, 1e-3);
  EXPECT_LT(s.planes.frontal, 1e-3);
  EXPECT_EQ(s.planes.grazing, -1.0);  // no grazing pixel
  EXPECT_GE(s.few.all, 0.0);
  EXPECT_EQ(s.reference.width, 32);
  EXPECT_EQ(s.fewImage.height, 24);
}

TEST(RayMarchStudy, DifferenceImageIsScaledAndClamped) {
  Image8 a(2, 1, 4), b(2, 1, 4);
  a.at(0, 0)[0] = 100, b.at(0, 0)[0] = 90;  // 10 x 8 = 80
  a.at(1, 0)[1] = 0, b.at(1, 0)[1] = 200;   // 200 x 8 -> 255
  const Image8 d = differenceImage(a, b);
  EXPECT_EQ(d.at(0, 0)[0], 80);
  EXPECT_EQ(d.at(1, 0)[1], 255);
  EXPECT_EQ(d.at(0, 0)[3], 255);
  EXPECT_EQ(differenceImage(a, a).at(1, 0)[1], 0);
}

}  // namespace
}  // namespace tissue::studies
