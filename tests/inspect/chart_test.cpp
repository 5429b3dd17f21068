// The chart writer: a real PNG of the requested size showing each series in its palette
// colour, and one clear error for each kind of bad input (never an abort).
#include "tissue/inspect/chart.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>

#include "tissue/core/image.h"

namespace {

namespace fs = std::filesystem;
using tissue::inspect::ChartSeries;
using tissue::inspect::ChartSettings;
using tissue::inspect::writeLineChart;

fs::path outDir() {
  fs::path dir = fs::path(TISSUE_TEST_OUTPUT_DIR) / "inspect";
  fs::create_directories(dir);
  return dir;
}

/// Pixels within `tol` of an RGB colour, in columns [0, maxX) (default: all).
int countColour(const tissue::Image8& image, int r, int g, int b, int tol, int maxX = -1) {
  int n = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < (maxX < 0 ? image.width : maxX); ++x) {
      const auto* p = image.at(x, y);
      if (std::abs(p[0] - r) <= tol && std::abs(p[1] - g) <= tol && std::abs(p[2] - b) <= tol) ++n;
    }
  return n;
}

TEST(Chart, WritesPngOfRequestedSizeWithEachSeriesInItsColour) {
  ChartSeries line{"sine", {}, {}, true};
  ChartSeries scatter{"squares", {}, {}, false};
  for (int i = 1; i <= 40; ++i) {
    line.x.push_back(i);
    line.y.push_back(2.0 + std::sin(i * 0.3));
    scatter.x.push_back(i);
    scatter.y.push_back(0.01 * i * i);
  }
  ChartSettings settings{"test chart", "x (mm)", "y (unitless)", false, false, 640, 400};
  const fs::path png = outDir() / "chart.png";
  fs::remove(png);
  const ChartSeries both[] = {line, scatter};
  auto written = writeLineChart(png, settings, both);
  ASSERT_TRUE(written.ok()) << written.error().message;
  auto image = tissue::readImage(png, 3);
  ASSERT_TRUE(image.ok()) << image.error().message;
  EXPECT_EQ(image->width, 640);
  EXPECT_EQ(image->height, 400);
  // Mostly white background, the first series blue (31,119,180), the second orange (255,127,14).
  EXPECT_GT(countColour(*image, 255, 255, 255, 2), 640 * 400 / 2);
  EXPECT_GT(countColour(*image, 31, 119, 180, 30), 100);
  EXPECT_GT(countColour(*image, 255, 127, 14, 30), 20);
}

TEST(Chart, LogAxesAccepted) {
  ChartSeries s{"power law", {1, 10, 100, 1000}, {1, 0.1, 0.01, 0.001}, true};
  ChartSettings settings{"log-log", "springs", "ms", true, true, 400, 300};
  auto written = writeLineChart(outDir() / "chart_log.png", settings, std::span(&s, 1));
  EXPECT_TRUE(written.ok()) << written.error().message;
}

// The atlas's close-up frame: every point within 0.1 % of the others on log axes. VTK's own
// range for so narrow a spread drew the axis and no point (the main job's atlas_close-up.png).
TEST(Chart, PointsWithinATenthOfAPercentStillShowOnLogAxes) {
  ChartSeries points{
      "points", {16.9, 18.2, 20.6, 51.0, 277.6}, {0.8771, 0.8773, 0.8772, 0.8771, 0.8769}, false};
  ChartSeries front{"front", {16.9, 51.0, 277.6}, {0.8771, 0.8771, 0.8769}, true};
  ChartSettings settings{"narrow", "ms", "rel RMS", true, true, 640, 400};
  const fs::path png = outDir() / "chart_narrow.png";
  const ChartSeries both[] = {points, front};
  auto written = writeLineChart(png, settings, both);
  ASSERT_TRUE(written.ok()) << written.error().message;
  auto image = tissue::readImage(png, 3);
  ASSERT_TRUE(image.ok()) << image.error().message;
  // Left of the legend (which holds both colours whatever the plot shows).
  EXPECT_GT(countColour(*image, 31, 119, 180, 30, 500), 20);   // the points, blue
  EXPECT_GT(countColour(*image, 255, 127, 14, 30, 500), 100);  // the front's line, orange
}

TEST(Chart, BadInputGivesOneClearError) {
  const fs::path png = outDir() / "bad.png";
  ChartSettings settings;
  auto none = writeLineChart(png, settings, {});
  ASSERT_FALSE(none.ok());
  EXPECT_NE(none.error().message.find("no series"), std::string::npos);

  ChartSeries mismatched{"m", {1, 2}, {1}, true};
  auto m = writeLineChart(png, settings, std::span(&mismatched, 1));
  ASSERT_FALSE(m.ok());
  EXPECT_NE(m.error().message.find("'m'"), std::string::npos);

  ChartSeries nan{"n", {1, 2}, {1, std::nan("")}, true};
  EXPECT_FALSE(writeLineChart(png, settings, std::span(&nan, 1)).ok());

  ChartSeries negative{"neg", {1, 2}, {-1, 1}, true};
  ChartSettings logY = settings;
  logY.logY = true;
  auto l = writeLineChart(png, logY, std::span(&negative, 1));
  ASSERT_FALSE(l.ok());
  EXPECT_NE(l.error().message.find("logarithmic"), std::string::npos);

  ChartSettings tiny = settings;
  tiny.widthPx = 3;
  ChartSeries ok{"ok", {1}, {1}, true};
  EXPECT_FALSE(writeLineChart(png, tiny, std::span(&ok, 1)).ok());
  EXPECT_FALSE(fs::exists(png));
}

}  // namespace
