#pragma once
/// \file
/// Private: one inspection view as VTK draws it. A data set coloured by one of its arrays
/// through a lookup table with a colour bar (title with units), optional grey context geometry
/// and fixed-colour overlays (glyph line sets, an arrow, markers), framed by a camera that
/// looks at the data from above and the side. Rendered offscreen into PNG bytes, or shown in
/// an interactive window.

#include <vtkSmartPointer.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "tissue/core/result.h"

class vtkPolyData;

namespace tissue::inspect {

/// Geometry drawn in one colour (glyph lines, an arrow, marker spheres).
struct ViewOverlay {
  vtkSmartPointer<vtkPolyData> geometry;
  std::array<double, 3> rgb{0, 0, 0};  ///< 0..1
  float lineWidth = 2.0f;              ///< px
  float pointSize = 1.0f;              ///< px (vertices drawn as points)
  double opacity = 1.0;                ///< 0..1
  std::string legend;                  ///< a line of the legend text ("" none)
};

/// Everything one view draws.
struct ViewScene {
  std::string title;                      ///< above the image
  vtkSmartPointer<vtkPolyData> data;      ///< coloured by `array`
  std::string array;                      ///< point (or cell) array to colour by
  bool cellArray = false;                 ///< `array` is cell data
  std::array<double, 2> range{0.0, 1.0};  ///< colour range
  /// The colour map: viridis (sequential), cool-warm (diverging, symmetric data) or two-tone
  /// (gold at the low end, light grey at the high end: a sign such as handedness, under glyphs).
  enum class Palette { Viridis, CoolWarm, TwoTone } palette = Palette::Viridis;
  std::string barTitle;                  ///< the colour bar's title, with the unit
  bool tubes = false;                    ///< draw `data`'s lines as tubes
  double tubeRadius = 0.3;               ///< mm
  vtkSmartPointer<vtkPolyData> context;  ///< drawn grey and translucent beneath (may be null)
  std::vector<ViewOverlay> overlays;
};

/// Image size of a view, pixels.
struct ViewImage {
  int widthPx = 1000;
  int heightPx = 750;
};

/// Renders `scene` offscreen (on `displayId`, an Xlib Display*) and returns PNG bytes.
Result<std::vector<std::uint8_t>> renderViewPng(const ViewScene& scene, const ViewImage& size,
                                                void* displayId);

/// Shows `scene` in an on-screen window (on `displayId`) until the user closes it.
Result<void> showViewWindow(const ViewScene& scene, const ViewImage& size, void* displayId);

}  // namespace tissue::inspect
