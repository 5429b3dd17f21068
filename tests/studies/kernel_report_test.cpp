// Freude 2014's kernel tables: the normalisation of Table 6.3 (the largest RGB error = 1, each
// cell's channels summing to its bold sum), the thesis's sums beside the measured ones, and Table
// 6.5's rows, on made-up studies with known errors (the studies themselves are slow).
#include "tissue/studies/kernel_report.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

namespace tissue::studies {
namespace {

/// Studies of the report's materials whose errors are (1, 2, 3) x a, a distinct per material and model.
std::vector<KernelStudy> madeUpStudies() {
  std::vector<std::string> labels;
  for (const auto& spec : rankOneSpecs())
    labels.push_back(spec.label);
  for (int k = 1; k <= 6; ++k)
    labels.push_back("SVD " + std::to_string(k)), labels.push_back("d'Eon " + std::to_string(k));
  std::vector<KernelStudy> studies;
  double a = 1e-3;
  for (const char* name : kKernelReportMaterials) {
    KernelStudy s{name, 0.1, 100, {}, {}};
    for (const auto& label : labels) {
      KernelRun run;
      run.kernelRms = {a, 2 * a, 3 * a};
      for (const auto& [signal, unused] : kernelStudySignals())
        run.imageRms[signal] = {a / 2, a, 1.5 * a};
      s.runs[label] = run;
      a *= 1.01;
    }
    studies.push_back(s);
  }
  return studies;
}

struct Cell {
  double r = 0, g = 0, b = 0, sum = 0;
};
Cell parseCell(const std::string& text) {
  Cell c;
  EXPECT_EQ(std::sscanf(text.c_str(), "%lf %lf %lf (**%lf**", &c.r, &c.g, &c.b, &c.sum), 4) << text;
  return c;
}

TEST(KernelReport, Table63IsNormalisedToItsLargestErrorAndCellsSumAsTheThesis) {
  const auto studies = madeUpStudies();
  const double scale = kernelSpaceScale(studies);
  // The largest channel of the four thesis models: Wholemilk's (the last material) Manual, blue.
  EXPECT_DOUBLE_EQ(scale, studies.back().runs.at("Manual").kernelRms[2]);
  const Table t = kernelSpaceTable(studies, scale);
  ASSERT_EQ(t.rows.size(), kKernelReportMaterials.size());
  ASSERT_EQ(t.header.size(), 1u + 7u);
  double largest = 0;
  for (const auto& row : t.rows)
    for (std::size_t m = 1; m < row.size(); ++m) {
      const Cell c = parseCell(row[m]);
      EXPECT_NEAR(c.r + c.g + c.b, c.sum, 2e-3) << row[m];
      if (m <= 4) largest = std::max({largest, c.r, c.g, c.b});
      EXPECT_EQ(row[m].find("thesis") != std::string::npos, m <= 4) << row[m];
    }
  EXPECT_DOUBLE_EQ(largest, 1.0);
  // Skin1's SVD1 cell carries the thesis's 0.192.
  const auto skin =
      std::find_if(t.rows.begin(), t.rows.end(), [](const auto& row) { return row[0] == "Skin1"; });
  ASSERT_NE(skin, t.rows.end());
  EXPECT_NE((*skin)[1].find("thesis 0.192"), std::string::npos) << (*skin)[1];
}

TEST(KernelReport, Table65HasSixRanksWithTheThesisSums) {
  const auto studies = madeUpStudies();
  const double scale = rankScale(studies, "shaded patch");
  const Table t = rankTable(studies, "shaded patch", scale);
  ASSERT_EQ(t.rows.size(), 6u);
  ASSERT_EQ(t.header.size(), 5u + 4u);  // k, Skin1's two models and their thesis sums, four other materials
  double largest = 0;
  for (std::size_t k = 0; k < 6; ++k) {
    EXPECT_EQ(t.rows[k][2], fixed(kFreude2014Table65Svd[k]));
    EXPECT_EQ(t.rows[k][4], fixed(kFreude2014Table65Deon[k]));
    for (std::size_t col : {1u, 3u}) {
      const Cell c = parseCell(t.rows[k][col]);
      largest = std::max({largest, c.r, c.g, c.b});
    }
  }
  EXPECT_DOUBLE_EQ(largest, 1.0);
}

TEST(KernelReport, ThesisTablesCoverTheReportsMaterials) {
  for (std::size_t i = 0; i < kKernelReportMaterials.size(); ++i)
    EXPECT_STREQ(kFreude2014Table63[i].material, kKernelReportMaterials[i]);
  // Table 6.5: both kernel families improve with every added rank.
  for (std::size_t k = 1; k < 6; ++k) {
    EXPECT_LT(kFreude2014Table65Svd[k], kFreude2014Table65Svd[k - 1]);
    EXPECT_LT(kFreude2014Table65Deon[k], kFreude2014Table65Deon[k - 1]);
  }
}

TEST(KernelReport, NeedsSkin1) {
  EXPECT_FALSE(kernelReport({}));
}

}  // namespace
}  // namespace tissue::studies
