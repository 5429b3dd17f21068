#pragma once
/// \file
/// A ParaView time series of a simulated organ (SOFA's VTKExporter, frame by frame): a .pvd
/// collection and one VTK XML file per frame, every file and the collection written atomically
/// (a viewer opening the series mid-run never reads a half-written file).
///
/// Each frame is a .vtp for a surface-spring organ (points: the surface's vertices; cells: its
/// triangles) or a .vtu for a tet mesh or an embedded lattice (points: the simulated nodes, then,
/// for a lattice, the surface's vertices; cells: the tets or hexahedra, then the surface's
/// triangles). Point data: velocity_mm_per_s, stretch (mean L/L0), strain (stretch - 1),
/// contact_force_N, plane_normal, plane_offset_mm, plane_residual_mm, tangent (T, w), normal;
/// the surface arrays are 0 on a lattice's nodes. Cell data: strain (the mean over the cell's
/// points) and surface (1 for the surface's triangles, 0 for volume cells). The positions are
/// the points (mm).
///
/// A command writes one frame per loop iteration:
///   auto series = inspect::PvdSeries::create(dir);                    // once
///   series->addFrame(inspect::snapshotOf(loop.run(), loop.surface())); // every frame

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "tissue/core/result.h"
#include "tissue/inspect/organ_snapshot.h"

namespace tissue::inspect {

/// What one frame cost.
struct PvdFrameCost {
  double frameMs = 0.0;       ///< ms, the frame's VTK data set built and its file written
  double collectionMs = 0.0;  ///< ms, the .pvd rewritten
};

/// The series being written. Movable, not copyable.
class PvdSeries {
 public:
  /// A series `<dir>/<name>.pvd` with frames `<dir>/<name>_NNNNNN.vtp|vtu`. Creates `dir`;
  /// fails when it cannot, or when `name` is empty or has a path separator.
  static Result<PvdSeries> create(const std::filesystem::path& dir, const std::string& name = "organ");

  /// Writes `frame` as the next time step (at frame.timeS s) and rewrites the .pvd. Time steps
  /// must increase: a frame at or before the last one is an error (nothing written).
  Result<PvdFrameCost> addFrame(const OrganSnapshot& frame);

  const std::filesystem::path& pvdPath() const { return m_pvd; }
  std::size_t frameCount() const { return m_entries.size(); }
  /// The frame files written so far, in time order.
  std::vector<std::filesystem::path> framePaths() const;

 private:
  struct Entry {
    double timeS;
    std::string file;  ///< relative to the .pvd's folder
  };
  PvdSeries(std::filesystem::path dir, std::string name);
  std::filesystem::path m_dir;
  std::string m_name;
  std::filesystem::path m_pvd;
  std::vector<Entry> m_entries;
};

/// A series of a bare scenario run (what `tissue-sim simulate` has: a ScenarioRun without the
/// scene's loop). It keeps the run's surface in step itself (a mesh::DeformableSurface of
/// run.mesh().surface, updated with run.positions() each frame), so that every frame carries the
/// planes and tangents too. A surface without UVs (a tet mesh's boundary) gets the planar
/// projection (x, y) over its bounding box as UVs, so its tangents are that projection's frame.
class RunSeries {
 public:
  /// Starts `<dir>/<name>.pvd` for `run`. Fails on a bad folder or name, or when the surface
  /// cannot be built (an invalid mesh).
  static Result<RunSeries> create(const scenario::ScenarioRun& run, const std::filesystem::path& dir,
                                  const std::string& name = "organ");
  ~RunSeries();
  RunSeries(RunSeries&&) noexcept;
  RunSeries& operator=(RunSeries&&) noexcept;

  /// The frame `run` has just simulated: the surface updated, the snapshot taken, the file and
  /// the .pvd written (PvdSeries::addFrame).
  Result<PvdFrameCost> addFrame(const scenario::ScenarioRun& run);
  const PvdSeries& series() const { return m_series; }

 private:
  RunSeries(PvdSeries series, std::unique_ptr<mesh::DeformableSurface> surface);
  PvdSeries m_series;
  std::unique_ptr<mesh::DeformableSurface> m_surface;
};

/// Writes one frame on its own (.vtp or .vtu as the organ's kind; see the file comment).
/// `path`'s extension is replaced by the right one; returns the path written.
Result<std::filesystem::path> writeOrganFrame(const OrganSnapshot& frame, const std::filesystem::path& path);

}  // namespace tissue::inspect
