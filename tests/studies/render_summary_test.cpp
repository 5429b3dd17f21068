// One organ's render as tissue-sim render reports it (studies/render_summary.h): the data liver's
// assets, each method's settings from the choices and no other method's, the frame's timings.
#include "tissue/studies/render_summary.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>

#include "data_organ.h"

namespace tissue::studies {
namespace {

TEST(RenderSummary, EachMethodReportsItsOwnSettings) {
  auto assets = scene::loadOrganAssets(testdata::dataOrgan("liver"));
  ASSERT_TRUE(assets) << assets.error().message;
  scene::MethodChoices c;
  c.kernel = "deon";
  c.taps = 21;
  c.rank = 3;
  c.gaussians = 4;
  c.mapSize = 512;
  c.cull = false;
  c.samples = 40;
  c.adaptive = false;
  c.parallaxDepthMm = 2.5f;
  render::RenderTimings t;
  for (const auto& [name, ms] : {std::pair<const char*, double>{"lit", 1.0}, {"ray-march", 7.5}}) {
    render::PassTiming p;
    p.name = name;
    p.cpuMs = ms;
    t.passes.push_back(p);
  }
  t.totalCpuMs = 9.0;
  t.uploadCpuMs = 0.25;
  using render::ShadingMethod;
  const std::vector<std::pair<ShadingMethod, std::vector<std::string>>> own = {
      {ShadingMethod::Lit, {}},
      {ShadingMethod::Separable, {"kernel", "taps", "rank"}},
      {ShadingMethod::TextureSpace, {"gaussians", "map_size", "depth_size"}},
      {ShadingMethod::RayMarch, {"adaptive", "march_samples", "pass_ms"}},
      {ShadingMethod::Parallax, {"layer_depth_mm", "refractive_index", "lightmap_size", "blur_passes"}}};
  for (const auto& [method, keys] : own) {
    const auto j = nlohmann::json::parse(organRenderJson(*assets, method, c, t));
    EXPECT_EQ(j["method"], std::string(render::shadingMethodName(method)));
    EXPECT_EQ(j["triangles"], assets->mesh.triangles.size());
    EXPECT_EQ(j["material"], assets->material.file.string());
    EXPECT_DOUBLE_EQ(j["render_ms"].get<double>(), 9.0);
    EXPECT_DOUBLE_EQ(j["upload_ms"].get<double>(), 0.25);
    EXPECT_EQ(j["passes"].size(), 2u);
    for (const auto& key : keys)
      EXPECT_TRUE(j.contains(key)) << render::shadingMethodName(method) << " " << key;
    for (const auto& [other, otherKeys] : own) {
      if (other == method) continue;
      for (const auto& key : otherKeys) {
        if (std::find(keys.begin(), keys.end(), key) != keys.end()) continue;
        EXPECT_FALSE(j.contains(key)) << render::shadingMethodName(method) << " " << key;
      }
    }
  }
  const auto sep = nlohmann::json::parse(organRenderJson(*assets, ShadingMethod::Separable, c, t));
  EXPECT_EQ(sep["kernel"], "deon");
  EXPECT_EQ(sep["taps"], 21);
  EXPECT_EQ(sep["rank"], 3);
  const auto tsd = nlohmann::json::parse(organRenderJson(*assets, ShadingMethod::TextureSpace, c, t));
  EXPECT_EQ(tsd["gaussians"], 4);
  EXPECT_EQ(tsd["map_size"], 512);
  EXPECT_EQ(tsd["cull"], false);
  const auto rm = nlohmann::json::parse(organRenderJson(*assets, ShadingMethod::RayMarch, c, t));
  EXPECT_EQ(rm["march_samples"], 40);
  EXPECT_DOUBLE_EQ(rm["pass_ms"].get<double>(), 7.5);
  const auto px = nlohmann::json::parse(organRenderJson(*assets, ShadingMethod::Parallax, c, t));
  EXPECT_DOUBLE_EQ(px["layer_depth_mm"].get<double>(), 2.5);
  EXPECT_DOUBLE_EQ(px["refractive_index"].get<double>(),
                   double(assets->material.ior));  // no choice: the file's
  c.adaptive = true;
  const auto adaptive = nlohmann::json::parse(organRenderJson(*assets, ShadingMethod::RayMarch, c, t));
  EXPECT_EQ(adaptive["max_samples"], render::RayMarchSettings{}.maxSamples);
  EXPECT_FALSE(adaptive.contains("march_samples"));
}

}  // namespace
}  // namespace tissue::studies
