// The ray-march failure study on a flat quad, where eq. 14's fitted planes are the surface: the
// plane entry equals the mesh entry (no error), few samples do err, a head-on view has no grazing
// pixels (-1), and the difference image is |a - b| x gain, clamped.
#include "tissue/studies/raymarch_study.h"

#include <gtest/gtest.h>

#include "../subsurface/flat_quad.h"
#include "data_organ.h"

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

// The study's cases on the data meshes, small: one result and one table row per case, errors
// display RMS in [0, 1] (or -1 for an empty band), 3 jittered samples further from the reference
// than the plane approximation at the reference's own samples, and three images per case.
TEST(RayMarchStudy, EveryCaseHasItsRowAndImages) {
  RayMarchStudyConfig config;
  config.width = 32, config.height = 24;
  config.referenceSamples = 24;
  config.fewSamples = 3;
  auto study = runRayMarchStudy(testdata::dataOrgan, config, true);
  ASSERT_TRUE(study) << study.error().message;
  const std::size_t n = std::size(kRayMarchStudyCases);
  ASSERT_EQ(study->cases.size(), n);
  for (std::size_t i = 0; i < n; ++i) {
    const RayMarchCaseResult& c = study->cases[i];
    EXPECT_EQ(c.name, kRayMarchStudyCases[i].name);
    for (double e : {c.planes.all, c.few.all, c.planes.frontal, c.few.frontal})
      EXPECT_TRUE(e >= 0.0 && e <= 1.0) << c.name << " " << e;
    for (double e : {c.planes.grazing, c.few.grazing})
      EXPECT_TRUE(e == -1.0 || (e >= 0.0 && e <= 1.0)) << c.name << " " << e;
    EXPECT_GT(c.few.all, c.planes.all) << c.name;
  }
  const Report& report = study->output.report;
  EXPECT_EQ(testdata::lineCount(testdata::fileText(report, "raymarch_study.csv")), n + 1);
  EXPECT_EQ(testdata::fileText(report, "raymarch_study.json"), study->output.json + "\n");
  EXPECT_NE(study->output.json.find("\"samples10_rms_frontal\""), std::string::npos);
  ASSERT_EQ(report.images.size(), 3 * n);
  EXPECT_EQ(report.images[0].name, "raymarch_fail_patch_plane_error_x8.png");
  for (const ReportImage& image : report.images)
    EXPECT_EQ(image.image.width * 3, image.image.height * 4) << image.name;
  EXPECT_FALSE(runRayMarchStudy([](const std::string&) { return scene::OrganSource{}; }, config));
}

}  // namespace
}  // namespace tissue::studies
