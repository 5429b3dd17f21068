// Contact sheets: layout, the box filter's averages, and refusals.
#include <gtest/gtest.h>

#include <vector>

#include "tissue/core/image.h"

namespace tissue {
namespace {

Image8 filled(int w, int h, std::uint8_t value) {
  Image8 image(w, h, 1);
  std::fill(image.pixels.begin(), image.pixels.end(), value);
  return image;
}

TEST(TileImages, LaysOutRowsOfColumnsLeftToRightTopToBottom) {
  const std::vector<Image8> images = {filled(4, 2, 10), filled(4, 2, 20), filled(4, 2, 30)};
  auto tiled = tileImages(images, 2);
  ASSERT_TRUE(tiled) << tiled.error().message;
  EXPECT_EQ(tiled->width, 8);
  EXPECT_EQ(tiled->height, 4);  // two rows: the second holds one image and black
  EXPECT_EQ(tiled->at(0, 0)[0], 10);
  EXPECT_EQ(tiled->at(7, 1)[0], 20);
  EXPECT_EQ(tiled->at(3, 3)[0], 30);
  EXPECT_EQ(tiled->at(7, 3)[0], 0);
}

TEST(TileImages, ShrinkAveragesEachBlock) {
  Image8 checker(2, 2, 1);
  checker.pixels = {0, 100, 200, 100};  // mean 100
  auto tiled = tileImages(std::vector<Image8>{checker}, 1, 2);
  ASSERT_TRUE(tiled);
  ASSERT_EQ(tiled->width, 1);
  EXPECT_EQ(tiled->at(0, 0)[0], 100);
}

TEST(TileImages, RefusesNoneMismatchedAndBadCounts) {
  EXPECT_FALSE(tileImages({}, 2));
  auto mismatched = tileImages(std::vector<Image8>{filled(4, 2, 1), filled(2, 2, 1)}, 2);
  ASSERT_FALSE(mismatched);
  EXPECT_NE(mismatched.error().message.find("image 2"), std::string::npos);
  EXPECT_FALSE(tileImages(std::vector<Image8>{filled(4, 2, 1)}, 0));
  EXPECT_FALSE(tileImages(std::vector<Image8>{filled(4, 2, 1)}, 1, 8));
}

}  // namespace
}  // namespace tissue
