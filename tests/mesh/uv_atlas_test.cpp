// The automatic UV atlas: no overlaps, no flips, gutters between charts, every triangle mapped,
// analytic distortion on a flat patch, and the distortion on organ meshes (printed).
#include "tissue/mesh/uv_atlas.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <numbers>

#include "../data/uv_overlap.h"
#include "test_meshes.h"
#include "tissue/mesh/load_mesh.h"

namespace tissue::mesh {
namespace {

/// Geometric positions and triangles of a render mesh (welded at its UV seams).
struct Welded {
  std::vector<Float3> positions;
  std::vector<Triangle> triangles;
};

Welded weld(const SurfaceMesh& m) {
  Welded w;
  w.positions.resize(m.geometricVertexCount);
  for (std::size_t i = 0; i < m.positions.size(); ++i)
    w.positions[m.geometricIndex[i]] = m.positions[i];
  for (const Triangle& t : m.triangles)
    w.triangles.push_back({m.geometricIndex[t[0]], m.geometricIndex[t[1]], m.geometricIndex[t[2]]});
  return w;
}

/// The invariants every atlas must satisfy; returns its distortion.
AtlasDistortion checkAtlas(const Welded& mesh, const UvAtlas& atlas, const AtlasSettings& settings) {
  // Every input triangle is mapped to render vertices of the same input vertices.
  EXPECT_EQ(atlas.triangles.size(), mesh.triangles.size());
  EXPECT_EQ(atlas.uvs.size(), atlas.originalVertex.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k)
      EXPECT_EQ(atlas.originalVertex[atlas.triangles[t][k]], mesh.triangles[t][k]) << "triangle " << t;
  // Inside [0, 1]^2.
  for (const Float2& w : atlas.uvs) {
    EXPECT_GE(w.x, 0.0f);
    EXPECT_LE(w.x, 1.0f);
    EXPECT_GE(w.y, 0.0f);
    EXPECT_LE(w.y, 1.0f);
  }
  // No overlaps, within a chart or between charts (the data tests' exact checker, gutter 0: its
  // separating-axis gap underestimates diagonal distances, so the gutter is checked on boxes).
  const std::vector<Float2> uvs(atlas.uvs.begin(), atlas.uvs.end());
  const auto conflicts = datatest::findUvConflicts(uvs, atlas.triangles, 0.0);
  EXPECT_TRUE(conflicts.empty()) << conflicts.size() << " conflicts, first between triangles "
                                 << (conflicts.empty() ? 0 : conflicts[0].first) << " and "
                                 << (conflicts.empty() ? 0 : conflicts[0].second);
  // Charts' bounding boxes lie a gutter apart and a gutter inside the map.
  std::vector<std::array<float, 4>> box(atlas.chartCount, {2.0f, 2.0f, -1.0f, -1.0f});
  for (std::size_t t = 0; t < atlas.triangles.size(); ++t)
    for (std::uint32_t v : atlas.triangles[t]) {
      auto& b = box[atlas.chartOfTriangle[t]];
      b = {std::min(b[0], atlas.uvs[v].x), std::min(b[1], atlas.uvs[v].y), std::max(b[2], atlas.uvs[v].x),
           std::max(b[3], atlas.uvs[v].y)};
    }
  const float gutter = 0.999f * settings.gutterTexels / float(settings.resolution);
  for (std::size_t a = 0; a < box.size(); ++a) {
    EXPECT_GE(std::min(box[a][0], box[a][1]), gutter) << a;
    EXPECT_LE(std::max(box[a][2], box[a][3]), 1.0f - gutter) << a;
    for (std::size_t b = a + 1; b < box.size(); ++b) {
      const float gap = std::max(std::max(box[b][0] - box[a][2], box[a][0] - box[b][2]),
                                 std::max(box[b][1] - box[a][3], box[a][1] - box[b][3]));
      EXPECT_GE(gap, gutter) << "charts " << a << " and " << b;
    }
  }
  EXPECT_TRUE(hasUsableUvs(atlas.uvs, atlas.triangles, atlas.uvs.size()));
  std::vector<Float3> renderPositions;
  for (std::uint32_t v : atlas.originalVertex)
    renderPositions.push_back(mesh.positions[v]);
  const AtlasDistortion d = measureAtlasDistortion(renderPositions, atlas.uvs, atlas.triangles);
  EXPECT_EQ(d.flippedTriangles, 0u);
  return d;
}

void print(const std::string& name, const UvAtlas& atlas, const AtlasDistortion& d) {
  std::cout << name << ": charts " << atlas.chartCount << ", render vertices " << atlas.uvs.size()
            << ", L2 stretch " << d.l2Stretch << ", angle s1/s2 mean " << d.meanAngleRatio << " max "
            << d.maxAngleRatio << ", area mean " << d.meanAreaRatio << " max " << d.maxAreaRatio
            << ", coverage " << d.coverage << ", texels/mm " << atlas.texelsPerMm << "\n";
}

TEST(UvAtlas, FlatPatchIsOneUndistortedChart) {
  const Welded grid = weld(test::makeGrid(20, 10, 40.0f, 20.0f));
  const AtlasSettings settings;
  auto atlas = computeUvAtlas(grid.positions, grid.triangles, settings);
  ASSERT_TRUE(atlas) << atlas.error().message;
  EXPECT_EQ(atlas->chartCount, 1u);
  const AtlasDistortion d = checkAtlas(grid, *atlas, settings);
  // LSCM reproduces an isometry of a flat patch up to a similarity.
  EXPECT_NEAR(d.l2Stretch, 1.0, 1e-4);
  EXPECT_NEAR(d.maxAngleRatio, 1.0, 1e-4);
  EXPECT_NEAR(d.maxAreaRatio, 1.0, 1e-4);
  // One chart of 40 x 20 mm laid landscape across the map: texels per mm = usable width / 40.
  const float usable = float(settings.resolution) - 2.0f * settings.gutterTexels;
  EXPECT_NEAR(atlas->texelsPerMm, usable / 40.0f, 0.01f * usable / 40.0f);
}

TEST(UvAtlas, SphereHasValidChartsInsideTheNormalCone) {
  const Welded sphere = weld(test::makeUvSphere(30.0f, 24, 48));
  const AtlasSettings settings;
  auto atlas = computeUvAtlas(sphere.positions, sphere.triangles, settings);
  ASSERT_TRUE(atlas) << atlas.error().message;
  const AtlasDistortion d = checkAtlas(sphere, *atlas, settings);
  print("sphere r 30 mm", *atlas, d);
  EXPECT_GT(atlas->chartCount, 1u);  // a closed surface cannot be one disk
  // Charts within a 50-degree cone of a sphere are spherical caps: mildly distorted.
  EXPECT_LT(d.l2Stretch, 1.15);
  EXPECT_LT(d.meanAngleRatio, 1.1);
  // Every chart lies in the cone of its seed: no two triangles of a chart differ by > 100 deg.
  std::vector<Float3> n(sphere.triangles.size());
  for (std::size_t t = 0; t < n.size(); ++t) {
    const auto& tri = sphere.triangles[t];
    const Float3 a = sphere.positions[tri[0]], b = sphere.positions[tri[1]], c = sphere.positions[tri[2]];
    n[t] = {(a.x + b.x + c.x), (a.y + b.y + c.y), (a.z + b.z + c.z)};  // radial on a sphere
  }
  for (std::size_t s = 0; s < n.size(); s += 37)
    for (std::size_t t = 0; t < n.size(); ++t)
      if (atlas->chartOfTriangle[s] == atlas->chartOfTriangle[t]) {
        EXPECT_LT(test::angleBetween(n[s], n[t]), 2.0 * 50.0 * std::numbers::pi / 180.0 + 0.05);
      }
}

TEST(UvAtlas, AnnulusIsSplitIntoDisks) {
  // A flat ring: one normal everywhere, so region growing gives one chart with a hole, which
  // LSCM cannot flatten one-to-one; the atlas must split it.
  Welded ring;
  const int segments = 32;
  for (int k = 0; k < segments; ++k) {
    const double a = 2.0 * std::numbers::pi * k / segments;
    ring.positions.push_back({float(10.0 * std::cos(a)), float(10.0 * std::sin(a)), 0.0f});
    ring.positions.push_back({float(20.0 * std::cos(a)), float(20.0 * std::sin(a)), 0.0f});
  }
  for (std::uint32_t k = 0; k < std::uint32_t(segments); ++k) {
    const std::uint32_t i0 = 2 * k, o0 = 2 * k + 1, i1 = 2 * ((k + 1) % segments), o1 = i1 + 1;
    ring.triangles.push_back({i0, o0, o1});
    ring.triangles.push_back({i0, o1, i1});
  }
  const AtlasSettings settings;
  auto atlas = computeUvAtlas(ring.positions, ring.triangles, settings);
  ASSERT_TRUE(atlas) << atlas.error().message;
  EXPECT_GE(atlas->chartCount, 2u);
  const AtlasDistortion d = checkAtlas(ring, *atlas, settings);
  EXPECT_NEAR(d.maxAngleRatio, 1.0, 1e-3);  // flat pieces flatten without distortion
}

class OrganAtlas : public ::testing::TestWithParam<std::pair<const char*, float>> {};

TEST_P(OrganAtlas, IsValidAndReportsItsDistortion) {
  const auto [file, scale] = GetParam();
  const std::string name(file);
  const std::filesystem::path path = name.starts_with("data/")
                                         ? std::filesystem::path(TISSUE_TEST_DATA_DIR) / name.substr(5)
                                         : std::filesystem::path(TISSUE_TEST_SHARED_DIR) / "meshes" / name;
  if (!std::filesystem::exists(path)) GTEST_FAIL() << path << " is not here";
  LoadOptions options;
  options.scaleToMm = scale;
  auto mesh = loadMesh(path, options);
  ASSERT_TRUE(mesh) << mesh.error().message;
  const Welded organ = weld(*mesh);
  const AtlasSettings settings;
  auto atlas = computeUvAtlas(organ.positions, organ.triangles, settings);
  ASSERT_TRUE(atlas) << atlas.error().message;
  const AtlasDistortion d = checkAtlas(organ, *atlas, settings);
  print(name, *atlas, d);
  EXPECT_LT(d.l2Stretch, 1.5);
  EXPECT_GT(d.coverage, 0.3);
}

INSTANTIATE_TEST_SUITE_P(Meshes, OrganAtlas,
                         ::testing::Values(std::pair{"liver-smooth.obj", 25.0f},
                                           std::pair{"data/meshes/liver.obj", 1.0f}));

TEST(UvAtlas, UsableUvsNeedAllPresentAndNoOverlap) {
  SurfaceMesh grid = test::makeGrid(4, 4, 10.0f, 10.0f);
  EXPECT_TRUE(hasUsableUvs(grid.uvs, grid.triangles, grid.positions.size()));
  EXPECT_FALSE(hasUsableUvs({}, grid.triangles, grid.positions.size()));
  // Folding one vertex over its neighbours makes triangles overlap.
  grid.uvs[6] = {0.9f, 0.9f};
  EXPECT_FALSE(hasUsableUvs(grid.uvs, grid.triangles, grid.positions.size()));
  EXPECT_GT(countUvOverlaps(grid.uvs, grid.triangles, 100), 0u);
  // A mirrored copy elsewhere does not overlap: mirrored charts are usable.
  SurfaceMesh mirrored = test::makeGrid(4, 4, 10.0f, 10.0f);
  for (Float2& w : mirrored.uvs)
    w = {1.0f - w.x, w.y};
  EXPECT_TRUE(hasUsableUvs(mirrored.uvs, mirrored.triangles, mirrored.positions.size()));
}

TEST(UvAtlas, BadInputIsAnError) {
  const std::vector<Float3> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const std::vector<Triangle> bad = {{0, 1, 3}};
  auto r = computeUvAtlas(p, bad);
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().message.find("triangle 1"), std::string::npos) << r.error().message;
  EXPECT_FALSE(computeUvAtlas({}, {}));
}

}  // namespace
}  // namespace tissue::mesh
