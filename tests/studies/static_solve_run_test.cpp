// A scenario's static equilibrium (studies/static_solve_run.h) on the data liver: converged to
// the tolerance asked, one finite position line a vertex, the JSON the report's figures; a cap of
// one step gives an unconverged solution, not an error.
#include "tissue/studies/static_solve_run.h"

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>

namespace tissue::studies {
namespace {

scenario::Scenario dataScenario() {
  const std::filesystem::path data = TISSUE_TEST_DATA_DIR, shared = TISSUE_TEST_SHARED_DIR;
  auto parsed = scenario::loadScenario(data / "scenarios" / "liver_poke_grasp.json",
                                       {.sharedMeshesDir = shared / "meshes"});
  EXPECT_TRUE(parsed) << parsed.error().message;
  return *parsed;
}

TEST(StaticSolveRun, DataLiverConvergesAndWritesEveryVertex) {
  const double tolerance = 1e-6;  // N
  auto s = solveScenarioStatic(dataScenario(), {.toleranceN = tolerance, .maxIterations = 500});
  ASSERT_TRUE(s) << s.error().message;
  EXPECT_TRUE(s->report.converged);
  EXPECT_LE(s->report.residualN, tolerance);
  EXPECT_GT(s->vertices, 1000u);
  // One "x y z" line of finite mm a vertex.
  std::istringstream lines(s->positionLines);
  std::string line;
  std::size_t count = 0;
  while (std::getline(lines, line)) {
    std::istringstream xyz(line);
    double x = NAN, y = NAN, z = NAN;
    ASSERT_TRUE(xyz >> x >> y >> z) << line;
    EXPECT_TRUE(std::isfinite(x) && std::isfinite(y) && std::isfinite(z));
    ++count;
  }
  EXPECT_EQ(count, s->vertices);
  const auto j = nlohmann::json::parse(s->json);
  EXPECT_EQ(j["vertices"], s->vertices);
  EXPECT_EQ(j["converged"], true);
  EXPECT_EQ(j["iterations"], s->report.iterations);
  EXPECT_EQ(j["accepted_steps"], s->report.acceptedSteps);
  EXPECT_DOUBLE_EQ(j["residual_N"].get<double>(), s->report.residualN);
  EXPECT_DOUBLE_EQ(j["tolerance_N"].get<double>(), tolerance);
  EXPECT_DOUBLE_EQ(j["ms"].get<double>(), s->ms);
}

TEST(StaticSolveRun, OneStepIsAnUnconvergedSolution) {
  auto s = solveScenarioStatic(dataScenario(), {.toleranceN = 1e-12, .maxIterations = 1});
  ASSERT_TRUE(s) << s.error().message;
  EXPECT_FALSE(s->report.converged);
  EXPECT_EQ(s->report.iterations, 1);
  EXPECT_EQ(nlohmann::json::parse(s->json)["converged"], false);
}

}  // namespace
}  // namespace tissue::studies
