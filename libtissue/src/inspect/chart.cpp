// Charts through VTK's chart module. Debian's VTK 9.1 renders only through X (no EGL/OSMesa
// build), so the render window gets a Display* from XDisplay: $DISPLAY or a private Xvfb.
#include "tissue/inspect/chart.h"

#include <algorithm>

#include <vtkAxis.h>
#include <vtkChartLegend.h>
#include <vtkChartXY.h>
#include <vtkContextScene.h>
#include <vtkContextView.h>
#include <vtkDoubleArray.h>
#include <vtkNew.h>
#include <vtkPlot.h>
#include <vtkPlotLine.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkTable.h>
#include <vtkTextProperty.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "tissue/core/atomic_file.h"
#include "vtk_io.h"
#include "x_display.h"

namespace tissue::inspect {
namespace {

/// Tableau 10: distinguishable on white and for the common colour-vision deficiencies.
constexpr std::array<std::array<unsigned char, 3>, 10> kPalette{{{31, 119, 180},
                                                                 {255, 127, 14},
                                                                 {44, 160, 44},
                                                                 {214, 39, 40},
                                                                 {148, 103, 189},
                                                                 {140, 86, 75},
                                                                 {227, 119, 194},
                                                                 {127, 127, 127},
                                                                 {188, 189, 34},
                                                                 {23, 190, 207}}};

Result<void> validate(const std::filesystem::path& png, const ChartSettings& settings,
                      std::span<const ChartSeries> series) {
  const std::string where = "chart " + png.string() + ": ";
  if (settings.widthPx < 64 || settings.widthPx > 8192 || settings.heightPx < 64 || settings.heightPx > 8192)
    return Error{where + "size " + std::to_string(settings.widthPx) + "x" +
                 std::to_string(settings.heightPx) +
                 " px is outside 64..8192; pass a sensible ChartSettings::widthPx/heightPx"};
  if (series.empty()) return Error{where + "no series to draw; pass at least one ChartSeries"};
  for (const ChartSeries& s : series) {
    const std::string what = where + "series '" + s.label + "': ";
    if (s.x.empty() || s.x.size() != s.y.size())
      return Error{what + std::to_string(s.x.size()) + " x values and " + std::to_string(s.y.size()) +
                   " y values; give one x per y, at least one point"};
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i]))
        return Error{what + "point " + std::to_string(i) + " is not finite; drop it or replace it"};
      if ((settings.logX && s.x[i] <= 0.0) || (settings.logY && s.y[i] <= 0.0))
        return Error{what + "point " + std::to_string(i) +
                     " is not positive on a logarithmic axis; use a linear axis or drop it"};
    }
  }
  return {};
}

vtkSmartPointer<vtkTable> seriesTable(const ChartSeries& s) {
  auto table = vtkSmartPointer<vtkTable>::New();
  vtkNew<vtkDoubleArray> x, y;
  x->SetName("x");
  y->SetName(s.label.empty() ? "y" : s.label.c_str());
  table->AddColumn(x);
  table->AddColumn(y);
  table->SetNumberOfRows(static_cast<vtkIdType>(s.x.size()));
  for (std::size_t i = 0; i < s.x.size(); ++i) {
    table->SetValue(static_cast<vtkIdType>(i), 0, s.x[i]);
    table->SetValue(static_cast<vtkIdType>(i), 1, s.y[i]);
  }
  return table;
}

// The axis's range from the data with a margin. VTK's automatic range for values within ~0.1 % of
// each other on a log axis draws the ticks and no point (seen on the atlas's close-up frame,
// every method within noise of the others), so the range is set here: the data's span plus 5 %
// each side, and at least +-5 % of the mean (a factor 1.1 on a log axis) so that near-equal
// values sit mid-plot.
void fixRange(vtkAxis* axis, std::span<const ChartSeries> series, bool yAxis, bool log) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const ChartSeries& s : series)
    for (double v : yAxis ? s.y : s.x) {
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
  if (!(lo <= hi)) return;
  if (log) {
    double a = std::log10(lo), b = std::log10(hi);
    const double pad = std::max(0.05 * (b - a), std::log10(1.1) - 0.5 * (b - a));
    axis->SetUnscaledRange(std::pow(10.0, a - pad), std::pow(10.0, b + pad));
  } else {
    const double pad =
        std::max(0.05 * (hi - lo), 0.05 * std::max(std::abs(lo), std::abs(hi)) - 0.5 * (hi - lo));
    axis->SetUnscaledRange(lo - (pad > 0.0 ? pad : 1.0), hi + (pad > 0.0 ? pad : 1.0));
  }
  axis->SetBehavior(vtkAxis::FIXED);
}

void styleAxis(vtkAxis* axis, const std::string& title, bool log) {
  axis->SetTitle(title);
  axis->SetLogScale(log);
  axis->GetTitleProperties()->SetFontSize(16);
  axis->GetLabelProperties()->SetFontSize(13);
}

}  // namespace

Result<void> writeLineChart(const std::filesystem::path& png, const ChartSettings& settings,
                            std::span<const ChartSeries> series) {
  if (auto valid = validate(png, settings, series); !valid) return valid;
  auto display = XDisplay::open();
  if (!display) return Error{"chart " + png.string() + ": " + display.error().message};

  // Scene: one XY chart with a legend, white background.
  vtkNew<vtkContextView> view;
  vtkRenderWindow* window = view->GetRenderWindow();
  window->SetDisplayId(display->displayId());
  window->SetOffScreenRendering(1);
  window->SetSize(settings.widthPx, settings.heightPx);
  view->GetRenderer()->SetBackground(1.0, 1.0, 1.0);
  vtkNew<vtkChartXY> chart;
  view->GetScene()->AddItem(chart);
  chart->SetTitle(settings.title);
  chart->GetTitleProperties()->SetFontSize(18);
  chart->SetShowLegend(true);
  chart->GetLegend()->GetLabelProperties()->SetFontSize(13);
  if (settings.legendOutside) {
    // A right margin as wide as the legend (about 8 px per character at 13 pt, plus the swatch),
    // and the legend placed in it, outside the plot area.
    std::size_t longest = 0;
    for (const auto& s : series)
      longest = std::max(longest, s.label.size());
    const int margin = std::min(settings.widthPx / 2, 60 + 8 * static_cast<int>(longest));
    chart->SetAutoSize(true);
    chart->SetBorders(70, 60, margin, 50);
    chart->GetLegend()->SetInline(false);
    chart->GetLegend()->SetHorizontalAlignment(vtkChartLegend::RIGHT);
    chart->GetLegend()->SetVerticalAlignment(vtkChartLegend::TOP);
  }
  styleAxis(chart->GetAxis(vtkAxis::BOTTOM), settings.xLabel, settings.logX);
  styleAxis(chart->GetAxis(vtkAxis::LEFT), settings.yLabel, settings.logY);
  fixRange(chart->GetAxis(vtkAxis::BOTTOM), series, false, settings.logX);
  fixRange(chart->GetAxis(vtkAxis::LEFT), series, true, settings.logY);

  // Series: the tables must live until the render.
  std::vector<vtkSmartPointer<vtkTable>> tables;
  for (std::size_t k = 0; k < series.size(); ++k) {
    tables.push_back(seriesTable(series[k]));
    // A line needs two points (VTK logs an error for one): a single point is drawn as a marker.
    const bool line = series[k].lines && series[k].x.size() >= 2;
    vtkPlot* plot = chart->AddPlot(line ? vtkChart::LINE : vtkChart::POINTS);
    plot->SetInputData(tables.back(), 0, 1);
    const auto& c = kPalette[k % kPalette.size()];
    plot->SetColor(c[0], c[1], c[2], 255);
    plot->SetWidth(line ? 2.5f : 1.0f);
    if (auto* l = vtkPlotLine::SafeDownCast(plot)) l->SetMarkerStyle(vtkPlotPoints::CIRCLE);
  }

  // Render, grab the back buffer, encode PNG in memory, write atomically.
  const auto bytes = renderToPng(window);
  window->Finalize();
  if (bytes.empty())
    return Error{"chart " + png.string() + ": VTK produced no image; check the X display (Xvfb) works"};
  return writeFileAtomic(png, bytes);
}

}  // namespace tissue::inspect
