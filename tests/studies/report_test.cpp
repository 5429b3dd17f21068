// Study reports: Markdown and CSV tables, number formats, and the folder written atomically.
#include "tissue/studies/report.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "tissue/core/atomic_file.h"

namespace tissue::studies {
namespace {

TEST(Report, MarkdownTableHasHeaderRuleAndPaddedRows) {
  const Table t{{"a", "b", "c"}, {{"1", "2", "3"}, {"x"}}};
  EXPECT_EQ(markdownTable(t), "| a | b | c |\n|---|---|---|\n| 1 | 2 | 3 |\n| x |  |  |\n");
}

TEST(Report, CsvQuotesCellsWithCommasQuotesAndNewlines) {
  const Table t{{"name", "value"}, {{"Apple, red", "say \"hi\""}, {"two\nlines", "3"}}};
  EXPECT_EQ(csvTable(t), "name,value\n\"Apple, red\",\"say \"\"hi\"\"\"\n\"two\nlines\",3\n");
}

TEST(Report, NumberFormats) {
  EXPECT_EQ(fixed(3.14159, 2), "3.14");
  EXPECT_EQ(general(0.000123456, 3), "0.000123");
  EXPECT_EQ(fixed(std::nan("")), "-");
  EXPECT_EQ(general(std::nan("")), "-");
}

TEST(Report, WritesEveryFileIntoANewFolder) {
  const auto dir = std::filesystem::temp_directory_path() / "tissue_report_test" / "nested";
  std::filesystem::remove_all(dir.parent_path());
  Report r;
  r.add("a.md", "# A\n");
  r.add("a.csv", "x,y\n1,2\n");
  ASSERT_TRUE(writeReport(dir, r));
  auto md = readTextFile(dir / "a.md");
  auto csv = readTextFile(dir / "a.csv");
  ASSERT_TRUE(md && csv);
  EXPECT_EQ(*md, "# A\n");
  EXPECT_EQ(*csv, "x,y\n1,2\n");
  std::filesystem::remove_all(dir.parent_path());
}

TEST(Report, ABadChartFailsNamingItAfterTheTextFiles) {
  const auto dir = std::filesystem::temp_directory_path() / "tissue_report_chart_test";
  std::filesystem::remove_all(dir);
  Report r;
  r.add("kept.md", "kept\n");
  r.charts.push_back({"bad.png", {.title = "empty", .xLabel = {}, .yLabel = {}}, {}});  // no series: refused
  auto ok = writeReport(dir, r);
  ASSERT_FALSE(ok);
  EXPECT_NE(ok.error().message.find("bad.png"), std::string::npos) << ok.error().message;
  EXPECT_TRUE(std::filesystem::exists(dir / "kept.md"));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace tissue::studies
