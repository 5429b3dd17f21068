// Properties of the layer textures: committed 128 x 128 ones and, when built, the 1024 x 1024 ones.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "tissue/core/image.h"

namespace tissue::datatest {
namespace {

namespace fs = std::filesystem;

/// Texture folders to check: the committed small set, and the build-time large set if present.
std::vector<fs::path> textureRoots() {
  std::vector<fs::path> roots = {fs::path(TISSUE_TEST_DATA_DIR) / "textures"};
  const fs::path generated = fs::path(TISSUE_TEST_GENERATED_DATA_DIR) / "textures";
  if (fs::exists(generated / "liver" / "subsurface.png")) roots.push_back(generated);
  return roots;
}

Image8 load(const fs::path& path, int channels) {
  auto image = readImage(path);
  EXPECT_TRUE(image.ok()) << (image.ok() ? "" : image.error().message);
  if (!image.ok()) return {};
  EXPECT_EQ(image->channels, channels) << path;
  EXPECT_EQ(image->width, image->height) << path;
  return *image;
}

TEST(DataTextures, SubsurfaceDepthsAreNonDecreasingAndLayered) {
  for (const fs::path& root : textureRoots()) {
    for (const char* mesh : {"patch", "liver", "tube"}) {
      const Image8 s = load(root / mesh / "subsurface.png", 4);
      ASSERT_FALSE(s.pixels.empty());
      std::size_t thinVessel = 0, thickVessel = 0, fat = 0;
      for (std::size_t i = 0; i < s.pixels.size(); i += 4) {
        const std::uint8_t* p = &s.pixels[i];
        ASSERT_LE(p[0], p[1]) << root << " " << mesh << " texel " << i / 4;
        ASSERT_LE(p[1], p[2]) << root << " " << mesh << " texel " << i / 4;
        ASSERT_LE(p[2], p[3]) << root << " " << mesh << " texel " << i / 4;
        ASSERT_GE(p[3], 180);  // the deep layer lies at a nearly uniform depth
        fat += p[0] + 20 < p[1];
        thinVessel += p[1] + 20 < p[2];
        thickVessel += p[2] + 20 < p[3];
      }
      // Every layer is present somewhere, none covers everything.
      const std::size_t n = s.pixels.size() / 4;
      for (std::size_t count : {fat, thinVessel, thickVessel}) {
        EXPECT_GT(count, n / 200) << root << " " << mesh;
        EXPECT_LT(count, n / 2) << root << " " << mesh;
      }
    }
  }
}

TEST(DataTextures, NormalMapsDecodeToUnitVectorsFacingOut) {
  for (const fs::path& root : textureRoots()) {
    for (const char* mesh : {"patch", "liver", "tube"}) {
      const Image8 n = load(root / mesh / "normal_map.png", 3);
      ASSERT_FALSE(n.pixels.empty());
      double tilt = 0.0;
      for (std::size_t i = 0; i < n.pixels.size(); i += 3) {
        const double x = n.pixels[i] / 127.5 - 1.0, y = n.pixels[i + 1] / 127.5 - 1.0,
                     z = n.pixels[i + 2] / 127.5 - 1.0;
        ASSERT_GT(z, 0.0);
        ASSERT_NEAR(std::sqrt(x * x + y * y + z * z), 1.0, 0.02) << root << " " << mesh;
        tilt += std::sqrt(x * x + y * y);
      }
      EXPECT_GT(tilt / double(n.pixels.size() / 3), 0.01) << "normal map is flat: " << root << " " << mesh;
    }
  }
}

TEST(DataTextures, ColourOpacityAndInnerTexturesHaveTheirFormats) {
  for (const fs::path& root : textureRoots()) {
    for (const char* mesh : {"patch", "liver", "tube"}) {
      const Image8 base = load(root / mesh / "base_color.png", 3);
      const Image8 inner = load(root / mesh / "inner_base.png", 3);
      const Image8 opacity = load(root / mesh / "opacity.png", 1);
      ASSERT_FALSE(base.pixels.empty() || inner.pixels.empty() || opacity.pixels.empty());
      // Tissue colours are red-dominant; the inner layer is darker than the outer one.
      double baseSum = 0.0, innerSum = 0.0;
      for (std::size_t i = 0; i < base.pixels.size(); i += 3) {
        ASSERT_GE(base.pixels[i], base.pixels[i + 2]);
        ASSERT_GE(inner.pixels[i], inner.pixels[i + 1]);
        baseSum += base.pixels[i] + base.pixels[i + 1] + base.pixels[i + 2];
        innerSum += inner.pixels[i] + inner.pixels[i + 1] + inner.pixels[i + 2];
      }
      EXPECT_LT(innerSum, baseSum) << root << " " << mesh;
      // Opacity dips over vessels but the outer layer is mostly opaque.
      const auto [lo, hi] = std::minmax_element(opacity.pixels.begin(), opacity.pixels.end());
      EXPECT_LT(*lo, 170) << root << " " << mesh;
      EXPECT_GT(*hi, 220) << root << " " << mesh;
    }
  }
}

}  // namespace
}  // namespace tissue::datatest
