#pragma once
/// \file
/// Full versus incremental re-fit of the local planes (François 2009 §2.2) between a rest shape
/// and a deformed one: the time of each, the share of planes the incremental fitter re-fits, and
/// the largest deviation of its planes (exact, and with a normal-error bound) from a full re-fit.
/// GL-free. Lengths in mm, angles in rad, times in ms (medians over the repeats).

#include <array>
#include <span>
#include <string>
#include <vector>

#include "tissue/core/result.h"
#include "tissue/core/types.h"
#include "tissue/mesh/load_mesh.h"
#include "tissue/mesh/local_planes.h"
#include "tissue/scenario/scenario.h"

namespace tissue::studies {

/// One re-fit variant against the full re-fit of the deformed shape.
struct RefitVariant {
  double refittedFraction = 0.0;       ///< planes re-fitted / vertices, the last deformed update
  double refitMs = 0.0;                ///< ms, median
  double maxNormalDeviationRad = 0.0;  ///< rad, over the repeats
  double maxOffsetDeviationMm = 0.0;   ///< mm, over the repeats
};

struct RefitComparison {
  double movedFraction = 0.0;  ///< vertices the deformation moved / vertices
  double fullRefitMs = 0.0;    ///< ms, median of fitVertexPlanes over the whole mesh
  RefitVariant exact;          ///< the incremental fitter without a bound (must match the full re-fit)
  RefitVariant tolerant;       ///< the incremental fitter with the `refit` bound
  double speedup() const { return fullRefitMs / (exact.refitMs > 1e-9 ? exact.refitMs : 1e-9); }
};

/// Times full and incremental re-fits between `rest` and `deformed` (same triangles), `repeats`
/// times, alternating back to rest (untimed) so each incremental update moves the same vertices.
RefitComparison compareRefits(std::span<const Float3> rest, std::span<const Float3> deformed,
                              std::span<const Triangle> triangles, const mesh::PlaneFitSettings& settings,
                              int repeats, const mesh::PlaneRefitSettings& refit);

/// Per-frame figures of one incrementally re-fitted surface under the simulator.
struct RefitSeries {
  double maxNormalErrorRad = 0.0;     ///< rad, its bound (0: exact)
  double meanRefittedFraction = 0.0;  ///< planes re-fitted / vertices, mean over frames
  double planesMsMedian = 0.0, planesMsP99 = 0.0, planesMsMax = 0.0;  ///< ms per frame
  double maxNormalDeviationRad = 0.0;  ///< rad, against the full re-fit, over all frames
  double maxOffsetDeviationMm = 0.0;   ///< mm, the same
};

/// The vertex displacement steps the scenario study counts (mm).
inline constexpr std::array<float, 5> kRefitMotionStepsMm = {1e-5f, 1e-4f, 1e-3f, 1e-2f, 1e-1f};

struct ScenarioRefitStudy {
  std::size_t vertices = 0;
  int frames = 0;
  double meanChangedVertexFraction = 0.0;  ///< vertices whose position changed at all, per frame
  /// Per step of kRefitMotionStepsMm: the fraction of vertices moving farther per frame, mean.
  std::array<double, kRefitMotionStepsMm.size()> meanFractionBeyond{};
  /// theta x the tolerant fitter's per-vertex tolerance (mm per rad): p10, median, p90, mm.
  double toleranceMmP10 = 0.0, toleranceMmMedian = 0.0, toleranceMmP90 = 0.0;
  double normalsMsMedian = 0.0, tangentsMsMedian = 0.0;  ///< ms per frame, the tolerant surface
  double fullRefitMsMedian = 0.0;  ///< ms per frame: normals and every plane from scratch
  RefitSeries exact, tolerant;
};

/// The simulator runs `scenario` for `frames` frames and drives two surfaces made from `mesh`
/// (the scenario's shaded mesh, same vertices as the simulated one): the exact re-fit (bound
/// 0) and the tolerant one (bound `maxNormalErrorRad`); each frame both are compared with a full
/// re-fit of the simulated positions. Fails when the meshes' vertex counts differ.
Result<ScenarioRefitStudy> studyRefitUnderScenario(const scenario::Scenario& scenario,
                                                   const SurfaceMesh& mesh,
                                                   const mesh::PlaneFitSettings& settings,
                                                   double maxNormalErrorRad, int frames);

/// `tissue-sim refit-bench --mesh`: compareRefits after a local poke (the `pokeFraction` of the
/// vertices nearest the top pushed in by 3% of the mesh's extent) and after a global bend (5%).
struct MeshRefitBench {
  std::size_t vertices = 0;
  mesh::PlaneFitSettings settings;
  double meanNeighbourhood = 0;  ///< vertices per neighbourhood sphere; hundreds: is the mesh in mm?
  int repeats = 0;               ///< of the poke; the bend max(3, repeats / 4)
  RefitComparison poke{}, bend{};
  double maxNormalErrorRad = 0;  ///< rad, the tolerant re-fit's bound
};
/// `repeats` 0: 2e6 / vertices, clamped to 5..200.
/// `rest` and `triangles`: the mesh's geometric vertices (mesh::geometricPositionsOf), mm.
MeshRefitBench benchRefitOnMesh(std::span<const Float3> rest, std::span<const Triangle> triangles,
                                const mesh::PlaneFitSettings& settings, double pokeFraction, int repeats,
                                const mesh::PlaneRefitSettings& refit);

/// As JSON text: the poke's comparison at the top level (moved_fraction, refitted_fraction,
/// full_refit_ms, incremental_refit_ms, speedup, max_normal_deviation_rad,
/// max_offset_deviation_mm, tolerant), the bend's as "global", and vertices, radius_mm,
/// sigma_t_per_mm, epsilon, mean_neighbourhood, repeats.
std::string meshRefitBenchJson(const MeshRefitBench& bench);

/// The scenario study as JSON text: vertices, frames, mean_changed_vertex_fraction,
/// mean_fraction_moving_per_frame_beyond, plane_tolerance_mm, normals_ms_median,
/// tangents_ms_median, full_refit_ms_median, exact, tolerant.
std::string scenarioRefitJson(const ScenarioRefitStudy& study);

}  // namespace tissue::studies
