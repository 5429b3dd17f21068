#include "tissue/mesh/deformable_surface.h"

#include <gtest/gtest.h>

#include <cmath>

#include "test_meshes.h"
#include "tissue/mesh/tangent_frames.h"
#include "tissue/mesh/vertex_normals.h"

namespace tissue::mesh {
namespace {

TEST(DeformableSurface, RequiresUvsAndAValidMaterial) {
  auto grid = test::makeGrid(4, 4, 10.0f, 10.0f);
  EXPECT_FALSE(DeformableSurface::create(grid, {.sigma_t = -1.0f}).ok());
  grid.uvs.clear();
  const auto r = DeformableSurface::create(grid);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().message.find("texture coordinates"), std::string::npos);
}

TEST(DeformableSurface, PatchBorderIsItsBoundary) {
  auto surface = DeformableSurface::create(test::makeGrid(10, 6, 20.0f, 12.0f));
  ASSERT_TRUE(surface.ok());
  EXPECT_EQ(surface->boundaryVertices().size(), std::size_t(2 * (10 + 6)));
  auto sphere = DeformableSurface::create(test::makeUvSphere(10.0f, 8, 16));
  ASSERT_TRUE(sphere.ok());
  EXPECT_TRUE(sphere->boundaryVertices().empty());  // closed: nothing to pin by default
}

TEST(DeformableSurface, UpdateMatchesRecomputationFromScratch) {
  auto surface = DeformableSurface::create(test::makeUvSphere(30.0f, 30, 60));
  ASSERT_TRUE(surface.ok());
  std::vector<Float3> geo(surface->geometricRestPositions().begin(), surface->geometricRestPositions().end());
  for (auto& p : geo)
    if (p.z > 20.0f) p.z -= 0.3f * (p.z - 20.0f);  // poke the north cap
  const auto stats = surface->update(geo);
  EXPECT_GT(stats.refit.movedVertices, 0u);
  EXPECT_LT(stats.refit.refittedPlanes, geo.size() / 3);
  // Normals and tangents equal a from-scratch computation on the render vertices.
  const auto& m = surface->mesh();
  std::vector<Float3> gn(geo.size()), n(m.positions.size());
  computeVertexNormals(geo, surface->geometricTriangles(), gn);
  for (std::size_t i = 0; i < n.size(); ++i)
    n[i] = gn[m.geometricIndex[i]];
  std::vector<Float4> t(m.positions.size());
  computeTangentFrames(m.positions, m.uvs, m.triangles, n, t, m.geometricIndex);
  for (std::size_t i = 0; i < n.size(); ++i) {
    EXPECT_EQ(surface->normals()[i], n[i]);
    EXPECT_EQ(surface->tangents()[i], t[i]);
    EXPECT_EQ(m.positions[i], geo[m.geometricIndex[i]]);
  }
  // Planes equal a full re-fit.
  std::vector<Float4> incremental(surface->planes().begin(), surface->planes().end());
  surface->refitAllPlanes();
  for (std::size_t i = 0; i < incremental.size(); ++i) {
    EXPECT_LT(test::angleBetween({incremental[i].x, incremental[i].y, incremental[i].z},
                                 {surface->planes()[i].x, surface->planes()[i].y, surface->planes()[i].z}),
              1e-5);
    EXPECT_NEAR(incremental[i].w, surface->planes()[i].w, 1e-4f);
  }
}

}  // namespace
}  // namespace tissue::mesh
