// The scenes of the texture-space speed-up table (studies/tsd_bench.h): the camera sits the asked
// distance from its target with the organ inside its depth range, and on a headless context the
// row holds 16 organs 1.1 widths apart, its scenes the middle n of them centred on the target.
#include "tissue/studies/tsd_bench.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "data_organ.h"
#include "tissue/context/headless_context.h"

namespace tissue::studies {
namespace {

TEST(TsdBench, CameraAtTheAskedDistance) {
  const render::Scene s = tsdBenchScene({10.0f, 0.0f, 0.0f}, 300.0f, 150.0f, 400.0f);
  const Float3 d{s.camera.eye.x - 10.0f, s.camera.eye.y, s.camera.eye.z};
  EXPECT_NEAR(std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z), 300.0f, 1e-3f);
  EXPECT_LE(s.camera.nearMm, 300.0f - 150.0f + 1e-3f);
  EXPECT_GE(s.camera.farMm, 300.0f + 150.0f);
}

TEST(TsdBenchGl, TheRowAndItsMiddleOrgans) {
  auto organ = loadTsdOrgan(std::filesystem::path(TISSUE_TEST_DATA_DIR) / "meshes" / "liver.obj", 1.0f);
  ASSERT_TRUE(organ) << organ.error().message;
  auto context = context::createHeadlessContext({}, {.backend = "", .log = false});
  ASSERT_TRUE(context) << "no headless context (EGL, then OSMesa): " << context.error().message;
  auto renderer = render::Renderer::create((*context)->procAddressFunction());
  ASSERT_TRUE(renderer) << renderer.error().message;
  auto row = uploadOrganRow(*renderer, *organ);
  ASSERT_TRUE(row) << row.error().message;
  ASSERT_EQ(row->meshes.size(), std::size_t(TsdOrganRow::kMaxObjects));
  EXPECT_NEAR(row->widthMm, organ->hi.x - organ->lo.x, 1e-4f);
  EXPECT_NEAR(row->rowX(1) - row->rowX(0), 1.1f * row->widthMm, 1e-3f);
  EXPECT_NEAR(row->rowX(7) + row->rowX(8), 0.0f, 1e-3f);  // centred on x = 0
  for (int n : kTsdBenchObjects) {
    const render::Scene s = row->sceneOf(n, 2.0f * row->sizeMm, {});
    ASSERT_EQ(s.objects.size(), std::size_t(n));
    EXPECT_NEAR(s.camera.target.x, 0.0f, 0.6f * 1.1f * row->widthMm) << n;  // the middle of the row
  }
  render::TextureSpaceSettings tsd;
  tsd.gaussians = {render::ProfileGaussian{1.0f, {1.0f, 1.0f, 1.0f}}};
  tsd.mapSize = 64;
  const render::Scene one = row->sceneOf(1, row->sizeMm, tsd);
  auto image = renderer->renderImage(one, 32, 24);
  ASSERT_TRUE(image) << image.error().message;
}

// The accuracy rows, small: 2, 4 and 6 Gaussians without and with the optimisations, each
// diffused map within the reference's own signal (relative RMS below 1) at the asked size; no
// speed-up table, so no speed-up CSV and no chart even when asked; Jimenez's Table 1 in the JSON.
TEST(TsdBenchGl, AccuracyRowsAndTheirReport) {
  auto organ = loadTsdOrgan(testdata::dataOrgan("liver").mesh, 1.0f);
  ASSERT_TRUE(organ) << organ.error().message;
  auto context = context::createHeadlessContext({}, {.backend = "", .log = false});
  ASSERT_TRUE(context) << "no headless context (EGL, then OSMesa): " << context.error().message;
  auto renderer = render::Renderer::create((*context)->procAddressFunction());
  ASSERT_TRUE(renderer) << renderer.error().message;
  TsdBenchConfig config;
  config.width = 64, config.height = 40;  // the optimised map is sized from the viewport
  config.mapSize = 64;
  config.repeats = 1;
  config.accuracyOnly = config.chart = true;
  config.skinTable = std::filesystem::path(TISSUE_TEST_SHARED_DIR) / "reference" / "deon_skin_gaussians.tsv";
  auto bench = runTsdBench(*renderer, *organ, config);
  ASSERT_TRUE(bench) << bench.error().message;
  EXPECT_TRUE(bench->speedup.empty());
  ASSERT_EQ(bench->accuracy.size(), 6u);
  for (std::size_t i = 0; i < 6; ++i) {
    const TsdAccuracyRow& a = bench->accuracy[i];
    EXPECT_EQ(a.gaussians, 2 + 2 * int(i / 2));
    EXPECT_EQ(a.optimised, i % 2 == 1);
    EXPECT_GT(a.ms, 0.0);
    EXPECT_TRUE(std::isfinite(a.error.rms) && a.error.rms > 0.0);
    EXPECT_LT(a.error.relative, 1.0);
    if (!a.optimised) {
      EXPECT_EQ(a.mapSize, config.mapSize);  // unoptimised: the full map
    }
  }
  EXPECT_GT(bench->referenceTexels, 100u);
  const Report& report = bench->output.report;
  EXPECT_EQ(testdata::lineCount(testdata::fileText(report, "tsd_bench_accuracy.csv")), 7u);
  EXPECT_TRUE(testdata::fileText(report, "tsd_bench_speedup.csv").empty());
  EXPECT_TRUE(report.charts.empty());
  EXPECT_NE(bench->output.json.find("\"interior_relative_rms\""), std::string::npos);
  EXPECT_NE(bench->output.json.find("2.77"), std::string::npos);  // Table 1, 16 heads at 100
  config.gaussians = 3;
  EXPECT_FALSE(runTsdBench(*renderer, *organ, config));
}

}  // namespace
}  // namespace tissue::studies
