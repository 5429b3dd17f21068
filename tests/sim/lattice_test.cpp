// The embedded lattice: counts, embedding, affine exactness, force scattering, masses, errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numeric>

#include "closed_surfaces.h"
#include "tissue/sim/lattice.h"

namespace tissue::sim {
namespace {

using test::boxSurface;
using test::icosphere;

Vec3d toVec(const Float3& p) {
  return {p.x, p.y, p.z};
}

TEST(Lattice, OneCellHasAllTwentyEightPairs) {
  const auto box = boxSurface({0, 0, 0}, {10, 10, 10});
  auto lattice = buildEmbeddedLattice(box.positions, box.triangles, {.cellSize = 10.0});
  ASSERT_TRUE(lattice.ok()) << lattice.error().message;
  EXPECT_EQ(lattice->cells.size(), 1u);
  EXPECT_EQ(lattice->nodeCount(), 8u);
  EXPECT_EQ(lattice->springs.size(), 28u);  // 12 edges, 12 face diagonals, 4 body diagonals
}

TEST(Lattice, TwoCellsShareAFacesSixSprings) {
  const auto box = boxSurface({0, 0, 0}, {10, 5, 5});
  auto lattice = buildEmbeddedLattice(box.positions, box.triangles, {.cellSize = 5.0});
  ASSERT_TRUE(lattice.ok()) << lattice.error().message;
  EXPECT_EQ(lattice->cells.size(), 2u);
  EXPECT_EQ(lattice->nodeCount(), 12u);
  EXPECT_EQ(lattice->springs.size(), 2u * 28u - 6u);  // shared face: 4 edges, 2 diagonals
}

TEST(Lattice, EmbeddingReproducesTheRestPositions) {
  const auto sphere = icosphere(30.0, {5, -3, 2}, 3);
  auto lattice = buildEmbeddedLattice(sphere.positions, sphere.triangles, {.cellsAlongLongestAxis = 8});
  ASSERT_TRUE(lattice.ok()) << lattice.error().message;
  std::vector<Float3> out(sphere.positions.size());
  embedPositions(*lattice, lattice->nodePositions, out);
  for (std::size_t s = 0; s < out.size(); ++s) {
    EXPECT_NEAR(out[s].x, sphere.positions[s].x, 1e-4);
    EXPECT_NEAR(out[s].y, sphere.positions[s].y, 1e-4);
    EXPECT_NEAR(out[s].z, sphere.positions[s].z, 1e-4);
    const auto& w = lattice->vertexWeights[s];
    EXPECT_NEAR(std::accumulate(w.begin(), w.end(), 0.0), 1.0, 1e-12);
    for (double wc : w)
      EXPECT_GE(wc, 0.0);
  }
}

TEST(Lattice, AnyAffineMapOfTheNodesMovesTheSurfaceExactly) {
  const auto sphere = icosphere(25.0, {0, 0, 0}, 2);
  auto lattice = buildEmbeddedLattice(sphere.positions, sphere.triangles, {.cellsAlongLongestAxis = 6});
  ASSERT_TRUE(lattice.ok());
  // A rotation (40 degrees about a tilted axis) plus a translation, then a shear plus a stretch.
  const double c = std::cos(0.7), s = std::sin(0.7);
  auto rigid = [&](const Vec3d& p) {
    return Vec3d{c * p.x - s * p.y + 3.0, s * p.x + c * p.y - 7.0, p.z + 11.0};
  };
  auto affine = [](const Vec3d& p) {
    return Vec3d{1.3 * p.x + 0.4 * p.y, 0.8 * p.y - 0.2 * p.z, p.z + 0.5 * p.x};
  };
  for (auto map : {std::function<Vec3d(const Vec3d&)>(rigid), std::function<Vec3d(const Vec3d&)>(affine)}) {
    std::vector<Vec3d> moved;
    for (const Vec3d& n : lattice->nodePositions)
      moved.push_back(map(n));
    std::vector<Float3> out(sphere.positions.size());
    embedPositions(*lattice, moved, out);
    for (std::size_t v = 0; v < out.size(); ++v) {
      const Vec3d want = map(toVec(sphere.positions[v]));
      EXPECT_NEAR(out[v].x, want.x, 1e-4);
      EXPECT_NEAR(out[v].y, want.y, 1e-4);
      EXPECT_NEAR(out[v].z, want.z, 1e-4);
    }
  }
}

TEST(Lattice, ScatterIsTheTransposeOfTheEmbedding) {
  const auto sphere = icosphere(20.0, {0, 0, 0}, 2);
  auto lattice = buildEmbeddedLattice(sphere.positions, sphere.triangles, {.cellsAlongLongestAxis = 5});
  ASSERT_TRUE(lattice.ok());
  std::vector<Vec3d> f(sphere.positions.size());
  for (std::size_t v = 0; v < f.size(); ++v)
    f[v] = {std::sin(1.0 * double(v)), std::cos(2.0 * double(v)), 0.5};
  std::vector<Vec3d> nodeForces(lattice->nodeCount());
  scatterToNodes(*lattice, f, nodeForces);
  // Virtual work: sum_s f_s . (W x)_s = sum_n (W^T f)_n . x_n for any node displacement x.
  std::vector<Vec3d> x(lattice->nodeCount());
  for (std::size_t n = 0; n < x.size(); ++n)
    x[n] = {std::cos(0.3 * double(n)), std::sin(0.7 * double(n)), 0.1 * double(n % 7)};
  double surfaceWork = 0.0, nodeWork = 0.0;
  Vec3d surfaceTotal{}, nodeTotal{};
  for (std::size_t v = 0; v < f.size(); ++v) {
    Vec3d u{};
    for (int c = 0; c < 8; ++c)
      u += lattice->vertexWeights[v][c] * x[lattice->vertexNodes[v][c]];
    surfaceWork += dot(f[v], u);
    surfaceTotal += f[v];
  }
  for (std::size_t n = 0; n < x.size(); ++n) {
    nodeWork += dot(nodeForces[n], x[n]);
    nodeTotal += nodeForces[n];
  }
  EXPECT_NEAR(surfaceWork, nodeWork, 1e-9 * std::abs(surfaceWork) + 1e-9);
  EXPECT_NEAR(length(surfaceTotal - nodeTotal), 0.0, 1e-9);
}

TEST(Lattice, MassesSumToDensityTimesFilledVolume) {
  const auto sphere = icosphere(30.0, {0, 0, 0}, 3);
  const double density = 1.06e-3;  // g/mm^3
  auto lattice =
      buildEmbeddedLattice(sphere.positions, sphere.triangles,
                           {.cellsAlongLongestAxis = 10, .mass = {.total = 0.0, .density = density}});
  ASSERT_TRUE(lattice.ok());
  const double h = lattice->cellSize;
  EXPECT_DOUBLE_EQ(lattice->filledVolume, double(lattice->cells.size()) * h * h * h);
  EXPECT_NEAR(std::accumulate(lattice->masses.begin(), lattice->masses.end(), 0.0),
              density * lattice->filledVolume, 1e-12 * density * lattice->filledVolume);
  // A corner node of one cell gets 1/8 of it; an interior node of eight cells gets a whole cell.
  const double cellMass = density * h * h * h;
  const double largest = *std::max_element(lattice->masses.begin(), lattice->masses.end());
  EXPECT_NEAR(largest, cellMass, 1e-12);
  auto total = buildEmbeddedLattice(sphere.positions, sphere.triangles,
                                    {.cellsAlongLongestAxis = 10, .mass = {.total = 700.0}});
  ASSERT_TRUE(total.ok());
  EXPECT_NEAR(std::accumulate(total->masses.begin(), total->masses.end(), 0.0), 700.0, 1e-9);
}

TEST(Lattice, InsideCellsConvergeToTheEnclosedVolume) {
  // Cells kept for their centre approximate the sphere; the extra cells only hold vertices.
  const auto sphere = icosphere(30.0, {1, 2, 3}, 4);
  const double volume = test::enclosedVolume(sphere.positions, sphere.triangles);
  auto lattice = buildEmbeddedLattice(sphere.positions, sphere.triangles, {.cellsAlongLongestAxis = 30});
  ASSERT_TRUE(lattice.ok());
  const double h = lattice->cellSize;
  EXPECT_NEAR(double(lattice->insideCells) * h * h * h, volume, 0.03 * volume);
  EXPECT_GT(lattice->filledVolume, volume);  // every vertex embedded: the lattice covers the surface
}

TEST(Lattice, BoxAlignedWithTheGridIsFilledExactly) {
  const auto box = boxSurface({0, 0, 0}, {40, 20, 10});
  auto lattice = buildEmbeddedLattice(box.positions, box.triangles, {.cellsAlongLongestAxis = 8});
  ASSERT_TRUE(lattice.ok());
  EXPECT_EQ(lattice->insideCells, 8u * 4u * 2u);
  EXPECT_EQ(lattice->vertexCells, 0u);
  EXPECT_DOUBLE_EQ(lattice->filledVolume, 8000.0);
}

TEST(Lattice, PinningNodesOfAVertex) {
  const auto box = boxSurface({0, 0, 0}, {10, 10, 10});
  auto lattice = buildEmbeddedLattice(box.positions, box.triangles, {.cellSize = 5.0});
  ASSERT_TRUE(lattice.ok());
  const std::vector<std::uint32_t> corner = {7};  // (10, 10, 10)
  const auto cell = cellNodes(*lattice, corner);
  EXPECT_EQ(cell.size(), 8u);
  const auto nearest = nearestNodes(*lattice, corner);
  ASSERT_EQ(nearest.size(), 1u);
  EXPECT_NEAR(length(lattice->nodePositions[nearest[0]] - Vec3d{10, 10, 10}), 0.0, 1e-12);
}

TEST(Lattice, OpenAndNonManifoldSurfacesAreErrors) {
  auto sphere = icosphere(10.0, {0, 0, 0}, 1);
  auto open = sphere;
  open.triangles.pop_back();
  auto r = buildEmbeddedLattice(open.positions, open.triangles, {});
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().message.find("surface is open"), std::string::npos) << r.error().message;
  EXPECT_NE(r.error().message.find("3 boundary edges"), std::string::npos) << r.error().message;
  auto fin = sphere;
  const Triangle t = fin.triangles[0];
  fin.positions.push_back({50, 50, 50});
  fin.triangles.push_back({t[0], t[1], static_cast<std::uint32_t>(fin.positions.size() - 1)});
  r = buildEmbeddedLattice(fin.positions, fin.triangles, {});
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().message.find("non-manifold"), std::string::npos) << r.error().message;
  r = buildEmbeddedLattice(sphere.positions, sphere.triangles, {.cellSize = 1e-4});
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().message.find("larger cell size"), std::string::npos) << r.error().message;
}

}  // namespace
}  // namespace tissue::sim
