// Error measures of separable kernels: the exact FFT convolution and the pre-integration identity.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "tissue/optics/kernel.h"
#include "tissue/optics/kernel_error.h"

namespace tissue::optics {
namespace {

const std::filesystem::path kReference = std::filesystem::path(TISSUE_TEST_SHARED_DIR) / "reference";

GroundTruthKernel skinTruth(int halfCells) {
  auto all = loadJensenMaterials(kReference / "jensen2001_materials.tsv");
  EXPECT_TRUE(all.ok());
  auto profile = groundTruthProfile(*findMaterial(*all, "Skin1"));
  EXPECT_TRUE(profile.ok());
  return *groundTruthKernel(*profile, halfCells);
}

TEST(KernelError, FftConvolutionEqualsTheDirectSumWithClampToEdge) {
  const auto truth = skinTruth(6);
  const auto signal = makeTestSignal(TestSignal::CircleAndSquares, 40);
  const auto fast = convolveExact(truth, signal);
  const int n = signal.size, h = truth.halfCells;
  for (int c = 0; c < kChannels; ++c) {
    double worst = 0;
    for (int y = 0; y < n; ++y) {
      for (int x = 0; x < n; ++x) {
        double sum = 0;  // (E * R)(x) = sum_d R(d) E(clamp(x - d))
        for (int dy = -h; dy <= h; ++dy)
          for (int dx = -h; dx <= h; ++dx)
            sum += truth.at(c, dy + h, dx + h) *
                   signal.value[static_cast<std::size_t>(std::clamp(y - dy, 0, n - 1) * n +
                                                         std::clamp(x - dx, 0, n - 1))];
        worst = std::max(
            worst,
            std::abs(sum - fast[static_cast<std::size_t>(c)].value[static_cast<std::size_t>(y * n + x)]));
      }
    }
    EXPECT_LT(worst, 1e-12) << "channel " << c;
  }
}

TEST(KernelError, PreIntegrationIsExactForAdditivelySeparableSignals) {
  // Freude eq. 5.14-5.16: for E = E1(x) + E2(y), E * A_p = E * R_d. With one tap per cell the
  // separable passes are the discrete convolution, so the difference is rounding only (the taps are
  // floats). SVD rank-1 on the same signal is not exact.
  const auto truth = skinTruth(40);
  KernelSettings full;
  full.taps = truth.size();
  const auto pre = *buildKernel(truth, KernelModel::PreIntegrated, full);
  const auto svd = *buildKernel(truth, KernelModel::Svd, full);
  const auto prerms = imageSpaceRms(truth, pre, TestSignal::AdditivelySeparable, 128);
  const auto svdrms = imageSpaceRms(truth, svd, TestSignal::AdditivelySeparable, 128);
  for (std::size_t c = 0; c < kChannels; ++c) {
    EXPECT_LT(prerms[c], 1e-6) << "channel " << c;
    EXPECT_GT(svdrms[c], 1e-3) << "channel " << c;
  }
  // A general signal is not exact for the pre-integrated kernel either.
  EXPECT_GT(imageSpaceRms(truth, pre, TestSignal::CircleAndSquares, 128)[0], 1e-4);
}

TEST(KernelError, TheGroundTruthItselfHasNoKernelSpaceError) {
  // Full-rank SVD reproduces R_d, so both measures vanish; rank 1 does not.
  const auto truth = skinTruth(10);
  KernelSettings s;
  s.rank = 8;
  s.taps = truth.size();
  const auto k8 = *buildKernel(truth, KernelModel::Svd, s);
  s.rank = 1;
  const auto k1 = *buildKernel(truth, KernelModel::Svd, s);
  EXPECT_LT(kernelSpaceRms(truth, k8)[0], 1e-3 * kernelSpaceRms(truth, k1)[0]);
}

TEST(KernelError, SignalsAreInTheUnitRange) {
  for (auto s : {TestSignal::VerticalEdge, TestSignal::CircleAndSquares, TestSignal::ShadedPatch,
                 TestSignal::AdditivelySeparable}) {
    const auto img = makeTestSignal(s, 64);
    double lo = 1, hi = 0;
    for (double v : img.value) {
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
    EXPECT_GE(lo, 0.0);
    EXPECT_LE(hi, 1.0);
    EXPECT_GT(hi - lo, 0.5);
  }
}

}  // namespace
}  // namespace tissue::optics
