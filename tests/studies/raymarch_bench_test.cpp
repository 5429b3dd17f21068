// The ray-march bench's measurements (studies/raymarch_bench.h) on a small frame of the data
// liver: the table's settings, one timing per setting, the covered pixels' radiance (uncovered
// ones masked out), and the adaptive march's mean samples within its own bounds.
#include "tissue/studies/raymarch_bench.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "data_organ.h"
#include "tissue/context/headless_context.h"

namespace tissue::studies {
namespace {

TEST(RayMarchBench, TheTableSettings) {
  render::RayMarchSettings adaptive;
  adaptive.minSamples = 3;
  const auto fixed = rayMarchBenchSetting(25, adaptive);
  EXPECT_EQ(fixed.samples, 25);
  EXPECT_FALSE(fixed.adaptive);
  EXPECT_EQ(fixed.radianceScale, kRayMarchRadianceScale);
  const auto chosen = rayMarchBenchSetting(0, adaptive);
  EXPECT_TRUE(chosen.adaptive);
  EXPECT_EQ(chosen.minSamples, 3);
}

TEST(RayMarchBenchGl, TimesEverySettingAndCountsSamples) {
  const std::filesystem::path data = TISSUE_TEST_DATA_DIR;
  scene::OrganSource source;
  source.mesh = data / "meshes" / "liver.obj";
  source.material = data / "materials" / "liver.json";
  source.materialOptions.textureRoots = {TISSUE_TEST_GENERATED_DATA_DIR, data};
  const int w = 32, h = 24;
  auto scene = loadRayMarchScene(source, float(w) / float(h), false);
  ASSERT_TRUE(scene) << scene.error().message;
  auto context = context::createHeadlessContext({}, {.backend = "", .log = false});
  ASSERT_TRUE(context) << "no headless context (EGL, then OSMesa): " << context.error().message;
  render::RendererSettings settings;
  settings.finishPasses = true;
  auto gpu = makeRayMarchRender(*scene, (*context)->procAddressFunction(), settings);
  ASSERT_TRUE(gpu) << gpu.error().message;
  const render::RayMarchSettings adaptive;
  auto timings = timeRayMarchSettings(*gpu, adaptive, w, h, 1);
  ASSERT_TRUE(timings) << timings.error().message;
  ASSERT_EQ(timings->size(), std::size(kRayMarchBenchSettings));
  for (const RayMarchTiming& t : *timings)
    EXPECT_GT(t.ms, 0.0);
  // The last frame is the adaptive one: the corner is uncovered, the organ covered.
  const std::vector<std::uint8_t> all(std::size_t(w * h), 1);
  auto radiance = readRayMarchRadiance(gpu->renderer, all);
  ASSERT_TRUE(radiance) << radiance.error().message;
  ASSERT_EQ(radiance->radiance.size(), all.size());
  EXPECT_EQ(radiance->mask[0], 0);
  std::size_t covered = 0;
  for (auto m : radiance->mask)
    covered += m;
  EXPECT_GT(covered, all.size() / 10);
  auto samples = meanSamples(*gpu, w, h, radiance->mask);
  ASSERT_TRUE(samples) << samples.error().message;
  EXPECT_GE(samples->mean, double(adaptive.minSamples));
  EXPECT_LE(samples->mean, double(adaptive.maxSamples));
  EXPECT_EQ(samples->image.width, w);
  EXPECT_FALSE(gpu->settings().showSamples);  // restored
}

// The whole bench, small: one row per setting in table order, more samples nearer the
// reference (10 against 100), the adaptive mean within its bounds, the method near its CPU twin,
// and the report's table, JSON keys, images and chart.
TEST(RayMarchBenchGl, TheBenchAndItsReport) {
  auto context = context::createHeadlessContext({}, {.backend = "", .log = false});
  ASSERT_TRUE(context) << "no headless context (EGL, then OSMesa): " << context.error().message;
  RayMarchBenchConfig config;
  config.width = 32, config.height = 24;
  config.referenceSamples = 40;
  config.repeats = 1;
  config.images = config.chart = true;
  auto bench = runRayMarchBench((*context)->procAddressFunction(), {}, testdata::dataOrgan("liver"), config);
  ASSERT_TRUE(bench) << bench.error().message;
  const std::size_t n = std::size(kRayMarchBenchSettings);
  ASSERT_EQ(bench->rows.size(), n);
  EXPECT_EQ(bench->rows[0].setting, "10");
  EXPECT_EQ(bench->rows[3].setting, "100");
  EXPECT_EQ(bench->rows[4].setting, "adaptive");
  for (const RayMarchBenchRow& r : bench->rows) {
    EXPECT_GT(r.timing.ms, 0.0) << r.setting;
    EXPECT_TRUE(std::isfinite(r.imageRms) && r.imageRms > 0.0 && r.imageRms < 1.0) << r.setting;
  }
  EXPECT_GT(bench->rows[0].imageRms, bench->rows[3].imageRms);
  EXPECT_GE(bench->rows[4].samples, double(config.adaptive.minSamples));
  EXPECT_LE(bench->rows[4].samples, double(config.adaptive.maxSamples));
  EXPECT_GT(bench->adaptiveMsRatioVs100, 0.0);
  EXPECT_LT(bench->gpuVsCpuModel50, 0.1);
  EXPECT_GT(bench->referenceMs, 0.0);
  const Report& report = bench->output.report;
  EXPECT_EQ(testdata::lineCount(testdata::fileText(report, "raymarch_bench.csv")), n + 1);
  for (const char* key : {"\"plane_approximation_rms\"", "\"gpu_vs_cpu_model_radiance_rel_rms_50\"",
                          "\"ms_ratio_vs_100\"", "\"cpu_ms\""})
    EXPECT_NE(bench->output.json.find(key), std::string::npos) << key;
  EXPECT_EQ(report.images.size(), n + 5);  // each setting, the samples, the two references, the twins
  ASSERT_EQ(report.charts.size(), 1u);
  EXPECT_EQ(report.charts[0].series[0].x.size(), n - 1);
}

}  // namespace
}  // namespace tissue::studies
