// Running scenarios: the static equilibrium of a pinned membrane built from a scenario.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "tissue/scenario/scenario_run.h"
#include "tissue/sim/static_solve.h"

namespace tissue::scenario {
namespace {

/// Writes a flat n x n grid (spacing mm, z = 0) as OBJ and returns its border vertices (0-based).
std::vector<std::uint32_t> writeGridObj(const std::filesystem::path& path, int n, double spacing) {
  std::ofstream out(path);
  std::vector<std::uint32_t> border;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      out << "v " << x * spacing << ' ' << y * spacing << " 0\n";
      if (x == 0 || y == 0 || x == n - 1 || y == n - 1)
        border.push_back(static_cast<std::uint32_t>(y * n + x));
    }
  for (int y = 0; y + 1 < n; ++y)
    for (int x = 0; x + 1 < n; ++x) {
      const int a = y * n + x + 1, b = a + 1, c = a + n + 1, d = a + n;
      out << "f " << a << ' ' << b << ' ' << c << "\nf " << a << ' ' << c << ' ' << d << '\n';
    }
  return border;
}

TEST(ScenarioRun, PinnedMembraneStaticEquilibriumHasNoForceLeft) {
  const std::filesystem::path dir = std::filesystem::path(TISSUE_TEST_OUTPUT_DIR) / "scenario";
  std::filesystem::create_directories(dir);
  const auto border = writeGridObj(dir / "membrane.obj", 11, 2.0);
  std::string pins;
  for (std::uint32_t b : border)
    pins += (pins.empty() ? "" : ", ") + std::to_string(b);
  const std::string text = R"({"mesh": "membrane.obj",
    "springs": {"from": "surface", "stiffness": 0.02, "bending_stiffness": 0.002},
    "mass": {"density": 0.001, "distribution": "lumped"}, "gravity": [0, 0, -9806.65],
    "pinned": [)" + pins + "]}";
  auto s = parseScenario(text, dir / "membrane.json");
  ASSERT_TRUE(s.ok()) << s.error().message;
  auto m = loadScenarioMesh(*s);
  ASSERT_TRUE(m.ok()) << m.error().message;
  auto system = buildSystem(*s, *m);
  ASSERT_TRUE(system.ok()) << system.error().message;
  std::vector<sim::Vec3d> x = sim::restState(m->positions).x;
  const auto report = sim::solveStatic(*system, x, {.toleranceN = 1e-9});
  EXPECT_TRUE(report.converged) << report.residualN;
  EXPECT_LE(sim::maxFreeForceN(*system, x), 1e-9);
  // The pins hold, the centre sags most, and the sag is symmetric about the centre.
  const std::uint32_t centre = 5 * 11 + 5;
  for (std::size_t k = 0; k < x.size(); ++k) {
    if (system->invMasses[k] == 0.0) {
      EXPECT_EQ(x[k].z, 0.0);
    }
    EXPECT_GE(x[k].z, x[centre].z - 1e-9);
  }
  EXPECT_LT(x[centre].z, -0.05);
  EXPECT_NEAR(x[4 * 11 + 5].z, x[6 * 11 + 5].z, 1e-6);
}

}  // namespace
}  // namespace tissue::scenario
