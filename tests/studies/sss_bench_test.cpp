// The SSS bench (studies/sss_bench.h) on a small frame of the data liver: the set-up puts the
// organ in the scene with its material's truth profile; the texture-space rows refuse to run
// before the reference exists; every separable and texture-space row is timed and measured
// (finite, non-negative errors, relative below the whole signal), and skips say why; the
// demo's last-frame reference error is measured the same way.
#include "tissue/studies/sss_bench.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

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
  std::size_t rows = 0;
  for (const SssBenchMethod& method : kSssBenchMethods) {
    auto r = method.rows(ctx, skipped);
    ASSERT_TRUE(r) << method.name << ": " << r.error().message;
    for (const SssBenchRow& row : *r) {
      EXPECT_EQ(row.method, method.name);
      EXPECT_GT(row.ms, 0.0);
      EXPECT_TRUE(std::isfinite(row.imageRms) && row.imageRms >= 0.0) << row.setting;
      EXPECT_LT(row.relativeRms, 1.0) << row.setting;
    }
    rows += r->size();
  }
  EXPECT_EQ(ctx.reference.size(), std::size_t(ctx.width * ctx.height));
  // 24 single-rank and 8 rank-R separable settings, 3 texture-space ones: each a row or a skip.
  EXPECT_EQ(rows + skipped.size(), 35u);
  for (const SssBenchSkip& s : skipped)
    EXPECT_FALSE(s.reason.empty()) << s.setting;
}

}  // namespace
}  // namespace tissue::studies
