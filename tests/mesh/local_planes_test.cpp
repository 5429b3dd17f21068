// The local planes of subsurface texture mapping (François et al. §2.2, eq. 7-8, 14) and
// their incremental re-fit under deformation.
#include "tissue/mesh/local_planes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "test_meshes.h"
#include "tissue/mesh/deformable_surface.h"
#include "tissue/mesh/vertex_normals.h"

namespace tissue::mesh {
namespace {

Float3 xyz(Float4 p) {
  return {p.x, p.y, p.z};
}

struct Fixture {
  std::vector<Float3> rest;
  std::vector<Triangle> tris;
};

Fixture sphereFixture(float radius = 30.0f) {
  const auto s = test::makeUvSphere(radius, 40, 80);
  return {geometricPositionsOf(s), geometricTrianglesOf(s)};
}

std::vector<Float3> normalsOf(std::span<const Float3> p, std::span<const Triangle> t) {
  std::vector<Float3> n(p.size());
  computeVertexNormals(p, t, n);
  return n;
}

double maxAngle(std::span<const Float4> a, std::span<const Float4> b) {
  double worst = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i)
    worst = std::max(worst, test::angleBetween(xyz(a[i]), xyz(b[i])));
  return worst;
}

double maxOffset(std::span<const Float4> a, std::span<const Float4> b) {
  double worst = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i)
    worst = std::max(worst, double(std::abs(a[i].w - b[i].w)));
  return worst;
}

TEST(LocalPlanes, RadiusFollowsEquation8) {
  const PlaneFitSettings s{.sigma_t = 2.0f, .epsilon = 0.05f};
  EXPECT_NEAR(s.radiusMm(), -std::log(0.05) / 2.0, 1e-6);
}

TEST(LocalPlanes, FlatPatchGivesItsOwnPlane) {
  auto grid = test::makeGrid(20, 20, 40.0f, 40.0f);
  for (auto& p : grid.positions)
    p = {p.x, 0.6f * p.y, 5.0f + 0.8f * p.y};  // tilted plane
  const auto n = normalsOf(grid.positions, grid.triangles);
  const auto hoods = findNeighbourhoods(grid.positions, 4.0f, grid.triangles);
  std::vector<Float4> planes(grid.positions.size());
  fitVertexPlanes(grid.positions, n, hoods, planes);
  for (std::size_t i = 0; i < planes.size(); ++i) {
    EXPECT_LT(test::angleBetween(xyz(planes[i]), n[i]), 1e-5) << i;
    EXPECT_NEAR(planes[i].w, 0.0f, 1e-4f) << i;  // the vertex lies on its plane: P_V = V
  }
}

TEST(LocalPlanes, SpherePlanesAreTangentParallelAndBelowTheVertex) {
  const float R = 30.0f;
  const auto f = sphereFixture(R);
  const auto n = normalsOf(f.rest, f.tris);
  const PlaneFitSettings settings{.sigma_t = 0.5f, .epsilon = 0.01f};  // r = 9.2 mm
  const auto hoods = findNeighbourhoods(f.rest, settings.radiusMm(), f.tris);
  std::vector<Float4> planes(f.rest.size());
  fitVertexPlanes(f.rest, n, hoods, planes);
  for (std::size_t i = 0; i < planes.size(); ++i) {
    const Float3 radial = {f.rest[i].x / R, f.rest[i].y / R, f.rest[i].z / R};
    // The UV sphere's sampling is mirror-symmetric east-west about every vertex, so N_S lies in
    // its meridian plane; it is symmetric north-south only near the equator, where N_S is radial.
    const float rxy = std::sqrt(f.rest[i].x * f.rest[i].x + f.rest[i].y * f.rest[i].y);
    if (rxy > 1e-3f) {
      const Float3 east = {-f.rest[i].y / rxy, f.rest[i].x / rxy, 0.0f};
      EXPECT_NEAR(planes[i].x * east.x + planes[i].y * east.y, 0.0f, 1e-4f) << i;
    }
    if (std::abs(f.rest[i].z) < 0.05f * R) {
      EXPECT_LT(test::angleBetween(xyz(planes[i]), radial), 1e-4) << i;
    }
    EXPECT_LT(test::angleBetween(xyz(planes[i]), radial), 0.05) << i;
    // The centroid of a spherical cap lies inside the sphere: the plane is below V (d < 0),
    // at most the cap height r^2 / (2R) deep.
    const float r = settings.radiusMm();
    EXPECT_LT(planes[i].w, 0.0f) << i;
    EXPECT_GT(planes[i].w, -r * r / (2.0f * R)) << i;
  }
}

TEST(LocalPlanes, NeighbourhoodsAreSymmetricAndHoldTheOneRing) {
  const auto f = sphereFixture();
  const auto hoods = findNeighbourhoods(f.rest, 3.0f, f.tris);
  const auto contains = [&](std::uint32_t a, std::uint32_t b) {
    return std::binary_search(hoods.indices.begin() + hoods.offsets[a],
                              hoods.indices.begin() + hoods.offsets[a + 1], b);
  };
  for (std::uint32_t v = 0; v < hoods.vertexCount(); ++v) {
    EXPECT_TRUE(contains(v, v));
    for (auto k = hoods.offsets[v]; k < hoods.offsets[v + 1]; ++k)
      EXPECT_TRUE(contains(hoods.indices[k], v));
  }
  for (const auto& t : f.tris)
    for (int k = 0; k < 3; ++k)
      EXPECT_TRUE(contains(t[k], t[(k + 1) % 3]));
}

/// Random local pokes (Gaussian bumps at random vertices) and random global deformations,
/// accumulated over many frames: the incremental planes equal a full re-fit each time. The
/// moments are exact integers, so the normals agree bit for bit and nothing drifts.
TEST(LocalPlanes, IncrementalEqualsFullAfterRandomLocalAndGlobalDeformations) {
  const auto f = sphereFixture();
  IncrementalPlaneFitter fitter(f.rest, f.tris, {.sigma_t = 1.5f, .epsilon = 0.01f});
  auto pos = f.rest;
  fitter.fitAll(pos, normalsOf(pos, f.tris));
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> uni(-1.0f, 1.0f);
  std::vector<Float4> full(pos.size());
  for (int frame = 0; frame < 300; ++frame) {
    const bool global = frame % 5 == 4;
    const Float3 c = pos[std::uniform_int_distribution<std::size_t>(0, pos.size() - 1)(rng)];
    const Float3 dir = {uni(rng), uni(rng), uni(rng)};
    for (auto& p : pos) {
      const float d2 = (p.x - c.x) * (p.x - c.x) + (p.y - c.y) * (p.y - c.y) + (p.z - c.z) * (p.z - c.z);
      if (global) {
        p = {p.x + 0.5f * std::sin(0.1f * p.y), p.y + 0.5f * std::cos(0.1f * p.z),
             p.z + 0.3f * std::sin(0.1f * p.x)};
      } else if (d2 < 100.0f) {
        const float w = 2.0f * std::exp(-d2 / 20.0f);  // only vertices within 10 mm move
        p = {p.x + w * dir.x, p.y + w * dir.y, p.z + w * dir.z};
      }
    }
    const auto n = normalsOf(pos, f.tris);
    const auto stats = fitter.update(pos, n);
    fitVertexPlanes(pos, n, fitter.neighbourhoods(), full);
    for (std::size_t i = 0; i < full.size(); ++i) {
      ASSERT_EQ(xyz(fitter.planes()[i]), xyz(full[i])) << "frame " << frame << " vertex " << i;
    }
    EXPECT_LT(maxOffset(fitter.planes(), full), 1e-5) << "frame " << frame;
    if (!global) {
      EXPECT_LT(stats.refittedPlanes, pos.size() / 4) << "a local poke must stay local";
    }
  }
}

TEST(LocalPlanes, OnlyPlanesWhoseNeighbourhoodMovedAreRefitted) {
  const auto f = sphereFixture();
  IncrementalPlaneFitter fitter(f.rest, f.tris, {.sigma_t = 1.5f, .epsilon = 0.01f});
  auto pos = f.rest;
  fitter.fitAll(pos, normalsOf(pos, f.tris));
  pos[123].x += 0.5f;
  const auto stats = fitter.update(pos, normalsOf(pos, f.tris));
  const auto& h = fitter.neighbourhoods();
  EXPECT_EQ(stats.movedVertices, 1u);
  EXPECT_EQ(stats.refittedPlanes, std::size_t(h.offsets[124] - h.offsets[123]));
}

/// Neighbourhoods are defined in the rest state (docs/DECISIONS.md): under a stretch the
/// membership does not change, so the planes change continuously with the deformation; with
/// current-state spheres, vertices would cross the sphere and the plane would jump.
TEST(LocalPlanes, RestStateNeighbourhoodsMakePlanesContinuousUnderStretch) {
  auto grid = test::makeGrid(30, 30, 60.0f, 60.0f);
  for (auto& p : grid.positions)
    p.z = 4.0f * std::sin(p.x * 0.15f) * std::cos(p.y * 0.1f);
  const auto rest = grid.positions;
  IncrementalPlaneFitter fitter(rest, grid.triangles, {.sigma_t = 1.0f, .epsilon = 0.01f});
  fitter.fitAll(rest, normalsOf(rest, grid.triangles));
  const auto membership = fitter.neighbourhoods().indices;
  std::vector<Float4> previous(fitter.planes().begin(), fitter.planes().end());
  double worstStep = 0.0;
  for (int step = 1; step <= 50; ++step) {
    const float s = 1.0f + 0.5f * float(step) / 50.0f;  // stretch x by up to 50%
    auto pos = rest;
    for (auto& p : pos)
      p.x *= s;
    fitter.update(pos, normalsOf(pos, grid.triangles));
    worstStep = std::max(worstStep, maxAngle(fitter.planes(), previous));
    previous.assign(fitter.planes().begin(), fitter.planes().end());
  }
  EXPECT_EQ(fitter.neighbourhoods().indices, membership);
  EXPECT_LT(worstStep, 0.02);  // 1% stretch per step moves no plane by more than ~1 degree
}

}  // namespace
}  // namespace tissue::mesh
