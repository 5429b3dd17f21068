// The re-fit comparison and the bench deformations: the exact incremental re-fit is the full
// re-fit (François 2009 §2.2 planes are a function of the neighbourhood only), a poke moves the
// fraction of vertices asked for, and a bound on the normal error only ever skips re-fits.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "tissue/studies/deformations.h"
#include "tissue/studies/refit_study.h"

namespace tissue::studies {
namespace {

// A 41 x 41 height field with 1 mm spacing and gentle waves (+z up).
struct Grid {
  std::vector<Float3> positions;
  std::vector<Triangle> triangles;
};
Grid waveGrid() {
  Grid g;
  const int n = 40;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      g.positions.push_back({float(i), float(j), float(0.5 * std::sin(0.3 * i) * std::cos(0.2 * j))});
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const auto a = std::uint32_t(j * (n + 1) + i), b = a + 1, c = a + std::uint32_t(n + 1), d = c + 1;
      g.triangles.push_back({a, b, d});
      g.triangles.push_back({a, d, c});
    }
  return g;
}

std::vector<Float3> upNormals(std::size_t n) {
  return std::vector<Float3>(n, Float3{0.0f, 0.0f, 1.0f});
}

TEST(Deformations, PokeMovesTheNearestFractionOnly) {
  const Grid g = waveGrid();
  std::vector<Float3> poked(g.positions.size());
  const auto moved = applyPoke(g.positions, upNormals(g.positions.size()), 840, 0.05, 1.0f, poked);
  EXPECT_NEAR(double(moved.size()), 0.05 * double(g.positions.size()), 1.0);
  std::size_t changed = 0;
  for (std::size_t v = 0; v < poked.size(); ++v)
    changed += poked[v] == g.positions[v] ? 0 : 1;
  EXPECT_LE(changed, moved.size());
  EXPECT_GT(changed, moved.size() / 2);
  EXPECT_LT(poked[840].z, g.positions[840].z - 0.5f);  // the centre goes in (along -normal)
}

TEST(Deformations, TopVertexIsTheHighest) {
  const Grid g = waveGrid();
  const std::uint32_t top = topVertex(g.positions);
  for (const Float3& p : g.positions)
    EXPECT_LE(p.z, g.positions[top].z);
}

TEST(RefitStudy, ExactIncrementalRefitIsTheFullRefit) {
  const Grid g = waveGrid();
  std::vector<Float3> poked(g.positions.size()), bent(g.positions.size());
  applyPoke(g.positions, upNormals(g.positions.size()), topVertex(g.positions), 0.05, 1.0f, poked);
  applyGlobalBend(g.positions, 2.0f, bent);
  const mesh::PlaneFitSettings fit;            // r = 3.1 mm: ~30 vertices per sphere
  const mesh::PlaneRefitSettings bound{1e-2};  // rad
  const RefitComparison local = compareRefits(g.positions, poked, g.triangles, fit, 3, bound);
  EXPECT_LT(local.exact.maxNormalDeviationRad, 1e-5);
  EXPECT_LT(local.exact.maxOffsetDeviationMm, 1e-5);
  EXPECT_GT(local.movedFraction, 0.02);
  EXPECT_LT(local.movedFraction, 0.06);
  // Planes near the poke are re-fitted, the far ones are not.
  EXPECT_GE(local.exact.refittedFraction, local.movedFraction);
  EXPECT_LT(local.exact.refittedFraction, 0.5);
  EXPECT_LE(local.tolerant.refittedFraction, local.exact.refittedFraction);
  const RefitComparison global = compareRefits(g.positions, bent, g.triangles, fit, 3, bound);
  EXPECT_GT(global.movedFraction, 0.9);
  EXPECT_LT(global.exact.maxNormalDeviationRad, 1e-5);
  EXPECT_GT(global.fullRefitMs, 0.0);
}

TEST(RefitStudy, MeshBenchPokesTheFractionAskedForAndBendsEverything) {
  const Grid g = waveGrid();
  const MeshRefitBench b = benchRefitOnMesh(g.positions, g.triangles, {}, 0.05, 3, {1e-2});
  EXPECT_EQ(b.vertices, g.positions.size());
  EXPECT_EQ(b.repeats, 3);
  EXPECT_NEAR(b.poke.movedFraction, 0.05, 0.01);
  EXPECT_GT(b.bend.movedFraction, 0.9);
  EXPECT_LT(b.poke.exact.maxNormalDeviationRad, 1e-5);
  EXPECT_GT(b.meanNeighbourhood, 10.0);  // r = 3.1 mm on a 1 mm grid: about 30 vertices
  EXPECT_LT(b.meanNeighbourhood, 60.0);
  const std::string json = meshRefitBenchJson(b);
  for (const char* key :
       {"\"moved_fraction\"", "\"speedup\"", "\"global\"", "\"tolerant\"", "\"mean_neighbourhood\""})
    EXPECT_NE(json.find(key), std::string::npos) << key;
}

}  // namespace
}  // namespace tissue::studies
