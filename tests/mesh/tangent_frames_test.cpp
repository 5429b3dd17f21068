#include "tissue/mesh/tangent_frames.h"

#include <gtest/gtest.h>

#include <cmath>

#include "test_meshes.h"
#include "tissue/mesh/deformable_surface.h"

namespace tissue::mesh {
namespace {

float dot3(Float3 a, Float3 b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
Float3 cross3(Float3 a, Float3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
Float3 xyz(Float4 t) {
  return {t.x, t.y, t.z};
}

void expectOrthonormal(std::span<const Float3> normals, std::span<const Float4> tangents) {
  for (std::size_t i = 0; i < normals.size(); ++i) {
    const Float3 t = xyz(tangents[i]);
    EXPECT_NEAR(dot3(t, t), 1.0f, 1e-5f) << i;
    EXPECT_NEAR(dot3(t, normals[i]), 0.0f, 1e-5f) << i;
    EXPECT_TRUE(tangents[i].w == 1.0f || tangents[i].w == -1.0f) << i;
  }
}

TEST(TangentFrames, GridFollowsUAndV) {
  auto grid = test::makeGrid(6, 4, 30.0f, 20.0f);
  std::vector<Float3> n(grid.positions.size(), Float3{0, 0, 1});
  std::vector<Float4> t(grid.positions.size());
  computeTangentFrames(grid.positions, grid.uvs, grid.triangles, n, t);
  expectOrthonormal(n, t);
  for (const auto& f : t) {
    EXPECT_LT(test::angleBetween(xyz(f), {1, 0, 0}), 1e-5);
    EXPECT_EQ(f.w, 1.0f);  // B = cross(N, T) = +y = direction of increasing v
  }
}

TEST(TangentFrames, MirroredUvsFlipHandedness) {
  auto grid = test::makeGrid(6, 4, 30.0f, 20.0f);
  for (auto& uv : grid.uvs)
    uv.x = 1.0f - uv.x;  // u now grows towards -x
  std::vector<Float3> n(grid.positions.size(), Float3{0, 0, 1});
  std::vector<Float4> t(grid.positions.size());
  computeTangentFrames(grid.positions, grid.uvs, grid.triangles, n, t);
  for (const auto& f : t) {
    EXPECT_LT(test::angleBetween(xyz(f), {-1, 0, 0}), 1e-5);
    EXPECT_EQ(f.w, -1.0f);  // cross(N, T) = -y, but v still grows towards +y
  }
}

/// Worst angle between the tangents and the analytic dP/du (east) away from the poles.
double worstEastError(const DeformableSurface& surface) {
  const auto& m = surface.mesh();
  double worst = 0.0;
  for (std::size_t i = 0; i < m.positions.size(); ++i) {
    const Float3 p = m.positions[i];
    const float rxy = std::sqrt(p.x * p.x + p.y * p.y);
    if (rxy < 0.5f * 25.0f) continue;  // near the poles dP/du vanishes
    worst = std::max(worst, test::angleBetween(xyz(surface.tangents()[i]), {-p.y / rxy, p.x / rxy, 0.0f}));
    EXPECT_EQ(surface.tangents()[i].w, 1.0f) << i;  // v grows northwards = cross(N, east)
  }
  return worst;
}

TEST(TangentFrames, MatchTheAnalyticUvGradient) {
  // On a UV sphere the two triangles of each quad skew dP/du by equal and opposite amounts, and
  // angle weighting cancels them: the tangent is the analytic east direction up to rounding,
  // including at the wrap-around seam (u = 0 / 1) where the copies pool their gradients.
  for (int stacks : {12, 24, 48}) {
    auto s = DeformableSurface::create(test::makeUvSphere(25.0f, stacks, 2 * stacks));
    ASSERT_TRUE(s.ok());
    expectOrthonormal(s->normals(), s->tangents());
    EXPECT_LT(worstEastError(*s), 1e-5) << stacks;
  }
}

TEST(TangentFrames, WrapSeamCopiesShareTheirFrame) {
  auto surface = DeformableSurface::create(test::makeUvSphere(25.0f, 24, 48));
  ASSERT_TRUE(surface.ok());
  const auto& m = surface->mesh();
  int seamPairs = 0;
  for (std::size_t i = 0; i < m.positions.size(); ++i)
    for (std::size_t j = i + 1; j < m.positions.size() && j < i + 60; ++j)
      if (m.geometricIndex[i] == m.geometricIndex[j] && std::abs(m.positions[i].z) < 20.0f) {
        EXPECT_EQ(surface->normals()[i], surface->normals()[j]);
        EXPECT_LT(test::angleBetween(xyz(surface->tangents()[i]), xyz(surface->tangents()[j])), 1e-6);
        ++seamPairs;
      }
  EXPECT_GT(seamPairs, 10);
}

TEST(TangentFrames, RotatedChartAcrossASeamKeepsItsOwnFrame) {
  // Two triangles of one flat square; the second chart's UVs are rotated by 90 degrees, so the
  // seam copies must keep perpendicular tangents (pooling them would blur both).
  SurfaceMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  // First chart: u along +x, v along +y. Second chart: u along +y, v along -x (rotated).
  m.uvs = {{0, 0}, {0.4f, 0}, {0.4f, 0.4f}, {0.5f, 0.5f}, {0.9f, 0.1f}, {0.9f, 0.5f}};
  m.geometricIndex = {0, 1, 2, 0, 2, 3};
  m.geometricVertexCount = 4;
  m.triangles = {{0, 1, 2}, {3, 4, 5}};
  std::vector<Float3> n(6, Float3{0, 0, 1});
  std::vector<Float4> t(6);
  computeTangentFrames(m.positions, m.uvs, m.triangles, n, t, m.geometricIndex);
  EXPECT_LT(test::angleBetween(xyz(t[0]), {1, 0, 0}), 1e-5);
  EXPECT_LT(test::angleBetween(xyz(t[3]), {0, 1, 0}), 1e-5);
}

TEST(TangentFrames, BitangentPointsAlongV) {
  auto sphere = test::makeUvSphere(25.0f, 16, 32);
  auto surface = DeformableSurface::create(sphere);
  ASSERT_TRUE(surface.ok());
  const auto& m = surface->mesh();
  for (const auto& tri : m.triangles) {
    // Per-triangle dP/dv must have a positive component along B = w cross(N, T).
    const Float3 e1 = {m.positions[tri[1]].x - m.positions[tri[0]].x,
                       m.positions[tri[1]].y - m.positions[tri[0]].y,
                       m.positions[tri[1]].z - m.positions[tri[0]].z};
    const Float3 e2 = {m.positions[tri[2]].x - m.positions[tri[0]].x,
                       m.positions[tri[2]].y - m.positions[tri[0]].y,
                       m.positions[tri[2]].z - m.positions[tri[0]].z};
    const float s1 = m.uvs[tri[1]].x - m.uvs[tri[0]].x, t1 = m.uvs[tri[1]].y - m.uvs[tri[0]].y;
    const float s2 = m.uvs[tri[2]].x - m.uvs[tri[0]].x, t2 = m.uvs[tri[2]].y - m.uvs[tri[0]].y;
    const float r = 1.0f / (s1 * t2 - s2 * t1);
    const Float3 dpdv = {(e2.x * s1 - e1.x * s2) * r, (e2.y * s1 - e1.y * s2) * r,
                         (e2.z * s1 - e1.z * s2) * r};
    const auto f = surface->tangents()[tri[0]];
    const Float3 b = cross3(surface->normals()[tri[0]], xyz(f));
    EXPECT_GT(dot3(dpdv, {b.x * f.w, b.y * f.w, b.z * f.w}), 0.0f);
  }
}

}  // namespace
}  // namespace tissue::mesh
