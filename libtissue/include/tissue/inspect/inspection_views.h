#pragma once
/// \file
/// Inspection views of one frame of a simulated organ: the fields that its shading and its
/// forces depend on, each drawn by VTK as a PNG (offscreen, colour bar with title and unit)
/// and written as a .vtp with the same arrays, so ParaView shows the same thing. The anchors
/// are SOFA's VTKExporter and iMSTK's VTK views. Without VTK every call is one Error.
///
///   spring_strain    the springs as lines (tubes when few), cell data strain L/L0 - 1
///   vertex_stretch   the surface, mean L/L0 of each vertex's springs
///   contact_force    the force each vertex passes the tool (N), the tool's force as an arrow
///   plane_fit        local planes (François et al. 2006 eq. 14): N_S glyphs, residual in mm
///   tangent_frames   T, B, N glyphs (red, green, blue), handedness flips at UV seams marked
///   texture_stretch  texture-space stretch per triangle (d'Eon et al. 2007 §3.2), 1 = mean
///   truth_error      the per-vertex error against the path-traced truth (TruthErrorMap hook)
///
/// VTK draws through X (Debian's build): $DISPLAY when it opens, else a private Xvfb.

#include <filesystem>
#include <string>
#include <vector>

#include "tissue/core/result.h"
#include "tissue/inspect/organ_snapshot.h"

namespace tissue::inspect {

/// The views (a closed set).
enum class InspectionView {
  SpringStrain,
  VertexStretch,
  ContactForce,
  PlaneFit,
  TangentFrames,
  TextureStretch
};

/// All of them, in the order above (truth_error only with a TruthErrorMap).
inline constexpr InspectionView kInspectionViews[] = {
    InspectionView::SpringStrain, InspectionView::VertexStretch, InspectionView::ContactForce,
    InspectionView::PlaneFit,     InspectionView::TangentFrames, InspectionView::TextureStretch};

/// The file stem of a view ("spring_strain", ...).
std::string viewName(InspectionView view);

/// How views are drawn (plain struct with defaults).
struct ViewSettings {
  int widthPx = 1000;            ///< PNG width, pixels (64..8192)
  int heightPx = 750;            ///< PNG height, pixels (64..8192)
  std::size_t maxGlyphs = 1500;  ///< glyphs per set at most (every k-th vertex beyond)
  std::size_t maxTubes = 20000;  ///< springs drawn as tubes up to this many, else as lines
};

/// What one view wrote.
struct WrittenView {
  std::string name;            ///< viewName
  std::filesystem::path png;   ///< the image
  std::filesystem::path data;  ///< the .vtp with the view's arrays
  double renderMs = 0.0;       ///< ms to build, draw and encode the image
  double writeMs = 0.0;        ///< ms to write the .vtp
};

/// The hook for the per-pixel error against the path-traced truth (tissue::truth). Whoever
/// holds the truth's texture atlas maps each texel's error onto the render vertices (e.g. the
/// mean over the texels of each vertex's one-ring in UV space) and passes it here; the view
/// then draws it on the mesh like the others. Nothing in this module computes it.
struct TruthErrorMap {
  std::vector<float> perRenderVertex;  ///< #R, in `unit`
  std::string quantity = "error";      ///< e.g. "relative luminance error"
  std::string unit = "unitless";       ///< e.g. "unitless", "%"
};

/// Writes one view of `frame` into `dir` (<name>.png, <name>.vtp), atomically.
Result<WrittenView> writeInspectionView(const OrganSnapshot& frame, InspectionView view,
                                        const std::filesystem::path& dir, const ViewSettings& settings = {});
/// The truth-error view (truth_error.png, .vtp). Fails when the map has not #R values.
Result<WrittenView> writeTruthErrorView(const OrganSnapshot& frame, const TruthErrorMap& error,
                                        const std::filesystem::path& dir, const ViewSettings& settings = {});
/// Every view of kInspectionViews, and truth_error when `truthError` is given, on one display.
Result<std::vector<WrittenView>> writeInspectionViews(const OrganSnapshot& frame,
                                                      const std::filesystem::path& dir,
                                                      const ViewSettings& settings = {},
                                                      const TruthErrorMap* truthError = nullptr);

/// Opens `view` of `frame` in an interactive VTK window (rotate, zoom) until the user closes it.
/// Needs a display ($DISPLAY); fails, saying so, without one. Blocks the caller meanwhile.
Result<void> showInspectionWindow(const OrganSnapshot& frame, InspectionView view,
                                  const ViewSettings& settings = {});

/// Whether an X display can be opened ($DISPLAY): where the viewer opens a window instead of
/// writing files.
bool hasDisplay();

}  // namespace tissue::inspect
