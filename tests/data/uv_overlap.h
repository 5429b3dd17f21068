#pragma once
/// \file
/// Exact checks of a UV atlas: triangles that overlap, and charts closer than a gutter.

#include <cstddef>
#include <vector>

#include "tissue/core/types.h"

namespace tissue::datatest {

/// A pair of UV triangles that violate the atlas rules.
struct UvConflict {
  std::size_t first = 0, second = 0;
  double separation = 0.0;  ///< largest separating gap found (UV units); <= 0 means overlap
};

/// Chart id per triangle: connected components of triangles sharing a `vt` index.
std::vector<int> uvCharts(const std::vector<Triangle>& uvTriangles, std::size_t uvCount);

/// Finds triangle pairs whose interiors overlap (same chart) or which are closer than `gutter`
/// (different charts). Separation is measured by the separating axis theorem on the six edge
/// normals: for two triangles with disjoint interiors one of them separates them, and the gap
/// along it never exceeds the true distance, so the gutter check is conservative. Candidates come
/// from a uniform grid over [0, 1]^2. Returns at most `maxConflicts` conflicts.
std::vector<UvConflict> findUvConflicts(const std::vector<Float2>& uvs,
                                        const std::vector<Triangle>& uvTriangles, double gutter,
                                        std::size_t maxConflicts = 10);

}  // namespace tissue::datatest
