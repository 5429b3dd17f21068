// The inspection views: each builds a VTK scene from the snapshot's plain arrays (view_scenes.cpp)
// and writes it as PNG and .vtp; or shows it in a window.
#include "tissue/inspect/inspection_views.h"

#include <X11/Xlib.h>
#include <vtkPolyData.h>

#include "tissue/core/atomic_file.h"
#include "tissue/core/stopwatch.h"
#include "view_render.h"
#include "view_scenes.h"
#include "vtk_io.h"
#include "x_display.h"

namespace tissue::inspect {
namespace {

Result<void> checkSettings(const ViewSettings& s) {
  if (s.widthPx < 64 || s.widthPx > 8192 || s.heightPx < 64 || s.heightPx > 8192)
    return Error{"inspection view size " + std::to_string(s.widthPx) + "x" + std::to_string(s.heightPx) +
                 " px is outside 64..8192; pass a sensible ViewSettings::widthPx/heightPx"};
  if (s.maxGlyphs == 0) return Error{"ViewSettings::maxGlyphs is 0; allow at least one glyph per set"};
  return {};
}

Result<WrittenView> writeScene(const ViewScene& scene, const std::string& name,
                               const std::filesystem::path& dir, const ViewSettings& settings,
                               const XDisplay& display) {
  WrittenView out{name, dir / (name + ".png"), dir / (name + ".vtp")};
  Stopwatch draw;
  auto png = renderViewPng(scene, {settings.widthPx, settings.heightPx}, display.displayId());
  if (!png) return png.error();
  if (auto w = writeFileAtomic(out.png, *png); !w) return w.error();
  out.renderMs = draw.elapsedMs();
  Stopwatch write;
  if (auto w = writeXmlAtomic(scene.data, out.data); !w) return w.error();
  out.writeMs = write.elapsedMs();
  return out;
}

}  // namespace

Result<WrittenView> writeInspectionView(const OrganSnapshot& frame, InspectionView view,
                                        const std::filesystem::path& dir, const ViewSettings& settings) {
  if (auto ok = checkSettings(settings); !ok) return ok.error();
  auto scene = buildViewScene(frame, view, settings);
  if (!scene) return scene.error();
  auto display = XDisplay::open();
  if (!display) return Error{"inspection view " + viewName(view) + ": " + display.error().message};
  return writeScene(*scene, viewName(view), dir, settings, *display);
}

Result<WrittenView> writeTruthErrorView(const OrganSnapshot& frame, const TruthErrorMap& error,
                                        const std::filesystem::path& dir, const ViewSettings& settings) {
  if (auto ok = checkSettings(settings); !ok) return ok.error();
  auto scene = buildTruthErrorScene(frame, error);
  if (!scene) return scene.error();
  auto display = XDisplay::open();
  if (!display) return Error{"inspection view truth_error: " + display.error().message};
  return writeScene(*scene, "truth_error", dir, settings, *display);
}

Result<std::vector<WrittenView>> writeInspectionViews(const OrganSnapshot& frame,
                                                      const std::filesystem::path& dir,
                                                      const ViewSettings& settings,
                                                      const TruthErrorMap* truthError) {
  if (auto ok = checkSettings(settings); !ok) return ok.error();
  auto display = XDisplay::open();  // one display (one Xvfb at most) for all views
  if (!display) return Error{"inspection views: " + display.error().message};
  std::vector<WrittenView> written;
  for (InspectionView view : kInspectionViews) {
    auto scene = buildViewScene(frame, view, settings);
    if (!scene) return scene.error();
    auto w = writeScene(*scene, viewName(view), dir, settings, *display);
    if (!w) return w.error();
    written.push_back(*w);
  }
  if (truthError) {
    auto scene = buildTruthErrorScene(frame, *truthError);
    if (!scene) return scene.error();
    auto w = writeScene(*scene, "truth_error", dir, settings, *display);
    if (!w) return w.error();
    written.push_back(*w);
  }
  return written;
}

Result<void> showInspectionWindow(const OrganSnapshot& frame, InspectionView view,
                                  const ViewSettings& settings) {
  if (auto ok = checkSettings(settings); !ok) return ok.error();
  if (!hasDisplay())
    return Error{"inspection window: no X display (DISPLAY unset or unreachable); write the views instead"};
  auto scene = buildViewScene(frame, view, settings);
  if (!scene) return scene.error();
  auto display = XDisplay::open();
  if (!display) return Error{"inspection window: " + display.error().message};
  return showViewWindow(*scene, {settings.widthPx, settings.heightPx}, display->displayId());
}

bool hasDisplay() {
  Display* display = XOpenDisplay(nullptr);  // Xlib reads DISPLAY; the library does not
  if (!display) return false;
  XCloseDisplay(display);
  return true;
}

}  // namespace tissue::inspect
