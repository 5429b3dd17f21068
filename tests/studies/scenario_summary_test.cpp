// A scenario run's summary (studies/scenario_summary.h): six frames of the data liver, every key
// there and the figures those of the run and its frames.
#include "tissue/studies/scenario_summary.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

namespace tissue::studies {
namespace {

TEST(ScenarioSummary, FiguresAreTheRunsAndItsFrames) {
  const std::filesystem::path data = TISSUE_TEST_DATA_DIR, shared = TISSUE_TEST_SHARED_DIR;
  auto parsed = scenario::loadScenario(data / "scenarios" / "liver_poke_grasp.json",
                                       {.sharedMeshesDir = shared / "meshes"});
  ASSERT_TRUE(parsed) << parsed.error().message;
  auto run = scenario::ScenarioRun::create(*parsed);
  ASSERT_TRUE(run) << run.error().message;
  std::vector<scenario::FrameMetrics> frames;
  std::size_t samples = 0;
  for (int f = 0; f < 6; ++f) {
    auto m = (*run)->advance();
    ASSERT_TRUE(m) << m.error().message;
    samples += m->forceSamplesN.size();
    frames.push_back(*m);
  }
  const double wallMs = 123.5;
  const auto j = nlohmann::json::parse(scenarioRunSummaryJson(**run, frames, wallMs));
  for (const char* key : {"scenario",
                          "mesh",
                          "vertices",
                          "simulated_vertices",
                          "springs",
                          "substeps",
                          "integrator",
                          "frames",
                          "nan_frames",
                          "divergence_events",
                          "degraded_frames",
                          "frame_ms",
                          "max_factor_ms",
                          "force_update_hz",
                          "max_contact_force_N",
                          "mean_contact_force_N",
                          "ms_per_frame",
                          "max_frame_steps",
                          "max_frame_solver_iterations",
                          "frame_work_bound",
                          "tool_teleports",
                          "wall_ms"})
    EXPECT_TRUE(j.contains(key)) << key;
  const scenario::ScenarioRun& r = **run;
  EXPECT_EQ(j["scenario"], r.scenario().file.string());
  EXPECT_EQ(j["vertices"], r.mesh().positions.size());
  EXPECT_EQ(j["springs"], r.simulator().system().springs.size());
  EXPECT_EQ(j["substeps"], r.simulator().substeps());
  EXPECT_EQ(j["integrator"], std::string(sim::integratorName(r.simulator().integrator())));
  EXPECT_EQ(j["frames"], 6);
  EXPECT_EQ(j["nan_frames"], 0);
  EXPECT_DOUBLE_EQ(j["wall_ms"].get<double>(), wallMs);
  EXPECT_EQ(j["frame_work_bound"]["steps"], r.frameWorkBound().steps);
  EXPECT_LE(j["max_frame_steps"].get<int>(), r.frameWorkBound().steps);
  // Six frames of dt each: the force samples per simulated second.
  EXPECT_NEAR(j["force_update_hz"].get<double>(), double(samples) / (6.0 * parsed->frameTime), 1e-6);
  EXPECT_GT(samples, 6u);  // several force samples a frame (the substeps)
  const auto& ms = j["frame_ms"];
  EXPECT_LE(ms["median"].get<double>(), ms["p99"].get<double>());
  EXPECT_LE(ms["p99"].get<double>(), ms["max"].get<double>());
  double maxTotal = 0.0;
  for (const auto& f : frames)
    maxTotal = std::max(maxTotal, f.totalMs);
  EXPECT_DOUBLE_EQ(ms["max"].get<double>(), maxTotal);
}

}  // namespace
}  // namespace tissue::studies
