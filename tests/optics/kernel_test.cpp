// Separable kernel models (Freude 2014, ch. 5; Jimenez's reference kernel; d'Eon's Gaussians).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "tissue/optics/kernel.h"
#include "tissue/optics/kernel_error.h"
#include "tissue/optics/kernel_gaussians.h"
#include "tissue/optics/kernel_jimenez.h"

namespace tissue::optics {
namespace {

const std::filesystem::path kReference = std::filesystem::path(TISSUE_TEST_SHARED_DIR) / "reference";

GroundTruthKernel truthOf(const std::string& name, int halfCells = 60) {
  auto all = loadJensenMaterials(kReference / "jensen2001_materials.tsv");
  EXPECT_TRUE(all.ok());
  auto material = findMaterial(*all, name);
  EXPECT_TRUE(material.ok());
  auto profile = groundTruthProfile(*material);
  EXPECT_TRUE(profile.ok());
  auto truth = groundTruthKernel(*profile, halfCells);
  EXPECT_TRUE(truth.ok());
  return *truth;
}

SeparableKernel build(const GroundTruthKernel& truth, KernelModel model, KernelSettings s = {}) {
  if (model == KernelModel::Manual) s.manual = *manualParameters(truth.name);
  auto k = buildKernel(truth, model, s);
  EXPECT_TRUE(k.ok()) << (k.ok() ? "" : k.error().message);
  return *k;
}

void expectTap(const KernelTap& t, double r, double g, double b, double offset) {
  EXPECT_NEAR(t.weight.x, r, 1e-5);
  EXPECT_NEAR(t.weight.y, g, 1e-5);
  EXPECT_NEAR(t.weight.z, b, 1e-5);
  EXPECT_NEAR(t.offsetMm, offset, 1e-6);
}

TEST(Jimenez, ReproducesThePublishedVectors) {
  const auto taps = jimenezTaps({}, 17);
  ASSERT_EQ(taps.size(), 17u);
  expectTap(taps[0], 0.536343, 0.624624, 0.748867, 0.0);
  const double offsets[] = {2, 1.53125, 1.125, 0.78125, 0.5, 0.28125, 0.125, 0.03125};
  const double w[][3] = {{0.00317394, 0.000134823, 3.77269e-05}, {0.0100386, 0.000914679, 0.000275702},
                         {0.0144609, 0.00317269, 0.00106399},    {0.0216301, 0.00794618, 0.00376991},
                         {0.0347317, 0.0151085, 0.00871983},     {0.0571056, 0.0287432, 0.0172844},
                         {0.0582416, 0.0659959, 0.0411329},      {0.0324462, 0.0656718, 0.0532821}};
  for (int i = 0; i < 8; ++i) {
    expectTap(taps[static_cast<std::size_t>(1 + i)], w[i][0], w[i][1], w[i][2], -offsets[i]);  // -2 .. -0.03
    expectTap(taps[static_cast<std::size_t>(16 - i)], w[i][0], w[i][1], w[i][2], offsets[i]);  // .. +2
  }
  const auto eleven = jimenezTaps({}, 11);
  expectTap(eleven[0], 0.560479, 0.669086, 0.784728, 0.0);
  const double o11[] = {2, 1.28, 0.72, 0.32, 0.08};
  const double w11[][3] = {{0.00471691, 0.000184771, 5.07566e-05},
                           {0.0192831, 0.00282018, 0.00084214},
                           {0.03639, 0.0130999, 0.00643685},
                           {0.0821904, 0.0358608, 0.0209261},
                           {0.0771802, 0.113491, 0.0793803}};
  for (int i = 0; i < 5; ++i) {
    expectTap(eleven[static_cast<std::size_t>(1 + i)], w11[i][0], w11[i][1], w11[i][2], -o11[i]);
    expectTap(eleven[static_cast<std::size_t>(10 - i)], w11[i][0], w11[i][1], w11[i][2], o11[i]);
  }
}

TEST(Kernels, EnergyConservingModelsKeepTheOneNorm) {
  // Every model but plain SVD claims ||A||_1 = ||R_d||_1 = 1: from the dense components and from
  // the taps the renderer gets. Plain SVD rank-1 must miss it (else the test could not fail).
  for (const char* name : {"Skin1", "Marble", "Ketchup"}) {
    const auto truth = truthOf(name);
    KernelSettings normalised;
    normalised.normalizeEnergy = true;
    KernelSettings three;
    three.rank = 3;
    const std::pair<KernelModel, KernelSettings> cases[] = {
        {KernelModel::Svd, normalised}, {KernelModel::PreIntegrated, {}}, {KernelModel::Guided, {}},
        {KernelModel::Manual, {}},      {KernelModel::Deon, three},       {KernelModel::Jimenez, {}}};
    for (const auto& [model, s] : cases) {
      const auto k = build(truth, model, s);
      const auto e = kernelEnergy(k);
      for (int c = 0; c < kChannels; ++c) {
        double dense = 0;
        for (const auto& comp : k.components) {
          double sum = 0;
          for (double v : comp.dense[static_cast<std::size_t>(c)])
            sum += v;
          dense += channelOf(comp.sign, c) * sum * sum;
        }
        EXPECT_NEAR(dense, 1.0, 1e-9) << name << " " << kernelModelName(model) << " channel " << c;
        EXPECT_NEAR(e[static_cast<std::size_t>(c)], 1.0, 2e-6) << name << " " << kernelModelName(model);
      }
    }
    const auto plain = kernelEnergy(build(truth, KernelModel::Svd));
    EXPECT_GT(std::abs(plain[0] - 1.0), 1e-3) << name;
  }
}

TEST(Kernels, SvdRankOneHasTheLowestKernelSpaceRmsOfTheRankOneModels) {
  for (const char* name : {"Apple", "Marble", "Ketchup", "Skin1", "Wholemilk"}) {
    const auto truth = truthOf(name);
    const auto svd = kernelSpaceRms(truth, build(truth, KernelModel::Svd));
    KernelSettings normalised;
    normalised.normalizeEnergy = true;
    KernelSettings k0;
    k0.guidedK = 0.0;
    for (const auto& other : {build(truth, KernelModel::Svd, normalised),
                              build(truth, KernelModel::PreIntegrated), build(truth, KernelModel::Guided),
                              build(truth, KernelModel::Guided, k0), build(truth, KernelModel::Manual),
                              build(truth, KernelModel::Deon), build(truth, KernelModel::Jimenez)}) {
      const auto rms = kernelSpaceRms(truth, other);
      for (int c = 0; c < kChannels; ++c)
        EXPECT_LE(svd[static_cast<std::size_t>(c)], rms[static_cast<std::size_t>(c)] * (1 + 1e-9))
            << name << " vs " << kernelModelName(other.model) << " channel " << c;
    }
  }
}

TEST(Kernels, GuidedWithKZeroImprovesOnItsPreIntegratedStartUnderTheConstraint) {
  // k = 0 minimises the plain squared error with sum(a) = 1; the pre-integrated start satisfies
  // the constraint, so the optimum is no worse, and no better than the unconstrained SVD.
  const auto truth = truthOf("Skin1");
  KernelSettings k0;
  k0.guidedK = 0.0;
  const auto guided = kernelSpaceRms(truth, build(truth, KernelModel::Guided, k0));
  const auto pre = kernelSpaceRms(truth, build(truth, KernelModel::PreIntegrated));
  const auto svd = kernelSpaceRms(truth, build(truth, KernelModel::Svd));
  for (std::size_t c = 0; c < kChannels; ++c) {
    EXPECT_LT(guided[c], 0.9 * pre[c]);
    EXPECT_GE(guided[c], svd[c]);
  }
}

TEST(Kernels, HigherSvdRankAndMoreGaussiansApproachTheGroundTruth) {
  const auto truth = truthOf("Skin1");
  double previousSvd = 1e9, previousDeon = 1e9;
  for (int rank = 1; rank <= 4; ++rank) {
    KernelSettings s;
    s.rank = rank;
    const auto svd = kernelSpaceRms(truth, build(truth, KernelModel::Svd, s));
    const auto deon = kernelSpaceRms(truth, build(truth, KernelModel::Deon, s));
    EXPECT_LT(svd[0], previousSvd);
    EXPECT_LT(deon[0], previousDeon * 1.0001);
    EXPECT_LE(svd[0], deon[0] * (1 + 1e-9));  // Eckart-Young: SVD is the best rank-R kernel
    previousSvd = svd[0];
    previousDeon = deon[0];
  }
}

TEST(Kernels, TapsKeepEachComponentsSumAndAreSymmetric) {
  const auto truth = truthOf("Marble");
  for (int taps : {3, 9, 17, 25}) {
    KernelSettings s;
    s.taps = taps;
    const auto k = build(truth, KernelModel::PreIntegrated, s);
    ASSERT_EQ(static_cast<int>(k.taps().size()), taps);
    EXPECT_EQ(k.taps()[0].offsetMm, 0.f);
    for (int c = 0; c < kChannels; ++c) {
      double sum = 0;
      for (const auto& t : k.taps())
        sum += channelOf(t.weight, c);
      EXPECT_NEAR(sum, 1.0, 1e-6);
    }
    for (int i = 1; i <= taps / 2; ++i) {  // centre, then -K..-1, then 1..K
      const auto& neg = k.taps()[static_cast<std::size_t>(i)];
      const auto& pos = k.taps()[static_cast<std::size_t>(taps - i)];
      EXPECT_NEAR(neg.offsetMm, -pos.offsetMm, 1e-6);
      EXPECT_NEAR(neg.weight.x, pos.weight.x, 1e-7);
      if (i > 1) {
        EXPECT_LT(k.taps()[static_cast<std::size_t>(i - 1)].offsetMm, neg.offsetMm);
      }
    }
  }
}

TEST(Kernels, BadSettingsAreClearErrors) {
  const auto truth = truthOf("Skin1", 20);
  KernelSettings even;
  even.taps = 16;
  auto k = buildKernel(truth, KernelModel::PreIntegrated, even);
  ASSERT_FALSE(k.ok());
  EXPECT_NE(k.error().message.find("odd"), std::string::npos);
  auto manual = buildKernel(truth, KernelModel::Manual, {});
  ASSERT_FALSE(manual.ok());
  EXPECT_NE(manual.error().message.find("Table A.1"), std::string::npos);
  EXPECT_FALSE(manualParameters("Potato").ok());
  EXPECT_NEAR(manualParameters("skin1")->sigmaFarMm[0], 11.5, 1e-12);  // 1.15 cm
  EXPECT_EQ(*parseKernelModel("PreIntegrated"), KernelModel::PreIntegrated);
  EXPECT_FALSE(parseKernelModel("gauss").ok());
}

TEST(Gaussians, FittedColumnsSumToOneAndMoreGaussiansFitBetter) {
  auto all = loadJensenMaterials(kReference / "jensen2001_materials.tsv");
  ASSERT_TRUE(all.ok());
  const auto profile = *groundTruthProfile(*findMaterial(*all, "Skin1"));
  double previous = 1e9;
  for (int count : {1, 2, 4, 6}) {
    auto fit = fitGaussians(profile, count);
    ASSERT_TRUE(fit.ok()) << fit.error().message;
    ASSERT_EQ(static_cast<int>(fit->varianceMm2.size()), count);
    for (std::size_t c = 0; c < kChannels; ++c) {
      double sum = 0;
      for (double w : fit->weights[c]) {
        EXPECT_GE(w, 0.0);
        sum += w;
      }
      EXPECT_NEAR(sum, 1.0, 1e-12);
    }
    for (int i = 1; i < count; ++i)
      EXPECT_GT(fit->varianceMm2[static_cast<std::size_t>(i)],
                fit->varianceMm2[static_cast<std::size_t>(i - 1)]);
    // The red channel's 2D error against the normalised profile, on a grid of radii.
    double err = 0;
    const double total = 0.435956;  // the dipole's total R_d of Skin1 red (dipole_test)
    for (double r = 0.05; r < 15.0; r += 0.05) {
      const double e = evaluateProfile(profile, 0, r) / total - gaussianSumProfile(*fit, 0, r);
      err += e * e * r;
    }
    EXPECT_LT(err, previous) << count << " Gaussians";
    previous = err;
  }
  EXPECT_FALSE(fitGaussians(profile, 0).ok());
}

}  // namespace
}  // namespace tissue::optics
