// The volumetric spring sources of a scenario: "tet-edges" on the shared SOFA liver (.msh) and
// "lattice" on the data liver, run under gravity or a poke with no NaN; masses keep the total,
// pins hold, and the embedded surface starts exactly at rest.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "tissue/scenario/scenario_run.h"
#include "tissue/volume/tet_mesh.h"

namespace tissue::scenario {
namespace {

namespace fs = std::filesystem;

/// Lowest z of `positions` plus `fraction` of the z extent (mm): a pinned back region.
double zBelow(std::span<const Float3> positions, double fraction) {
  auto [lo, hi] = std::minmax_element(positions.begin(), positions.end(),
                                      [](const Float3& a, const Float3& b) { return a.z < b.z; });
  return double(lo->z) + fraction * double(hi->z - lo->z);
}

bool allFinite(std::span<const Float3> p) {
  return std::all_of(p.begin(), p.end(), [](const Float3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
  });
}

TEST(ScenarioVolume, TetEdgesOnTheSharedLiverHangUnderGravity) {
  const fs::path msh = fs::path(TISSUE_TEST_SHARED_DIR) / "meshes" / "liver.msh";
  if (!fs::exists(msh)) GTEST_FAIL() << "no shared meshes";
  auto tets = volume::loadTetMesh(msh, {.scaleToMm = 25.0f});
  ASSERT_TRUE(tets.ok()) << tets.error().message;
  const std::string text = R"({"mesh": ")" + msh.string() + R"(", "mesh_scale_to_mm": 25,
    "springs": {"from": "tet-edges", "stiffness": 0.05, "stiffness_law": "constant"},
    "mass": {"total": 1500, "distribution": "lumped"}, "gravity": [0, 0, -9806.65],
    "damping": {"springs": 0.0002, "rayleigh_mass": 5.0},
    "pinned": {"axis": "z", "below": )" +
                           std::to_string(zBelow(tets->positions, 0.2)) + R"(},
    "integrator": "implicit-euler", "frames": 30})";
  auto s = parseScenario(text, fs::path(TISSUE_TEST_OUTPUT_DIR) / "tets.json");
  ASSERT_TRUE(s.ok()) << s.error().message;
  auto run = ScenarioRun::create(*s);
  ASSERT_TRUE(run.ok()) << run.error().message;
  const auto& system = (*run)->simulator().system();
  EXPECT_EQ(system.vertexCount(), tets->positions.size());
  EXPECT_NEAR(std::accumulate(system.masses.begin(), system.masses.end(), 0.0), 1500.0, 1e-6);
  EXPECT_FALSE((*run)->mesh().triangles.empty());  // the boundary faces
  for (int f = 0; f < s->frames; ++f) {
    auto m = (*run)->advance();
    ASSERT_TRUE(m.ok()) << m.error().message;
    ASSERT_TRUE(m->finite) << "frame " << f;
  }
  // Pins hold exactly; the free part sags under gravity.
  const auto now = (*run)->positions();
  ASSERT_TRUE(allFinite(now));
  double sag = 0.0;
  for (std::size_t v = 0; v < now.size(); ++v) {
    if (system.invMasses[v] == 0.0) {
      EXPECT_EQ(now[v].z, tets->positions[v].z);
    }
    sag = std::max(sag, double(tets->positions[v].z - now[v].z));
  }
  EXPECT_GT(sag, 0.01);
}

TEST(ScenarioVolume, LatticeCarriesTheDataLiverThroughAPoke) {
  const fs::path obj = fs::path(TISSUE_TEST_DATA_DIR) / "meshes" / "liver.obj";
  const std::string text = R"({"mesh": ")" + obj.string() + R"(",
    "springs": {"from": "lattice", "stiffness": 0.2, "stiffness_law": "constant"},
    "lattice": {"cell_size": 16},
    "mass": {"total": 1500, "distribution": "lumped"}, "gravity": [0, 0, 0],
    "damping": {"springs": 0.0002, "rayleigh_mass": 5.0},
    "pinned": {"axis": "z", "below": -13}, "integrator": "implicit-euler", "frames": 60,
    "instrument": {"shape": "sphere", "radius": 8, "path": [
      {"time": 0.0, "position": [31.82, 0, 75]}, {"time": 1.0, "position": [31.82, 0, 45]}]}})";
  auto s = parseScenario(text, fs::path(TISSUE_TEST_OUTPUT_DIR) / "lattice.json");
  ASSERT_TRUE(s.ok()) << s.error().message;
  auto run = ScenarioRun::create(*s);
  ASSERT_TRUE(run.ok()) << run.error().message;
  const ScenarioMesh& mesh = (*run)->mesh();
  ASSERT_TRUE(mesh.lattice.has_value());
  const auto& system = (*run)->simulator().system();
  // The simulation runs on the lattice nodes, far fewer than the render mesh's vertices.
  EXPECT_EQ(system.vertexCount(), mesh.lattice->nodeCount());
  EXPECT_LT(system.vertexCount(), mesh.positions.size() / 4);
  EXPECT_NEAR(std::accumulate(system.masses.begin(), system.masses.end(), 0.0), 1500.0, 1e-6);
  // At rest the embedded surface is the loaded surface (trilinear weights reproduce it).
  const auto rest = (*run)->positions();
  ASSERT_EQ(rest.size(), mesh.positions.size());
  for (std::size_t v = 0; v < rest.size(); ++v) {
    EXPECT_NEAR(rest[v].x, mesh.positions[v].x, 1e-3);
    EXPECT_NEAR(rest[v].z, mesh.positions[v].z, 1e-3);
  }
  double maxForce = 0.0;
  for (int f = 0; f < s->frames; ++f) {
    auto m = (*run)->advance();
    ASSERT_TRUE(m.ok()) << m.error().message;
    ASSERT_TRUE(m->finite) << "frame " << f;
    maxForce = std::max(maxForce, m->forceMagnitudeN);
  }
  const auto poked = (*run)->positions();
  ASSERT_TRUE(allFinite(poked));
  // The tool reached the lattice: a force on it, and the surface under it moved down.
  EXPECT_GT(maxForce, 0.0);
  double deepest = 0.0;
  for (std::size_t v = 0; v < poked.size(); ++v)
    deepest = std::max(deepest, double(mesh.positions[v].z - poked[v].z));
  EXPECT_GT(deepest, 1.0);
}

}  // namespace
}  // namespace tissue::scenario
