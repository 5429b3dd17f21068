#include "tissue/mesh/vertex_normals.h"

#include <gtest/gtest.h>

#include <cmath>

#include "test_meshes.h"
#include "tissue/mesh/deformable_surface.h"

namespace tissue::mesh {
namespace {

TEST(VertexNormals, FlatGridIsExactlyUp) {
  const auto grid = test::makeGrid(8, 5, 40.0f, 25.0f);
  std::vector<Float3> n(grid.positions.size());
  computeVertexNormals(grid.positions, grid.triangles, n);
  for (const auto& v : n)
    EXPECT_LT(test::angleBetween(v, {0, 0, 1}), 1e-6);
}

TEST(VertexNormals, SphereNormalsAreRadialAndConverge) {
  // Angle weighting is second-order accurate on a sphere: halving the edge length divides the
  // worst angular error by about four.
  double previous = 1.0;
  for (int res : {8, 16, 32}) {
    const auto s = test::makeUvSphere(30.0f, res, 2 * res);
    const auto geo = geometricPositionsOf(s);
    const auto tris = geometricTrianglesOf(s);
    std::vector<Float3> n(geo.size());
    computeVertexNormals(geo, tris, n);
    double worst = 0.0;
    for (std::size_t i = 0; i < geo.size(); ++i) {
      const float len = std::sqrt(geo[i].x * geo[i].x + geo[i].y * geo[i].y + geo[i].z * geo[i].z);
      worst = std::max(worst, test::angleBetween(n[i], {geo[i].x / len, geo[i].y / len, geo[i].z / len}));
    }
    if (res > 8) {
      EXPECT_GT(previous / worst, 3.0) << "resolution " << res;
    }
    previous = worst;
  }
  EXPECT_LT(previous, 2e-3);
}

TEST(VertexNormals, AngleWeightingIgnoresTriangulation) {
  // A cube corner at the origin, its three faces triangulated in two different ways: the
  // angle-weighted normal is (1,1,1)/sqrt(3) either way (area weighting would differ).
  const std::vector<Float3> p = {{0, 0, 0},   {-1, 0, 0},  {0, -1, 0}, {0, 0, -1},
                                 {-1, -1, 0}, {0, -1, -1}, {-1, 0, -1}};
  // Faces around the corner seen from outside (+x+y+z): xy-face (z=0), yz-face (x=0), zx-face (y=0).
  const std::vector<Triangle> a = {{0, 1, 4}, {0, 4, 2}, {0, 2, 5}, {0, 5, 3}, {0, 3, 6}, {0, 6, 1}};
  const std::vector<Triangle> b = {{0, 1, 4}, {0, 4, 2}, {0, 2, 5}, {0, 5, 3}, {0, 3, 1}, {1, 3, 6}};
  std::vector<Float3> na(p.size()), nb(p.size());
  computeVertexNormals(p, a, na);
  computeVertexNormals(p, b, nb);
  const float k = 1.0f / std::sqrt(3.0f);
  EXPECT_LT(test::angleBetween(na[0], {k, k, k}), 1e-6);
  EXPECT_LT(test::angleBetween(nb[0], {k, k, k}), 1e-6);
}

}  // namespace
}  // namespace tissue::mesh
