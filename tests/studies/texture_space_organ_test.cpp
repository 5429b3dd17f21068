// The organ ready for texture-space diffusion and the skin profile (studies/texture_space_organ.h):
// a mesh without UVs gets the automatic atlas (the render-mesh path keeps it without), normals are
// unit and tangents one per vertex; the skin table's six Gaussians, fewer fitted to them that
// follow the same profile, and the reference table decaying to its cutoff at 3.5 sigma.
#include "tissue/studies/texture_space_organ.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

namespace tissue::studies {
namespace {

const std::filesystem::path kTable =
    std::filesystem::path(TISSUE_TEST_SHARED_DIR) / "reference" / "deon_skin_gaussians.tsv";

/// A closed box without UVs, 20 x 10 x 6 mm at one file unit per cm.
std::filesystem::path boxWithoutUvs() {
  const auto dir = std::filesystem::path(TISSUE_TEST_OUTPUT_DIR) / "studies";
  std::filesystem::create_directories(dir);
  const auto path = dir / "box_without_uvs.obj";
  std::ofstream out(path);
  out << "v 0 0 0\nv 2 0 0\nv 2 1 0\nv 0 1 0\nv 0 0 0.6\nv 2 0 0.6\nv 2 1 0.6\nv 0 1 0.6\n"
         "f 1 3 2\nf 1 4 3\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\nf 2 3 7\nf 2 7 6\nf 3 4 8\nf 3 8 7\n"
         "f 4 1 5\nf 4 5 8\n";
  return path;
}

TEST(TextureSpaceOrgan, AMeshWithoutUvsGetsTheAtlas) {
  auto organ = loadTsdOrgan(boxWithoutUvs(), 10.0f);
  ASSERT_TRUE(organ) << organ.error().message;
  EXPECT_TRUE(organ->atlas);
  EXPECT_GT(organ->charts, 0u);
  EXPECT_TRUE(organ->mesh.hasUvs());
  EXPECT_GT(organ->uvDensity, 0.0f);
  EXPECT_NEAR(organ->hi.x - organ->lo.x, 20.0f, 1e-4f);  // mm, the scale applied
  ASSERT_EQ(organ->normals.size(), organ->mesh.positions.size());
  ASSERT_EQ(organ->tangents.size(), organ->mesh.positions.size());
  for (const Float3& n : organ->normals)
    EXPECT_NEAR(std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z), 1.0f, 1e-4f);
  // The render-mesh path leaves it without UVs.
  auto plain = loadRenderMesh(boxWithoutUvs(), 10.0f);
  ASSERT_TRUE(plain) << plain.error().message;
  EXPECT_FALSE(plain->atlas);
  EXPECT_FALSE(plain->mesh.hasUvs());
  EXPECT_EQ(plain->uvDensity, 0.0f);
}

TEST(TextureSpaceOrgan, TheDataLiverKeepsItsOwnUvs) {
  auto organ = loadTsdOrgan(std::filesystem::path(TISSUE_TEST_DATA_DIR) / "meshes" / "liver.obj", 1.0f);
  ASSERT_TRUE(organ) << organ.error().message;
  EXPECT_FALSE(organ->atlas);
  EXPECT_EQ(organ->charts, 0u);
  EXPECT_GT(organ->uvDensity, 0.0f);
  EXPECT_EQ(organ->arrays().positions.size(), organ->mesh.positions.size());
}

TEST(TextureSpaceOrgan, FewerSkinGaussiansFollowTheSixTermProfile) {
  auto six = skinGaussians(kTable, 6);
  ASSERT_TRUE(six) << six.error().message;
  ASSERT_EQ(six->size(), 6u);
  for (const auto& g : *six)
    EXPECT_GT(g.varianceMm2, 0.0f);
  for (int count : {2, 4}) {
    auto fit = skinGaussians(kTable, count);
    ASSERT_TRUE(fit) << fit.error().message;
    ASSERT_EQ(fit->size(), std::size_t(count));
    // Radially weighted error of the red channel (the widest) over 0..4 mm, against its size.
    double err = 0.0, norm = 0.0;
    for (int i = 1; i <= 400; ++i) {
      const float r = 0.01f * float(i);
      const double a = double(render::evaluateGaussianSum(*six, r).x);
      const double b = double(render::evaluateGaussianSum(*fit, r).x);
      err += double(r) * (a - b) * (a - b);
      norm += double(r) * a * a;
    }
    EXPECT_LT(std::sqrt(err / norm), count == 2 ? 0.25 : 0.1) << count << " Gaussians";
  }
  EXPECT_FALSE(skinGaussians(kTable, 3));
  auto missing = skinGaussians("/nonexistent/deon.tsv", 6);
  ASSERT_FALSE(missing);
  EXPECT_NE(missing.error().message.find("/nonexistent/deon.tsv"), std::string::npos);
}

TEST(TextureSpaceOrgan, ReferenceTableDecaysToItsCutoff) {
  auto six = skinGaussians(kTable, 6);
  ASSERT_TRUE(six) << six.error().message;
  float cutoff = 0.0f;
  const render::RadialProfileTable table = skinProfileTable(*six, cutoff);
  float widest = 0.0f;
  for (const auto& g : *six)
    widest = std::max(widest, g.varianceMm2);
  EXPECT_NEAR(cutoff, 3.5f * std::sqrt(widest), 1e-5f);
  ASSERT_EQ(table.radiusMm.size(), table.value.size());
  EXPECT_FLOAT_EQ(table.radiusMm.back(), cutoff);
  for (std::size_t i = 1; i < table.value.size(); ++i)
    EXPECT_LE(table.value[i].x, table.value[i - 1].x);
  EXPECT_LT(table.value.back().x, 0.01f * table.value.front().x);
}

}  // namespace
}  // namespace tissue::studies
