#include "image_compare.h"

#include <algorithm>
#include <cstdlib>

namespace tissue::test {

ImageDiff compareImages(const Image8& actual, const Image8& expected, int pixelTolerance) {
  ImageDiff d;
  d.diffImage = Image8(actual.width, actual.height, 3);
  const int channels = std::min({actual.channels, expected.channels, 3});
  std::size_t over = 0;
  double sum = 0.0;
  for (int y = 0; y < actual.height; ++y) {
    for (int x = 0; x < actual.width; ++x) {
      int pixelMax = 0;
      for (int c = 0; c < channels; ++c) {
        const int diff = std::abs(int(actual.at(x, y)[c]) - int(expected.at(x, y)[c]));
        pixelMax = std::max(pixelMax, diff);
        sum += diff;
        d.diffImage.at(x, y)[c] = static_cast<std::uint8_t>(std::min(255, diff * 16));
      }
      d.maxDiff = std::max(d.maxDiff, pixelMax);
      if (pixelMax > pixelTolerance) ++over;
    }
  }
  const double pixels = double(actual.width) * actual.height;
  d.meanDiff = pixels > 0 ? sum / (pixels * channels) : 0.0;
  d.fractionOver = pixels > 0 ? double(over) / pixels : 0.0;
  return d;
}

std::string checkGolden(const std::string& name, const Image8& actual, const GoldenTolerance& tolerance) {
  const std::filesystem::path outDir = std::filesystem::path(TISSUE_TEST_OUTPUT_DIR) / "golden";
  const std::filesystem::path goldenPath =
      std::filesystem::path(TISSUE_TEST_SOURCE_DIR) / "tests/golden" / (name + ".png");
  if (auto w = writePng(outDir / (name + ".png"), actual); !w)
    return "cannot write actual image: " + w.error().message;
  auto golden = readImage(goldenPath, 4);
  if (!golden) {
    return "no golden " + goldenPath.string() + " (" + golden.error().message +
           "); inspect the actual image in " + outDir.string() + " and run scripts/accept-goldens.sh";
  }
  if (golden->width != actual.width || golden->height != actual.height) {
    return "golden " + goldenPath.string() + " is " + std::to_string(golden->width) + "x" +
           std::to_string(golden->height) + ", actual " + std::to_string(actual.width) + "x" +
           std::to_string(actual.height);
  }
  const ImageDiff d = compareImages(actual, *golden, tolerance.pixelTolerance);
  if (d.fractionOver <= tolerance.maxFractionOver && d.meanDiff <= tolerance.maxMeanDiff) return {};
  (void)writePng(outDir / (name + ".diff.png"), d.diffImage);
  return name + " differs from its golden: " + std::to_string(d.fractionOver * 100.0) + " % of pixels over " +
         std::to_string(tolerance.pixelTolerance) + " levels (allowed " +
         std::to_string(tolerance.maxFractionOver * 100.0) + " %), mean " + std::to_string(d.meanDiff) +
         " levels (allowed " + std::to_string(tolerance.maxMeanDiff) + "), max " + std::to_string(d.maxDiff) +
         "; actual and diff images in " + outDir.string() + "; accept with scripts/accept-goldens.sh";
}

double meanDifference(const Image8& a, const Image8& b) {
  return compareImages(a, b, 255).meanDiff;
}

}  // namespace tissue::test
