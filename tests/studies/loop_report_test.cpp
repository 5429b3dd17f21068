// The trainee's loop's figures for the reports (studies/loop_report.h): the rounding, the phase
// figures as JSON and as a table, the instrument's summary and the pass timings.
#include "tissue/studies/loop_report.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>

#include "tissue/core/statistics.h"

namespace tissue::studies {
namespace {

TEST(LoopReport, ThreeDigitsKeepsThreeSignificantDigits) {
  EXPECT_DOUBLE_EQ(threeDigits(1.23456), 1.23);
  EXPECT_DOUBLE_EQ(threeDigits(123456.0), 123000.0);
  EXPECT_DOUBLE_EQ(threeDigits(0.000987654), 0.000988);
  EXPECT_DOUBLE_EQ(threeDigits(-27.26), -27.3);
  EXPECT_EQ(threeDigits(0.0), 0.0);
  EXPECT_TRUE(std::isnan(threeDigits(std::numeric_limits<double>::quiet_NaN())));
  EXPECT_EQ(threeDigits(std::numeric_limits<double>::infinity()), std::numeric_limits<double>::infinity());
}

scene::LoopPhaseSamples knownSamples() {
  scene::LoopPhaseSamples samples;
  for (std::size_t p = 0; p < samples.phases.size(); ++p)
    for (int frame = 1; frame <= 200; ++frame)  // phase p: 1..200 ms times (p + 1), scaled
      samples.phases[p].second.push_back(double(frame) * double(p + 1) * 0.123456);
  return samples;
}

TEST(LoopReport, PhasesJsonHoldsEveryPhaseRoundedInOrder) {
  const scene::LoopPhaseSamples samples = knownSamples();
  const auto j = nlohmann::json::parse(loopPhasesJson(samples));
  ASSERT_TRUE(j.is_array());
  ASSERT_EQ(j.size(), samples.phases.size());
  for (std::size_t p = 0; p < samples.phases.size(); ++p) {
    const auto s = summarizeSamples(samples.phases[p].second);
    EXPECT_EQ(j[p]["phase"], samples.phases[p].first);
    EXPECT_DOUBLE_EQ(j[p]["median_ms"].get<double>(), threeDigits(s.median));
    EXPECT_DOUBLE_EQ(j[p]["p99_ms"].get<double>(), threeDigits(s.p99));
    EXPECT_DOUBLE_EQ(j[p]["max_ms"].get<double>(), threeDigits(s.max));
    EXPECT_LE(j[p]["median_ms"].get<double>(), j[p]["p99_ms"].get<double>());
    EXPECT_LE(j[p]["p99_ms"].get<double>(), j[p]["max_ms"].get<double>());
  }
}

TEST(LoopReport, PhasesTableIsWellFormedAndMatchesTheJson) {
  const scene::LoopPhaseSamples samples = knownSamples();
  const Table table = loopPhasesTable(samples);
  const auto j = nlohmann::json::parse(loopPhasesJson(samples));
  ASSERT_EQ(table.header, (std::vector<std::string>{"phase", "median", "p99", "max"}));
  ASSERT_EQ(table.rows.size(), samples.phases.size());
  for (std::size_t p = 0; p < table.rows.size(); ++p) {
    ASSERT_EQ(table.rows[p].size(), 4u);
    EXPECT_EQ(table.rows[p][0], samples.phases[p].first);
    EXPECT_DOUBLE_EQ(std::stod(table.rows[p][1]), j[p]["median_ms"].get<double>());
    EXPECT_DOUBLE_EQ(std::stod(table.rows[p][3]), j[p]["max_ms"].get<double>());
  }
  // The Markdown has a header, a rule and one line a phase.
  const std::string md = markdownTable(table);
  EXPECT_EQ(std::count(md.begin(), md.end(), '\n'), long(samples.phases.size() + 2));
  EXPECT_NE(md.find("| 4 render (lit, read back) | "), std::string::npos);
}

TEST(LoopReport, InstrumentJsonHoldsTheRecordsFigures) {
  scene::LoopRecord record;
  for (int f = 0; f < 120; ++f) {
    scenario::FrameMetrics m;
    m.frame = f;
    m.forceN = {0.01 * f, -0.5, 0.02 * f};
    m.forceMagnitudeN = std::sqrt(m.forceN.x * m.forceN.x + 0.25 + m.forceN.z * m.forceN.z);
    m.integrateMs = 1.5;
    record.frames.push_back(m);
  }
  record.maxPushN = 0.77;
  record.maxPullN = 5.19;
  record.pokedFrame = 40;
  record.liftedFrame = 90;
  const auto j = nlohmann::json::parse(instrumentJson(record));
  for (const char* key : {"frames", "nan_frames", "divergence_events", "max_contact_force_N",
                          "mean_contact_force_N", "max_push_N", "max_pull_N", "poked_frame", "lifted_frame",
                          "ms_per_frame", "contact_force_N_per_frame"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_EQ(j["frames"], 120);
  EXPECT_EQ(j["nan_frames"], 0);
  EXPECT_DOUBLE_EQ(j["max_push_N"].get<double>(), 0.77);
  EXPECT_DOUBLE_EQ(j["max_pull_N"].get<double>(), 5.19);
  EXPECT_EQ(j["poked_frame"], 40);
  EXPECT_EQ(j["lifted_frame"], 90);
  EXPECT_DOUBLE_EQ(j["ms_per_frame"]["integrate"].get<double>(), 1.5);
  EXPECT_DOUBLE_EQ(j["max_contact_force_N"].get<double>(), record.frames.back().forceMagnitudeN);
  const auto& forces = j["contact_force_N_per_frame"];
  ASSERT_EQ(forces.size(), 120u);
  for (std::size_t f = 0; f < forces.size(); f += 17) {
    ASSERT_EQ(forces[f].size(), 3u);
    EXPECT_DOUBLE_EQ(forces[f][0].get<double>(), record.frames[f].forceN.x);
    EXPECT_DOUBLE_EQ(forces[f][1].get<double>(), record.frames[f].forceN.y);
    EXPECT_DOUBLE_EQ(forces[f][2].get<double>(), record.frames[f].forceN.z);
  }
}

TEST(LoopReport, PassTimingsJsonListsThePassesInOrder) {
  render::RenderTimings timings;
  const auto pass = [](std::string name, double cpu, double gpu, int object) {
    render::PassTiming p;
    p.name = std::move(name);
    p.cpuMs = cpu;
    p.gpuMs = gpu;
    p.object = object;
    return p;
  };
  timings.passes = {pass("shadow:0", 0.5, -1.0, -1), pass("lit", 2.25, 1.75, 0),
                    pass("tonemap", 0.125, 0.0625, -1)};
  const auto j = nlohmann::json::parse(passTimingsJson(timings));
  ASSERT_EQ(j.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(j[i]["name"], timings.passes[i].name);
    EXPECT_DOUBLE_EQ(j[i]["cpu_ms"].get<double>(), timings.passes[i].cpuMs);
    EXPECT_DOUBLE_EQ(j[i]["gpu_ms"].get<double>(), timings.passes[i].gpuMs);
    EXPECT_EQ(j[i]["object"].get<int>(), timings.passes[i].object);
  }
  EXPECT_EQ(nlohmann::json::parse(passTimingsJson({})).size(), 0u);
}

}  // namespace
}  // namespace tissue::studies
