// The truth_error view's arithmetic (studies/inspect_run.h): the pixel each vertex projects to
// under the renderer's pinhole, hidden vertices left without a value, and the per-pixel error
// whose mean square over the organ is the atlas's rel RMS squared.
#include "tissue/studies/inspect_run.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "tissue/studies/atlas.h"

namespace tissue::studies {
namespace {

constexpr int kW = 64, kH = 48;

/// Each pixel's value is its index, so a vertex's value names its pixel.
std::vector<float> indexImage() {
  std::vector<float> v(std::size_t(kW) * kH);
  for (std::size_t i = 0; i < v.size(); ++i)
    v[i] = float(i);
  return v;
}

float pixel(int col, int row) {
  return float(row * kW + col);
}

TEST(TruthErrorView, VerticesTakeThePixelTheyProjectToAndHiddenOnesNone) {
  const render::Camera camera{
      .eye = {0, 0, 100}, .target = {0, 0, 0}, .up = {0, 1, 0}, .verticalFovDeg = 40.0f};
  const float tanHalf = std::tan(20.0f * 3.14159265f / 180.0f), aspect = float(kW) / float(kH);
  // World mm at z = 0 of the centre of pixel (col, row): ndc (2 (col + 0.5) / W - 1, 1 - 2 (row + 0.5) / H).
  const auto at = [&](int col, int row, float z) {
    const float s = 100.0f - z;  // distance from the eye
    return Float3{(2.0f * (float(col) + 0.5f) / kW - 1.0f) * s * tanHalf * aspect,
                  (1.0f - 2.0f * (float(row) + 0.5f) / kH) * s * tanHalf, z};
  };
  // A quad at z = 0 (the organ), and a small one at z = 50 in front of pixel (16, 24).
  const Float3 o = at(16, 24, 50.0f);
  std::vector<Float3> positions{{-30, -30, 0},       {30, -30, 0},          {30, 30, 0},
                                {-30, 30, 0},        o + Float3{-2, -2, 0}, o + Float3{2, -2, 0},
                                o + Float3{2, 2, 0}, o + Float3{-2, 2, 0}};
  const std::vector<Triangle> triangles{{0, 1, 2}, {0, 2, 3}, {4, 5, 6}, {4, 6, 7}};
  // The probes: the target, pixel (48, 12), the hidden one, one behind the eye, one outside.
  positions.push_back({0, 0, 0});
  positions.push_back(at(48, 12, 0.0f));
  positions.push_back(at(16, 24, 0.0f));
  positions.push_back({0, 0, 150});
  positions.push_back({400, 0, 0});
  auto rays = truth::makeRayMesh(positions, triangles, truth::Intersector::Bvh);
  ASSERT_TRUE(rays) << rays.error().message;
  const auto image = indexImage();
  const auto v = pixelValuesAtVertices(camera, kW, kH, image, positions, **rays);
  ASSERT_EQ(v.size(), positions.size());
  EXPECT_EQ(v[8], pixel(kW / 2, kH / 2));  // the image's centre
  EXPECT_EQ(v[9], pixel(48, 12));          // x right, y up: rows run down
  EXPECT_TRUE(std::isnan(v[10]));          // behind the small quad
  EXPECT_TRUE(std::isnan(v[11]));          // behind the eye
  EXPECT_TRUE(std::isnan(v[12]));          // outside the image
  EXPECT_FALSE(std::isnan(v[4]));          // the occluder's own corners are seen
  // Without the occluder the hidden probe is seen, at its pixel.
  auto open = truth::makeRayMesh(positions, std::span(triangles).first(2), truth::Intersector::Bvh);
  ASSERT_TRUE(open) << open.error().message;
  EXPECT_EQ(pixelValuesAtVertices(camera, kW, kH, image, positions, **open)[10], pixel(16, 24));
}

TEST(TruthErrorView, PerPixelErrorSquaresToTheAtlasRelRms) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(0.1f, 2.0f);
  const std::size_t n = std::size_t(kW) * kH;
  std::vector<Float3> truthImage(n), method(n);
  std::vector<std::uint8_t> covered(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    covered[i] = (i % kW) > 8 && (i % kW) < 56 && (i / kW) > 4 ? 1 : 0;
    truthImage[i] = {u(rng), u(rng), u(rng)};
    method[i] = truthImage[i] + Float3{0.3f, 0.0f, 0.0f};  // a constant error of 0.3
  }
  const auto e = relativeErrorImage(method, truthImage, covered, kW, kH);
  const double relRms = scoreAgainstTruth(truthImage, method, covered).relRms;
  for (std::size_t i = 0; i < n; ++i) {
    if (!covered[i]) {
      EXPECT_TRUE(std::isnan(e[i])) << i;
      continue;
    }
    EXPECT_NEAR(e[i], relRms, 1e-5) << i;  // constant, so the 3 x 3 mean changes nothing
  }
  // The method equal to the truth: no error anywhere on the organ.
  for (float x : relativeErrorImage(truthImage, truthImage, covered, kW, kH))
    if (!std::isnan(x)) {
      EXPECT_EQ(x, 0.0f);
    }
}

}  // namespace
}  // namespace tissue::studies
