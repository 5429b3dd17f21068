// The quality table from an atlas's JSON: errors per view class, cost priors from the frames'
// pixel counts, the wrap fallback, and the committed default.
#include "tissue/quality/quality_table.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

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

TEST(QualityTable, ReadsTheAtlasRowOfTheWrapTermAsItsOwn) {
  // An atlas that scored lit with the wrap term (tissue-sim atlas's "lit wrap" row): the option
  // takes that row's errors and cost, not plain lit's, and the frame's overhead stays plain lit's
  // intercept.
  const char* atlas = R"({
    "truth": {"frames": [{"frame": "rest", "organ_pixels": 1000}, {"frame": "close-up", "organ_pixels": 5000}]},
    "results": [
      {"method": "lit", "setting": "wrap", "frame": "rest", "ms": 3.5, "rel_rms": 0.3},
      {"method": "lit", "setting": "wrap", "frame": "close-up", "ms": 7.5, "rel_rms": 0.35},
      {"method": "lit", "setting": "default", "frame": "rest", "ms": 3.0, "rel_rms": 0.5},
      {"method": "lit", "setting": "default", "frame": "close-up", "ms": 7.0, "rel_rms": 0.7}
    ]})";
  auto table = qualityTableFromAtlasJson(atlas);
  ASSERT_TRUE(table) << table.error().message;
  EXPECT_EQ(table->options.size(), 2u);  // nothing added: the atlas has the row
  const int wrap = table->find("lit", kWrapSetting), lit = table->find("lit", "default");
  ASSERT_GE(wrap, 0);
  ASSERT_GE(lit, 0);
  const QualityOption& w = table->options[std::size_t(wrap)];
  EXPECT_DOUBLE_EQ(w.relRms[std::size_t(ViewClass::Rest)], 0.3);
  EXPECT_DOUBLE_EQ(w.relRms[std::size_t(ViewClass::CloseUp)], 0.35);
  EXPECT_NEAR(table->frameOverheadMs, 2.0, 1e-9);  // lit default: 2 ms + 1 ms per 1000 px
  EXPECT_NEAR(w.fixedMs, 0.5, 1e-9);               // the wrap row: 2.5 ms + 1 ms per 1000 px
  EXPECT_NEAR(w.msPerPx, 1e-3, 1e-12);
}

TEST(QualityTable, NoOptionIsPricedBelowPlainLit) {
  // The wrap row's times fall with the pixels (timing noise): its own line would have a negative
  // slope and an intercept below lit's, 0 ms per object. It takes plain lit's line instead.
  const char* atlas = R"({
    "truth": {"frames": [{"frame": "rest", "organ_pixels": 1000}, {"frame": "close-up", "organ_pixels": 5000}]},
    "results": [
      {"method": "lit", "setting": "wrap", "frame": "rest", "ms": 1.8, "rel_rms": 0.3},
      {"method": "lit", "setting": "wrap", "frame": "close-up", "ms": 1.5, "rel_rms": 0.35},
      {"method": "lit", "setting": "default", "frame": "rest", "ms": 3.0, "rel_rms": 0.5},
      {"method": "lit", "setting": "default", "frame": "close-up", "ms": 7.0, "rel_rms": 0.7}
    ]})";
  auto table = qualityTableFromAtlasJson(atlas);
  ASSERT_TRUE(table) << table.error().message;
  const QualityOption& w = table->options[std::size_t(table->find("lit", kWrapSetting))];
  const QualityOption& l = table->options[std::size_t(table->find("lit", "default"))];
  EXPECT_DOUBLE_EQ(w.fixedMs, l.fixedMs);
  EXPECT_DOUBLE_EQ(w.msPerPx, l.msPerPx);
  EXPECT_GT(w.msPerPx, 0.0);
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
}

}  // namespace
}  // namespace tissue::quality
