#include "tissue/mesh/deformable_surface.h"

#include <gtest/gtest.h>

#include <cmath>
#include <span>
#include <vector>

#include "test_meshes.h"
#include "tissue/core/vec_math.h"
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

// A dent that deepens and drifts across the north cap: frame f of a poke.
std::vector<Float3> pokedShape(std::span<const Float3> rest, int f) {
  std::vector<Float3> geo(rest.begin(), rest.end());
  const Float3 centre{3.0f * float(f) / 10.0f, 0.0f, 30.0f};
  for (auto& p : geo) {
    const Float3 d = p - centre;
    p.z -= 0.1f * float(f) * std::exp(-dot(d, d) / 60.0f);
  }
  return geo;
}

// Planes and tangents skipped while a method does not read them come back, when one does,
// equal to those of a surface that kept them current every frame (issue 16).
void expectCatchUpEqualsAlwaysCurrent(const PlaneRefitSettings& refit) {
  const auto sphere = test::makeUvSphere(30.0f, 30, 60);
  auto always = DeformableSurface::create(sphere, {}, 1, refit);
  auto lazy = DeformableSurface::create(sphere, {}, 1, refit);
  ASSERT_TRUE(always.ok() && lazy.ok());
  const std::vector<Float4> restPlanes(lazy->planes().begin(), lazy->planes().end());
  const std::vector<Float4> restTangents(lazy->tangents().begin(), lazy->tangents().end());
  lazy->setWork({.planes = false, .tangents = false});
  for (int f = 1; f <= 12; ++f) {
    const auto geo = pokedShape(always->geometricRestPositions(), f);
    const auto a = always->update(geo);
    const auto l = lazy->update(geo);
    EXPECT_TRUE(a.planes && a.tangents);
    EXPECT_GT(a.refit.refittedPlanes, 0u) << "frame " << f;
    // The lazy surface does no plane re-fit nor tangent work, and says its attributes are stale.
    EXPECT_FALSE(l.planes || l.tangents);
    EXPECT_EQ(l.refit.refittedPlanes, 0u);
    EXPECT_EQ(l.refit.movedVertices, 0u);
    EXPECT_FALSE(lazy->planesCurrent() || lazy->tangentsCurrent());
    for (std::size_t i = 0; i < restPlanes.size(); ++i)
      ASSERT_EQ(lazy->planes()[i], restPlanes[i]) << "frame " << f;  // stale: as at rest
    for (std::size_t i = 0; i < restTangents.size(); ++i)
      ASSERT_EQ(lazy->tangents()[i], restTangents[i]) << "frame " << f;
    for (std::size_t i = 0; i < lazy->normals().size(); ++i)
      ASSERT_EQ(lazy->normals()[i], always->normals()[i]);  // normals always follow
  }
  // The poke changed planes and tangents: the catch-up below has work to do.
  std::size_t changedPlanes = 0, changedTangents = 0;
  for (std::size_t i = 0; i < restPlanes.size(); ++i)
    changedPlanes += always->planes()[i] == restPlanes[i] ? 0 : 1;
  for (std::size_t i = 0; i < restTangents.size(); ++i)
    changedTangents += always->tangents()[i] == restTangents[i] ? 0 : 1;
  EXPECT_GT(changedPlanes, 0u);
  EXPECT_GT(changedTangents, 0u);
  // Switching the work on brings both up to date at once.
  const SurfaceWork fresh = lazy->setWork({});
  EXPECT_TRUE(fresh.planes && fresh.tangents);
  EXPECT_TRUE(lazy->planesCurrent() && lazy->tangentsCurrent());
  for (std::size_t i = 0; i < lazy->tangents().size(); ++i)
    ASSERT_EQ(lazy->tangents()[i], always->tangents()[i]) << "vertex " << i;  // exactly
  const auto caughtUp = lazy->planes();
  if (refit.maxNormalErrorRad == 0.0) {
    for (std::size_t i = 0; i < caughtUp.size(); ++i)
      ASSERT_EQ(caughtUp[i], always->planes()[i]) << "vertex " << i;  // the exact re-fit: bit for bit
  } else {
    // Both within the bound of a full re-fit of the current shape, so within twice it of each other.
    auto full = DeformableSurface::create(sphere, {}, 1, {.maxNormalErrorRad = 0.0});
    ASSERT_TRUE(full.ok());
    full->update(pokedShape(full->geometricRestPositions(), 12));
    const double theta = refit.maxNormalErrorRad;
    EXPECT_LE(comparePlanes(caughtUp, full->planes()).maxAngleRad, theta);
    EXPECT_LE(comparePlanes(always->planes(), full->planes()).maxAngleRad, theta);
    EXPECT_LE(comparePlanes(caughtUp, always->planes()).maxAngleRad, 2.0 * theta);
    EXPECT_LT(comparePlanes(caughtUp, full->planes()).maxOffsetMm, 1e-3);
  }
  // Nothing to bring up to date a second time.
  const SurfaceWork again = lazy->setWork({});
  EXPECT_FALSE(again.planes || again.tangents);
}

TEST(DeformableSurface, SkippedPlanesAndTangentsCatchUpExactly) {
  expectCatchUpEqualsAlwaysCurrent({.maxNormalErrorRad = 0.0});
}

TEST(DeformableSurface, SkippedPlanesCatchUpWithinTheRefitBound) {
  expectCatchUpEqualsAlwaysCurrent({});
}

}  // namespace
}  // namespace tissue::mesh
