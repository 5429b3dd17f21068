// The one-spring stability study's report: one table row per case, symplectic Euler at its
// theoretical limit 2 sqrt(m/k), the chart without explicit Euler, and the report's files.
#include "tissue/studies/stability_report.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace tissue::studies {
namespace {

sim::StabilityStudyConfig smallStudy() {
  sim::StabilityStudyConfig config;
  config.masses = {1.0};
  config.stiffnesses = {0.1, 1.0};
  return config;
}

TEST(StabilityReport, OneRowPerCaseAndSymplecticEulerAtTheTheory) {
  const auto r = runStabilityReport(smallStudy());
  ASSERT_EQ(r.cases.size(), 5u * 2u);  // five integrators, one mass, two stiffnesses
  const Table t = stabilityTable(r.cases);
  ASSERT_EQ(t.rows.size(), r.cases.size());
  int symplectic = 0;
  for (const auto& row : t.rows) {
    ASSERT_EQ(row.size(), t.header.size());
    if (row[0] != "symplectic-euler") continue;
    ++symplectic;
    EXPECT_NEAR(std::stod(row[6]), 1.0, 1e-3) << "measured / theory";  // h < 2 sqrt(m/k)
    EXPECT_EQ(row[7], "limit found");
  }
  EXPECT_EQ(symplectic, 2);
  const auto explicitRow =
      std::find_if(t.rows.begin(), t.rows.end(), [](const auto& row) { return row[0] == "explicit-euler"; });
  ASSERT_NE(explicitRow, t.rows.end());
  EXPECT_EQ((*explicitRow)[5], "-");  // undamped explicit Euler is stable at no step
}

TEST(StabilityReport, ChartDrawsTheLimitsRelativeToTheReference) {
  const auto cases = sim::runStabilityStudy(smallStudy());
  const auto series = stabilityChartSeries(cases);
  for (const auto& s : series) {
    EXPECT_EQ(s.label.find("explicit-euler"), std::string::npos) << s.label;
    EXPECT_EQ(s.x.size(), 2u) << s.label;  // one point per stiffness
    if (s.label.rfind("symplectic-euler", 0) != 0) continue;
    for (double y : s.y)
      EXPECT_NEAR(y, 1.0, 1e-3);
  }
  // symplectic Euler, Verlet, implicit Euler and the fast solver (the last two at the bound tested).
  EXPECT_EQ(series.size(), 4u);
}

TEST(StabilityReport, ReportHoldsTheTableTheJsonAndTheChart) {
  const auto r = runStabilityReport(smallStudy());
  std::vector<std::string> names;
  for (const auto& f : r.report.files)
    names.push_back(f.name);
  EXPECT_EQ(names, (std::vector<std::string>{"stability.md", "stability.json", "stability_chart.csv"}));
  ASSERT_EQ(r.report.charts.size(), 1u);
  EXPECT_EQ(r.report.charts[0].name, "stability.png");
  EXPECT_NE(r.report.files[0].text.find(r.markdown), std::string::npos);
  for (const char* key : {"\"cases\"", "\"measured_over_theory\"", "\"summary\"",
                          "\"explicit_euler_unstable_at_every_dt\": true"})
    EXPECT_NE(r.json.find(key), std::string::npos) << key;
  // The CSV: a header and one line per chart point (4 series x 2 stiffnesses).
  EXPECT_EQ(std::count(r.report.files[2].text.begin(), r.report.files[2].text.end(), '\n'), 1 + 4 * 2);
}

}  // namespace
}  // namespace tissue::studies
