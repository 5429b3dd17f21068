// The quality table from an atlas's JSON: errors per view class, cost priors from the frames'
// pixel counts, the wrap fallback, and the committed default.
#include "tissue/quality/quality_table.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

namespace tissue::quality {
namespace {

// Two methods on three frames; ms = overhead + fixed + per-pixel x pixels exactly.
const char* kAtlas = R"({
  "truth": {"frames": [{"frame": "rest", "organ_pixels": 1000}, {"frame": "poked", "organ_pixels": 1000},
                       {"frame": "close-up", "organ_pixels": 5000}]},
  "results": [
    {"method": "lit", "setting": "default", "frame": "rest", "ms": 3.0, "rel_rms": 0.5, "rel_rms_debiased": 0.4,
     "squared_vs_best_stderr": 0.003},
    {"method": "lit", "setting": "default", "frame": "poked", "ms": 3.0, "rel_rms": 0.6, "rel_rms_debiased": 0.45,
     "squared_vs_best_stderr": 0.002},
    {"method": "lit", "setting": "default", "frame": "close-up", "ms": 7.0, "rel_rms": 0.7, "rel_rms_debiased": 0.6,
     "squared_vs_best_stderr": 0.004},
    {"method": "ray-march", "setting": "50", "frame": "rest", "ms": 14.0, "rel_rms": 0.2},
    {"method": "ray-march", "setting": "50", "frame": "close-up", "ms": 54.0, "rel_rms": 0.3},
    {"method": "ray-march", "setting": "50", "frame": "backlit", "ms": 9.0, "rel_rms": 0.9}
  ]})";

// An atlas of the rest (1000 px) and close-up (5000 px) frames: plain lit at 2 ms + 1 ms per
// 1000 px (the frame's overhead is its intercept), then `rows` (JSON result objects).
std::string twoFrameAtlas(const std::string& rows) {
  return R"({"truth": {"frames": [{"frame": "rest", "organ_pixels": 1000},
                                  {"frame": "close-up", "organ_pixels": 5000}]},
             "results": [
      {"method": "lit", "setting": "default", "frame": "rest", "ms": 3.0, "rel_rms": 0.5},
      {"method": "lit", "setting": "default", "frame": "close-up", "ms": 7.0, "rel_rms": 0.7},
)" + rows +
         "]}";
}

TEST(QualityTable, ReadsErrorsPerViewClassAndCostPriors) {
  auto table = qualityTableFromAtlasJson(kAtlas);
  ASSERT_TRUE(table) << table.error().message;
  const int lit = table->find("lit", "default"), march = table->find("ray-march", "50");
  ASSERT_GE(lit, 0);
  ASSERT_GE(march, 0);
  const QualityOption& l = table->options[std::size_t(lit)];
  const QualityOption& m = table->options[std::size_t(march)];
  EXPECT_DOUBLE_EQ(l.relRms[std::size_t(ViewClass::Rest)], 0.4);  // the debiased value
  EXPECT_DOUBLE_EQ(l.relRms[std::size_t(ViewClass::CloseUp)], 0.6);
  // Grazing is missing: the mean of the others.
  EXPECT_NEAR(l.relRms[std::size_t(ViewClass::Grazing)], (0.4 + 0.45 + 0.6) / 3.0, 1e-12);
  EXPECT_DOUBLE_EQ(m.relRms[std::size_t(ViewClass::Rest)], 0.2);
  // How well the truth resolved each error: the paired difference's standard error, the mean of
  // the others where a frame is missing, 0 where the atlas gives none.
  EXPECT_DOUBLE_EQ(l.squaredStderr[std::size_t(ViewClass::Rest)], 0.003);
  EXPECT_DOUBLE_EQ(l.squaredStderr[std::size_t(ViewClass::CloseUp)], 0.004);
  EXPECT_NEAR(l.squaredStderr[std::size_t(ViewClass::Grazing)], 0.003, 1e-12);
  EXPECT_DOUBLE_EQ(m.squaredStderr[std::size_t(ViewClass::Rest)], 0.0);
  // lit: 2 ms + 1 ms per 1000 px; the lit intercept is the frame's overhead.
  EXPECT_NEAR(table->frameOverheadMs, 2.0, 1e-9);
  EXPECT_NEAR(l.fixedMs, 0.0, 1e-9);
  EXPECT_NEAR(l.msPerPx, 1e-3, 1e-12);
  EXPECT_NEAR(m.fixedMs + table->frameOverheadMs + m.msPerPx * 3000.0, 34.0, 1.0);
  EXPECT_GT(m.msPerPx, 5.0 * l.msPerPx);
  // The wrap fallback is added with lit's figures.
  const int wrap = table->find("lit", kWrapSetting);
  ASSERT_GE(wrap, 0);
  EXPECT_EQ(table->options[std::size_t(wrap)].relRms, l.relRms);
}

TEST(QualityTable, ReadsEachFramesViewAngleAndFillsTheObliqueAndLowFramesBetweenRestAndGrazing) {
  // An atlas with the frames' angles (truth.frames[].view_angle_deg), and without the oblique and
  // low frames.
  const char* atlas = R"({
    "truth": {"frames": [{"frame": "rest", "organ_pixels": 1000, "view_angle_deg": 24.7},
                         {"frame": "grazing", "organ_pixels": 600, "view_angle_deg": 79.8},
                         {"frame": "backlit", "organ_pixels": 2000, "view_angle_deg": 24.2}]},
    "results": [
      {"method": "lit", "setting": "default", "frame": "rest", "ms": 3.0, "rel_rms": 0.2,
       "squared_vs_best_stderr": 0.001},
      {"method": "lit", "setting": "default", "frame": "grazing", "ms": 2.6, "rel_rms": 0.4,
       "squared_vs_best_stderr": 0.003}]})";
  auto table = qualityTableFromAtlasJson(atlas);
  ASSERT_TRUE(table) << table.error().message;
  EXPECT_DOUBLE_EQ(table->viewAngleDeg[std::size_t(ViewClass::Rest)], 24.7);
  EXPECT_DOUBLE_EQ(table->viewAngleDeg[std::size_t(ViewClass::Grazing)], 79.8);
  EXPECT_TRUE(std::isnan(table->viewAngleDeg[std::size_t(ViewClass::Oblique)]));  // no such frame
  EXPECT_TRUE(std::isnan(table->viewAngleDeg[std::size_t(ViewClass::CloseUp)]));  // no such frame
  const QualityOption& l = table->options[std::size_t(table->find("lit", "default"))];
  EXPECT_NEAR(l.relRms[std::size_t(ViewClass::Oblique)], 0.3, 1e-12);
  EXPECT_NEAR(l.squaredStderr[std::size_t(ViewClass::Oblique)], 0.002, 1e-12);
  EXPECT_TRUE(std::isnan(table->viewAngleDeg[std::size_t(ViewClass::Low)]));
  EXPECT_NEAR(l.relRms[std::size_t(ViewClass::Low)], 0.35, 1e-12);  // between oblique and grazing
  EXPECT_NEAR(l.squaredStderr[std::size_t(ViewClass::Low)], 0.0025, 1e-12);
  // The other missing classes keep the mean of the frames there are.
  EXPECT_NEAR(l.relRms[std::size_t(ViewClass::CloseUp)], 0.3, 1e-12);
  // An atlas without angles: none known.
  auto plain = qualityTableFromAtlasJson(kAtlas);
  ASSERT_TRUE(plain);
  for (double a : plain->viewAngleDeg)
    EXPECT_TRUE(std::isnan(a));
}

// The far frame is no view class: its errors and pixels are the footprint axis beside the low
// frame's (controller.h, expectedSquaredError); only where every option has it.
TEST(QualityTable, ReadsTheFarFrameAsTheFootprintAxis) {
  const std::string rows = R"(
      {"method": "lit", "setting": "default", "frame": "low", "ms": 3.0, "rel_rms": 0.3},
      {"method": "lit", "setting": "default", "frame": "far", "ms": 2.2, "rel_rms": 0.5,
       "squared_vs_best_stderr": 0.004},
      {"method": "ray-march", "setting": "10", "frame": "low", "ms": 5.0, "rel_rms": 0.31},
      {"method": "ray-march", "setting": "10", "frame": "far", "ms": 2.5, "rel_rms": 0.4})";
  const std::string frames = R"({"truth": {"frames": [{"frame": "low", "organ_pixels": 750},
                                                      {"frame": "far", "organ_pixels": 110}]},
                                 "results": [)";
  auto table = qualityTableFromAtlasJson(frames + rows + "]}");
  ASSERT_TRUE(table) << table.error().message;
  EXPECT_DOUBLE_EQ(table->farFramePx, 110.0);
  EXPECT_DOUBLE_EQ(table->framePx[std::size_t(ViewClass::Low)], 750.0);
  const QualityOption& l = table->options[std::size_t(table->find("lit", "default"))];
  EXPECT_DOUBLE_EQ(l.farRelRms, 0.5);
  EXPECT_DOUBLE_EQ(l.farSquaredStderr, 0.004);
  EXPECT_DOUBLE_EQ(l.relRms[std::size_t(ViewClass::Low)], 0.3);
  // The far frame's error is in no class's mean (the classes the atlas lacks).
  EXPECT_DOUBLE_EQ(l.relRms[std::size_t(ViewClass::Rest)], 0.3);
  EXPECT_DOUBLE_EQ(table->options[std::size_t(table->find("lit", kWrapSetting))].farRelRms, 0.5);
  // One option without the far frame: no footprint axis.
  auto partial = qualityTableFromAtlasJson(
      frames + rows.substr(0, rows.rfind("{")) +
      R"({"method": "ray-march", "setting": "25", "frame": "low", "ms": 6.0, "rel_rms": 0.31}]})");
  ASSERT_TRUE(partial) << partial.error().message;
  EXPECT_TRUE(std::isnan(partial->farFramePx));
}

TEST(QualityTable, ReadsTheAtlasRowOfTheWrapTermAsItsOwn) {
  // An atlas that scored lit with the wrap term (tissue-sim atlas's "lit wrap" row): the option
  // takes that row's errors, not plain lit's. Its cost is the lit class's (costClassKey: one
  // shader, one more uniform): plain lit's line, whose intercept is the frame's overhead.
  const std::string atlas = twoFrameAtlas(R"(
      {"method": "lit", "setting": "wrap", "frame": "rest", "ms": 3.5, "rel_rms": 0.3},
      {"method": "lit", "setting": "wrap", "frame": "close-up", "ms": 5.5, "rel_rms": 0.35})");
  auto table = qualityTableFromAtlasJson(atlas);
  ASSERT_TRUE(table) << table.error().message;
  EXPECT_EQ(table->options.size(), 2u);  // nothing added: the atlas has the row
  const int wrap = table->find("lit", kWrapSetting), lit = table->find("lit", "default");
  ASSERT_GE(wrap, 0);
  ASSERT_GE(lit, 0);
  const QualityOption& w = table->options[std::size_t(wrap)];
  const QualityOption& l = table->options[std::size_t(lit)];
  EXPECT_DOUBLE_EQ(w.relRms[std::size_t(ViewClass::Rest)], 0.3);
  EXPECT_DOUBLE_EQ(w.relRms[std::size_t(ViewClass::CloseUp)], 0.35);
  EXPECT_EQ(w.costClass, l.costClass);
  EXPECT_NEAR(table->frameOverheadMs, 2.0, 1e-9);  // lit default: 2 ms + 1 ms per 1000 px
  EXPECT_NEAR(w.fixedMs, 0.0, 1e-9);               // and the wrap row with it (its own: 0.5 ms per 1000 px)
  EXPECT_NEAR(w.msPerPx, 1e-3, 1e-12);
  EXPECT_DOUBLE_EQ(l.msPerPx, w.msPerPx);
}

TEST(QualityTable, OptionsOfOneWorkShareOneCostLine) {
  // The separable kernel models of one tap count run one shader with other weights: one cost
  // class, one line fitted to all their rows (the d'Eon row's lone fast frame is noise, not a
  // cheaper kernel). Another tap count is another class.
  EXPECT_EQ(costClassKey("separable", "deon-11"), "separable-11");
  EXPECT_EQ(costClassKey("separable", "preintegrated-11"), "separable-11");
  EXPECT_EQ(costClassKey("lit", "wrap"), costClassKey("lit", "default"));
  EXPECT_NE(costClassKey("ray-march", "adaptive-100"), costClassKey("ray-march", "100"));
  EXPECT_NE(costClassKey("texture-space", "6g-opt"), costClassKey("texture-space", "6g-plain"));
  const std::string atlas = twoFrameAtlas(R"(
      {"method": "separable", "setting": "deon-11", "frame": "rest", "ms": 3.5, "rel_rms": 0.45},
      {"method": "separable", "setting": "deon-11", "frame": "close-up", "ms": 10.0, "rel_rms": 0.6},
      {"method": "separable", "setting": "preintegrated-11", "frame": "rest", "ms": 4.5, "rel_rms": 0.4},
      {"method": "separable", "setting": "preintegrated-11", "frame": "close-up", "ms": 12.0, "rel_rms": 0.5},
      {"method": "separable", "setting": "preintegrated-25", "frame": "rest", "ms": 6.0, "rel_rms": 0.38},
      {"method": "separable", "setting": "preintegrated-25", "frame": "close-up", "ms": 16.0, "rel_rms": 0.48})");
  auto table = qualityTableFromAtlasJson(atlas);
  ASSERT_TRUE(table) << table.error().message;
  const QualityOption& d = table->options[std::size_t(table->find("separable", "deon-11"))];
  const QualityOption& p = table->options[std::size_t(table->find("separable", "preintegrated-11"))];
  const QualityOption& q = table->options[std::size_t(table->find("separable", "preintegrated-25"))];
  EXPECT_EQ(d.costClass, p.costClass);
  EXPECT_NE(d.costClass, q.costClass);
  ASSERT_GE(d.costClass, 0);
  EXPECT_EQ(table->costClasses[std::size_t(d.costClass)], "separable-11");
  // Both rows' mean line: 4 ms at 1000 px, 11 ms at 5000 px (2.25 ms + 1.75e-3 ms/px, less lit's
  // intercept 2 ms); each row alone would be 1.875 + 1.625e-3 and 2.625 + 1.875e-3.
  EXPECT_DOUBLE_EQ(d.fixedMs, p.fixedMs);
  EXPECT_DOUBLE_EQ(d.msPerPx, p.msPerPx);
  EXPECT_NEAR(d.fixedMs, 0.25, 1e-9);
  EXPECT_NEAR(d.msPerPx, 1.75e-3, 1e-12);
  EXPECT_NEAR(q.msPerPx, 2.5e-3, 1e-12);  // its own line
}

TEST(QualityTable, NoOptionIsPricedBelowPlainLit) {
  // The separable row's times fall with the pixels (timing noise): its own line would have a
  // negative slope and an intercept below lit's, 0 ms per object. It takes plain lit's line instead.
  const std::string atlas = twoFrameAtlas(R"(
      {"method": "separable", "setting": "svd-7", "frame": "rest", "ms": 1.8, "rel_rms": 0.3},
      {"method": "separable", "setting": "svd-7", "frame": "close-up", "ms": 1.5, "rel_rms": 0.35})");
  auto table = qualityTableFromAtlasJson(atlas);
  ASSERT_TRUE(table) << table.error().message;
  const QualityOption& w = table->options[std::size_t(table->find("separable", "svd-7"))];
  const QualityOption& l = table->options[std::size_t(table->find("lit", "default"))];
  EXPECT_DOUBLE_EQ(w.fixedMs, l.fixedMs);
  EXPECT_DOUBLE_EQ(w.msPerPx, l.msPerPx);
  EXPECT_GT(w.msPerPx, 0.0);
}

// Plain lit's own times fall with the pixels (timing noise): its per-pixel cost is the least one
// the atlas resolved (the ray march's 1 ms per 1000 px here), through lit's centroid, not 0.
TEST(QualityTable, AnUnresolvedLitSlopeTakesTheLeastResolvedOne) {
  const std::string atlas = R"({"truth": {"frames": [{"frame": "rest", "organ_pixels": 1000},
                                  {"frame": "close-up", "organ_pixels": 5000}]},
             "results": [
      {"method": "lit", "setting": "default", "frame": "rest", "ms": 7.0, "rel_rms": 0.5},
      {"method": "lit", "setting": "default", "frame": "close-up", "ms": 5.0, "rel_rms": 0.7},
      {"method": "ray-march", "setting": "10", "frame": "rest", "ms": 9.0, "rel_rms": 0.3},
      {"method": "ray-march", "setting": "10", "frame": "close-up", "ms": 13.0, "rel_rms": 0.3},
      {"method": "ray-march", "setting": "50", "frame": "rest", "ms": 10.0, "rel_rms": 0.3},
      {"method": "ray-march", "setting": "50", "frame": "close-up", "ms": 30.0, "rel_rms": 0.3}]})";
  auto table = qualityTableFromAtlasJson(atlas);
  ASSERT_TRUE(table) << table.error().message;
  const QualityOption& l = table->options[std::size_t(table->find("lit", "default"))];
  EXPECT_DOUBLE_EQ(l.msPerPx, 1e-3);
  EXPECT_DOUBLE_EQ(l.fixedMs, 0.0);
  EXPECT_NEAR(table->frameOverheadMs, 6.0 - 1e-3 * 3000.0, 1e-9);  // lit's centroid: 3000 px, 6 ms
}

TEST(QualityTable, RefusesAJsonWithoutResults) {
  auto table = qualityTableFromAtlasJson(R"({"truth": {}})");
  ASSERT_FALSE(table);
  EXPECT_NE(table.error().message.find("results"), std::string::npos);
  EXPECT_FALSE(qualityTableFromAtlasJson("{not json"));
}

TEST(QualityTable, CommittedDefaultHasEveryMethodAndPositiveCosts) {
  const QualityTable& t = defaultQualityTable();
  std::set<std::string> methods;
  double litMs = -1.0, dearestMs = 0.0;
  for (const QualityOption& o : t.options) {
    methods.insert(o.method);
    const double ms = o.fixedMs + o.msPerPx * 2000.0;
    EXPECT_TRUE(ms > 0.0 && ms < 1e4) << o.method << " " << o.setting;
    if (o.method == "lit" && o.setting == "default") litMs = ms;
    dearestMs = std::max(dearestMs, ms);
    for (double e : o.relRms)
      EXPECT_TRUE(e >= 0.0 && e < 10.0) << o.method << " " << o.setting;
  }
  EXPECT_EQ(methods, (std::set<std::string>{"lit", "separable", "texture-space", "ray-march", "parallax"}));
  EXPECT_GE(t.find("lit", kWrapSetting), 0);
  EXPECT_GT(dearestMs, litMs);              // the atlas's costs differ: some method costs more than lit
  for (const QualityOption& o : t.options)  // and none less (NoOptionIsPricedBelowPlainLit)
    EXPECT_GE(o.fixedMs + o.msPerPx * 2000.0, litMs) << o.method << " " << o.setting;
  // The angle frames: rest, oblique, low and grazing in that order of view angle (the
  // controller's error follows the angle between them); the close-up is the oblique view's.
  const double rest = t.viewAngleDeg[std::size_t(ViewClass::Rest)];
  const double oblique = t.viewAngleDeg[std::size_t(ViewClass::Oblique)];
  const double low = t.viewAngleDeg[std::size_t(ViewClass::Low)];
  const double grazing = t.viewAngleDeg[std::size_t(ViewClass::Grazing)];
  EXPECT_LT(rest, oblique);
  EXPECT_LT(oblique, low);
  EXPECT_LT(low, grazing);
  EXPECT_NEAR(t.viewAngleDeg[std::size_t(ViewClass::CloseUp)], oblique, 5.0);
  EXPECT_GT(grazing, 70.0);
}

}  // namespace
}  // namespace tissue::quality
