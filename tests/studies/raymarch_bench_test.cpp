// The ray-march bench's measurements (studies/raymarch_bench.h) on a small frame of the data
// liver: the table's settings, one timing per setting, the covered pixels' radiance (uncovered
// ones masked out), and the adaptive march's mean samples within its own bounds.
#include "tissue/studies/raymarch_bench.h"

#include <gtest/gtest.h>

#include <filesystem>

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

}  // namespace
}  // namespace tissue::studies
