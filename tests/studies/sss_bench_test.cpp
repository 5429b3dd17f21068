// The SSS bench (studies/sss_bench.h) on a small frame of the data liver: the set-up puts the
// organ in the scene with its material's truth profile; the texture-space rows refuse to run
// before the reference exists; every separable and texture-space row is timed and measured
// (finite, non-negative errors, relative below the whole signal), and skips say why; the
// demo's last-frame reference error is measured the same way.
#include "tissue/studies/sss_bench.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "data_organ.h"
#include "tissue/context/headless_context.h"
#include "tissue/materials/method_materials.h"

namespace tissue::studies {
namespace {

TEST(SssBenchGl, RowsAreMeasuredAgainstTheReference) {
  const std::filesystem::path data = TISSUE_TEST_DATA_DIR;
  scene::OrganSource source;
  source.mesh = data / "meshes" / "liver.obj";
  source.material = data / "materials" / "liver.json";
  source.materialOptions.textureRoots = {TISSUE_TEST_GENERATED_DATA_DIR, data};
  source.uvAtlasFallback = false;
  auto organ = scene::loadOrganAssets(source);
  ASSERT_TRUE(organ) << organ.error().message;
  auto context = context::createHeadlessContext({}, {.backend = "", .log = false});
  ASSERT_TRUE(context) << "no headless context (EGL, then OSMesa): " << context.error().message;
  auto renderer = render::Renderer::create((*context)->procAddressFunction());
  ASSERT_TRUE(renderer) << renderer.error().message;
  SssBenchContext ctx;
  ctx.renderer = &*renderer;
  ctx.width = 40, ctx.height = 30, ctx.frames = 1;
  ASSERT_TRUE(setUpSssBench(ctx, *organ));
  ASSERT_EQ(ctx.scene.objects.size(), 1u);
  EXPECT_TRUE(bool(ctx.scene.objects[0].baseColor));
  ASSERT_EQ(ctx.profiles.size(), 2u);
  EXPECT_EQ(ctx.material.name, organ->material.name);
  std::vector<SssBenchSkip> skipped;
  EXPECT_FALSE(textureSpaceBenchRows(ctx, skipped));  // no reference yet
  // The whole bench on the same renderer: every method's rows, each timed and measured.
  auto bench = runSssBench(*renderer, source,
                           {.width = 40, .height = 30, .frames = 1, .samples = 0, .glRenderer = "x"});
  ASSERT_TRUE(bench) << bench.error().message;
  std::size_t textureSpace = 0;
  for (const SssBenchRow& row : bench->rows) {
    EXPECT_GT(row.ms, 0.0);
    EXPECT_TRUE(std::isfinite(row.imageRms) && row.imageRms >= 0.0) << row.setting;
    EXPECT_LT(row.relativeRms, 1.0) << row.setting;
    textureSpace += row.method == "texture-space";
  }
  EXPECT_EQ(bench->rows.front().method, "separable");  // the methods in kSssBenchMethods' order
  EXPECT_EQ(bench->rows.back().method, "texture-space");
  // 24 single-rank and 8 rank-R separable settings, 3 texture-space ones: each a row or a skip.
  EXPECT_EQ(bench->rows.size() + bench->skipped.size(), 35u);
  EXPECT_EQ(textureSpace, 3u);
  for (const SssBenchSkip& s : bench->skipped)
    EXPECT_FALSE(s.reason.empty()) << s.setting;
  // The report: one table row per measured setting, the JSON as the command prints it.
  const Report& report = bench->output.report;
  EXPECT_EQ(testdata::lineCount(testdata::fileText(report, "sss_bench.csv")), bench->rows.size() + 1);
  EXPECT_EQ(testdata::fileText(report, "sss_bench.json"), bench->output.json + "\n");
  for (const char* key : {"\"method_ms\"", "\"relative_rms\"", "\"skipped\"", "\"gl_renderer\": \"x\""})
    EXPECT_NE(bench->output.json.find(key), std::string::npos) << key;
  source.material = "missing.json";
  auto missing = runSssBench(*renderer, source, {});
  ASSERT_FALSE(missing);
  EXPECT_NE(missing.error().message.find("material for"), std::string::npos) << missing.error().message;
}

}  // namespace
}  // namespace tissue::studies
