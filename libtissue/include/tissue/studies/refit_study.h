#pragma once
/// \file
/// Full versus incremental re-fit of the local planes (François 2009 §2.2) between a rest shape
/// and a deformed one: the time of each, the share of planes the incremental fitter re-fits, and
/// the largest deviation of its planes (exact, and with a normal-error bound) from a full re-fit.
/// GL-free. Lengths in mm, angles in rad, times in ms (medians over the repeats).

#include <span>

#include "tissue/core/types.h"
#include "tissue/mesh/local_planes.h"

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

}  // namespace tissue::studies
