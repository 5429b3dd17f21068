#pragma once
// Validation shared by the loader and validateMesh(): every defect becomes one Error that
// names the source and the element (1-based, as a person counts in the file).

#include <functional>
#include <span>
#include <string>

#include "tissue/core/result.h"
#include "tissue/core/types.h"

namespace tissue::mesh::detail {

/// Names triangle t for an error message ("face 12", or "face 12 (triangle 2 of its fan)").
using TriangleLabel = std::function<std::string(std::size_t t)>;

/// True when the triangle's three distinct vertices are collinear (area below (1e-7 L)^2 where
/// L is the largest coordinate magnitude): it has no normal.
bool isZeroAreaTriangle(std::span<const Float3> points, const Triangle& t);

/// Checks finite coordinates, index range, non-degenerate triangles and a 2-manifold
/// (each edge in at most two triangles, consistently oriented; each vertex a single fan).
/// `points` and `triangles` are geometric (one entry per surface point).
Result<void> validateGeometry(std::span<const Float3> points, std::span<const Triangle> triangles,
                              const std::string& source, const TriangleLabel& label);

}  // namespace tissue::mesh::detail
