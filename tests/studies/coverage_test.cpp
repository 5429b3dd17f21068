// Silhouette handling: a partly covered pixel leaves the reference's surface points, and dividing
// by coverage undoes the blur's coverage weighting (a x colour / a = colour) and nothing else.
#include "tissue/studies/coverage.h"

#include <gtest/gtest.h>

namespace tissue::studies {
namespace {

render::FloatImage alphas(std::vector<float> a) {
  render::FloatImage image;
  image.width = int(a.size());
  image.height = 1;
  for (float x : a)
    image.pixels.push_back({0.0f, 0.0f, 0.0f, x});
  return image;
}

TEST(Coverage, PartlyCoveredPixelsAreNoSurface) {
  std::vector<Float4> diffuse(4, Float4{0.5f, 0.5f, 0.5f, 1.0f});  // w: object id 1
  dropPartialCoverage(diffuse, alphas({1.0f, 0.5f, 0.0f, 0.9995f}));
  EXPECT_EQ(diffuse[0].w, 1.0f);
  EXPECT_EQ(diffuse[1].w, 0.0f);
  EXPECT_EQ(diffuse[2].w, 0.0f);
  EXPECT_EQ(diffuse[3].w, 1.0f);
  EXPECT_EQ(diffuse[1].x, 0.5f);  // colour untouched
}

TEST(Coverage, RemovingTheWeightRestoresTheColour) {
  const Float4 colour{0.8f, 0.4f, 0.2f, 7.0f};
  std::vector<Float4> blurred;
  const std::vector<float> a = {1.0f, 0.25f, 0.0f};
  for (float w : a)
    blurred.push_back({w * colour.x, w * colour.y, w * colour.z, colour.w});
  removeCoverageWeight(blurred, alphas(a));
  EXPECT_FLOAT_EQ(blurred[0].x, 0.8f);
  EXPECT_FLOAT_EQ(blurred[1].x, 0.8f);
  EXPECT_FLOAT_EQ(blurred[1].y, 0.4f);
  EXPECT_FLOAT_EQ(blurred[1].z, 0.2f);
  EXPECT_EQ(blurred[1].w, 7.0f);
  EXPECT_EQ(blurred[2].x, 0.0f);  // uncovered: left alone (no division by zero)
}

}  // namespace
}  // namespace tissue::studies
