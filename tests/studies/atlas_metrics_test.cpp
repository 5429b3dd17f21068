// The atlas's scores (studies/atlas.h): relative RMS and PSNR of known images over a mask, the
// truth's own noise and the debiased error, the error image, and the Pareto front of a known set.
#include <gtest/gtest.h>

#include <cmath>

#include "tissue/scene/budget.h"
#include "tissue/studies/atlas.h"

namespace tissue::studies {
namespace {

TEST(AtlasMetrics, RelativeRmsAndPsnrOfKnownImages) {
  const std::vector<Float3> truth{{0.2f, 0.4f, 0.1f}, {1.0f, 0.5f, 0.25f}, {9.0f, 9.0f, 9.0f}};
  std::vector<Float3> method;
  for (const Float3& t : truth)
    method.push_back(1.1f * t);                   // 10% too bright everywhere
  const std::vector<std::uint8_t> mask{1, 1, 0};  // the third pixel is not organ
  method[2] = {0.0f, 0.0f, 0.0f};                 // and is ignored
  const AtlasScore s = scoreAgainstTruth(truth, method, mask);
  EXPECT_EQ(s.pixels, 2);
  EXPECT_NEAR(s.relRms, 0.1, 1e-6);
  EXPECT_NEAR(s.gain, 1.1, 1e-6);         // the level is 10% high
  EXPECT_NEAR(s.shapeRelRms, 0.0, 1e-6);  // and nothing else is wrong
  // PSNR by hand: the tone-mapped difference per channel.
  double mse = 0.0;
  for (int i = 0; i < 2; ++i) {
    const Float3 a = toneMap(truth[std::size_t(i)]), b = toneMap(method[std::size_t(i)]);
    mse += double((a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y) + (a.z - b.z) * (a.z - b.z));
  }
  EXPECT_NEAR(s.psnrDb, 10.0 * std::log10(6.0 / mse), 1e-6);
  // Identical images: no error, infinite PSNR; mismatched sizes: NaN.
  const AtlasScore same = scoreAgainstTruth(truth, truth, mask);
  EXPECT_EQ(same.relRms, 0.0);
  EXPECT_TRUE(std::isinf(same.psnrDb));
  EXPECT_TRUE(std::isnan(scoreAgainstTruth(truth, std::span<const Float3>(method).first(2), mask).relRms));
}

TEST(AtlasMetrics, ToneMapIsTheRenderersReinhardSrgb) {
  const Float3 c = toneMap({1.0f, 0.0f, 1000.0f});
  // x / (1 + x) = 0.5, then sRGB: 1.055 * 0.5^(1/2.4) - 0.055.
  EXPECT_NEAR(c.x, 1.055 * std::pow(0.5, 1.0 / 2.4) - 0.055, 1e-6);
  EXPECT_EQ(c.y, 0.0f);
  EXPECT_NEAR(c.z, 1.0f, 1e-3);
  EXPECT_NEAR(toneMap({0.5f, 0.5f, 0.5f}, 2.0f).x, c.x, 1e-6);  // exposure multiplies first
}

TEST(AtlasMetrics, TruthNoiseAndDebiasedError) {
  truth::TruthImage t;
  t.width = 2;
  t.height = 1;
  t.radiance = {{3.0f, 0.0f, 4.0f}, {100.0f, 100.0f, 100.0f}};
  t.stderrs = {{0.3f, 0.0f, 0.4f}, {50.0f, 50.0f, 50.0f}};
  t.covered = {1, 0};
  EXPECT_NEAR(truthNoiseRelRms(t), 0.1, 1e-6);  // |(0.3, 0, 0.4)| / |(3, 0, 4)|
  EXPECT_NEAR(debiasedError(0.5, 0.3), 0.4, 1e-12);
  EXPECT_EQ(debiasedError(0.1, 0.3), 0.0);
}

TEST(AtlasMetrics, ErrorImageMarksOrganPixelsByTheirError) {
  const std::vector<Float3> truth{{1, 1, 1}, {1, 1, 1}, {1, 1, 1}};
  const std::vector<Float3> method{{1, 1, 1}, {3, 3, 3}, {1, 1, 1}};
  const std::vector<std::uint8_t> mask{1, 1, 0};
  const Image8 img = errorImage(truth, method, mask, 3, 1, 0.5);
  EXPECT_EQ(img.pixels[0], 0);    // no error: black
  EXPECT_EQ(img.pixels[4], 255);  // 200% of the mean at scale 0.5: white
  EXPECT_EQ(img.pixels[6], 255);
  EXPECT_EQ(img.pixels[10], 40);  // off the organ: dark blue
}

TEST(AtlasMetrics, ParetoFrontOfAKnownSet) {
  //                          0    1    2    3    4    5    6
  const std::vector<double> ms{1.0, 2.0, 3.0, 0.5, 4.0, 2.0, NAN};
  const std::vector<double> er{0.5, 0.6, 0.2, 0.9, 0.1, 0.3, 0.01};
  // 3 (cheapest), 0, 5 (beats 1 at the same cost), 2, 4; 1 is dominated, 6 is not finite.
  EXPECT_EQ(paretoFront(ms, er), (std::vector<std::size_t>{3, 0, 5, 2, 4}));
  EXPECT_TRUE(paretoFront({}, {}).empty());
}

TEST(AtlasSettings, LitWithTheWrapTermHasItsOwnRow) {
  // The quality controller's small-footprint fallback is scored like every other setting, in
  // the quick atlas (the committed table's) and the full one.
  for (bool quick : {true, false}) {
    int wraps = 0, plain = 0;
    for (const AtlasSetting& s : atlasSettings(quick)) {
      if (s.method != render::ShadingMethod::Lit) continue;
      if (s.name == quality::kWrapSetting) {
        ++wraps;
        EXPECT_TRUE(s.choices.litWrapFromOptics);
      } else {
        ++plain;
        EXPECT_EQ(s.name, "default");
        EXPECT_EQ(s.choices.litWrap, 0.0f);
        EXPECT_FALSE(s.choices.litWrapFromOptics);
      }
    }
    EXPECT_EQ(wraps, 1) << (quick ? "quick" : "full");
    EXPECT_EQ(plain, 1) << (quick ? "quick" : "full");
  }
}

TEST(AtlasSettings, EveryRowNameReadsBackToItsChoices) {
  // The quality table names options by the atlas's rows; the scene turns a name back into the
  // choices (scene::choicesOfSetting): the same ones the atlas rendered.
  for (bool quick : {true, false})
    for (const AtlasSetting& s : atlasSettings(quick)) {
      const quality::QualityOption option{.method = std::string(render::shadingMethodName(s.method)),
                                          .setting = s.name,
                                          .relRms = {},
                                          .fixedMs = 0.0,
                                          .msPerPx = 0.0};
      auto c = scene::choicesOfSetting(option, {});
      ASSERT_TRUE(c) << option.method << " " << s.name << ": " << c.error().message;
      EXPECT_EQ(c->litWrap, s.choices.litWrap) << s.name;
      EXPECT_EQ(c->kernel, s.choices.kernel) << s.name;
      EXPECT_EQ(c->taps, s.choices.taps) << s.name;
      EXPECT_EQ(c->gaussians, s.choices.gaussians) << s.name;
      EXPECT_EQ(c->cull, s.choices.cull) << s.name;
      EXPECT_EQ(c->samples, s.choices.samples) << s.name;
      EXPECT_EQ(c->adaptive, s.choices.adaptive) << s.name;
    }
}

}  // namespace
}  // namespace tissue::studies
