#pragma once
// Comparing rendered images with goldens under a tolerance, and writing actual/diff images.
#include <filesystem>
#include <string>

#include "tissue/core/image.h"

namespace tissue::test {

/// Per-pixel statistics of |actual - expected| over the RGB channels, in 8-bit levels.
struct ImageDiff {
  int maxDiff = 0;            ///< largest channel difference of any pixel
  double meanDiff = 0.0;      ///< mean channel difference over all pixels and channels
  double fractionOver = 0.0;  ///< fraction of pixels whose largest difference exceeds the tolerance
  Image8 diffImage;           ///< RGB, |difference| x 16, for eyes
};

/// Compares two RGBA/RGB images of equal size; `pixelTolerance` in 8-bit levels.
ImageDiff compareImages(const Image8& actual, const Image8& expected, int pixelTolerance);

/// The golden tolerance: at most 0.5 % of pixels differ by more than 3 levels, mean < 0.5 levels.
/// llvmpipe is deterministic; the slack is for real GPUs' rasterisation and precision differences.
struct GoldenTolerance {
  int pixelTolerance = 3;          ///< 8-bit levels
  double maxFractionOver = 0.005;  ///< 0..1
  double maxMeanDiff = 0.5;        ///< 8-bit levels
};

/// Compares `actual` with tests/golden/<name>.png. Always writes the actual image to
/// <test output>/golden/<name>.png (what scripts/accept-goldens.sh copies) and, on a
/// mismatch, <name>.diff.png. Returns an empty string on success, else what failed.
std::string checkGolden(const std::string& name, const Image8& actual, const GoldenTolerance& tolerance = {});

/// Mean channel difference (8-bit levels) between two equally sized images.
double meanDifference(const Image8& a, const Image8& b);

}  // namespace tissue::test
