#pragma once
/// \file
/// Charts through VTK's chart module (vtkChartXY), written as PNG for reports and docs/.
/// VTK stays inside src/inspect; this header speaks plain arrays. Debian's VTK renders only
/// through X, so when no X display can be opened a private Xvfb is started for the call and
/// stopped after it (see x_display.h).

#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "tissue/core/result.h"

namespace tissue::inspect {

/// One data series: points (x[i], y[i]) in the units named by the chart's axis labels.
struct ChartSeries {
  std::string label;      ///< legend entry
  std::vector<double> x;  ///< abscissae; as many as y
  std::vector<double> y;  ///< ordinates; as many as x
  bool lines = true;      ///< connect the points with lines; false: points only (a scatter)
};

/// What surrounds the series.
struct ChartSettings {
  std::string title;   ///< above the plot
  std::string xLabel;  ///< with its unit, e.g. "time step h (ms)"
  std::string yLabel;  ///< with its unit
  bool logX = false;   ///< logarithmic x axis (every x must be > 0)
  bool logY = false;   ///< logarithmic y axis (every y must be > 0)
  int widthPx = 900;   ///< image width, pixels
  int heightPx = 600;  ///< image height, pixels
  /// Draw the legend in a margin right of the plot, so that it never covers the data (the
  /// margin is sized from the longest label); false: inside the plot's top right corner.
  bool legendOutside = true;
};

/// Draws `series` as an XY chart with a legend into `png`, written atomically. Fails (never
/// aborts) on empty or mismatched series, non-finite values, non-positive values on a log axis,
/// a size outside 64..8192 pixels, or when neither an X display nor Xvfb is available.
Result<void> writeLineChart(const std::filesystem::path& png, const ChartSettings& settings,
                            std::span<const ChartSeries> series);

}  // namespace tissue::inspect
