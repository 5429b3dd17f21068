// The atlas's scores (studies/atlas.h): relative RMS and PSNR of known images over a mask, the
// truth's own noise and the debiased error, the difference of two errors against a noisy truth,
// the error image, and the Pareto front of a known set.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <span>
#include <vector>

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

// The difference of two renderings' squared errors against a noisy truth: over many draws of the
// truth's noise its mean is the noiseless difference (the noise's own n^2 cancels), and its spread
// is the standard error the function gives from the per-pixel sigma.
TEST(AtlasMetrics, ErrorDifferenceIsUnbiasedAndItsStderrIsTheSpreadOverNoiseDraws) {
  constexpr int kPixels = 400;
  std::vector<Float3> truth, sigma, a, b;
  std::vector<std::uint8_t> mask(kPixels, 1);
  for (int i = 0; i < kPixels; ++i) {
    const float t = 0.5f + 0.4f * std::sin(0.1f * float(i));
    truth.push_back({t, 0.5f * t, 0.25f * t});
    sigma.push_back({0.05f * t, 0.04f * t, 0.03f * t});
    const float bump = 0.02f * std::cos(0.37f * float(i));
    a.push_back({1.03f * t + bump, 0.5f * t, 0.25f * t - bump});
    b.push_back({0.98f * t, 0.51f * t, 0.25f * t});
  }
  double exactA = 0.0, exactB = 0.0, ref = 0.0;
  for (int i = 0; i < kPixels; ++i) {
    const Float3 t = truth[std::size_t(i)], pa = a[std::size_t(i)], pb = b[std::size_t(i)];
    exactA += double((pa.x - t.x) * (pa.x - t.x) + (pa.y - t.y) * (pa.y - t.y) + (pa.z - t.z) * (pa.z - t.z));
    exactB += double((pb.x - t.x) * (pb.x - t.x) + (pb.y - t.y) * (pb.y - t.y) + (pb.z - t.z) * (pb.z - t.z));
    ref += double(t.x * t.x + t.y * t.y + t.z * t.z);
  }
  const double exact = (exactA - exactB) / ref;
  std::mt19937 rng(11);
  std::normal_distribution<double> gauss;
  constexpr int kDraws = 4000;
  double sum = 0.0, sumSq = 0.0, stderrSum = 0.0;
  for (int k = 0; k < kDraws; ++k) {
    std::vector<Float3> noisy(truth);
    for (int i = 0; i < kPixels; ++i) {
      noisy[std::size_t(i)].x += float(gauss(rng) * double(sigma[std::size_t(i)].x));
      noisy[std::size_t(i)].y += float(gauss(rng) * double(sigma[std::size_t(i)].y));
      noisy[std::size_t(i)].z += float(gauss(rng) * double(sigma[std::size_t(i)].z));
    }
    const ErrorDifference d = errorDifference(noisy, sigma, a, b, mask);
    sum += d.squared;
    sumSq += d.squared * d.squared;
    stderrSum += d.squaredStderr;
  }
  const double mean = sum / kDraws, spread = std::sqrt(sumSq / kDraws - mean * mean);
  const double stderrMean = stderrSum / kDraws;
  EXPECT_NEAR(mean, exact, 4.0 * spread / std::sqrt(double(kDraws)) + 0.01 * std::abs(exact));
  EXPECT_NEAR(stderrMean, spread, 0.08 * spread);
  // A is the worse here, by more than two standard errors.
  const ErrorDifference clean = errorDifference(truth, sigma, a, b, mask);
  EXPECT_GT(clean.squared, 2.0 * clean.squaredStderr);
  EXPECT_TRUE(clean.bLower());
  EXPECT_FALSE(clean.aLower());
  // Swapped, the sign flips; sizes that differ give NaN.
  EXPECT_NEAR(errorDifference(truth, sigma, b, a, mask).squared, -clean.squared, 1e-12);
  EXPECT_TRUE(std::isnan(errorDifference(truth, sigma, a, std::span(b).first(10), mask).squared));
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
