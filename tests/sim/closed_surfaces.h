#pragma once
// Closed test surfaces with known volumes, shared by the lattice and volume-keeping tests.

#include <vector>

#include "tissue/core/types.h"

namespace tissue::sim::test {

/// A closed triangle surface (outward, counter-clockwise from outside).
struct ClosedSurface {
  std::vector<Float3> positions;  ///< mm
  std::vector<Triangle> triangles;
};

/// An axis-aligned box from `lo` to `hi` (mm), two triangles per side.
ClosedSurface boxSurface(Float3 lo, Float3 hi);

/// An icosphere of `radius` mm about `centre`, `subdivisions` times subdivided (0: 12 vertices,
/// 3: 642 vertices), vertices pushed onto the sphere.
ClosedSurface icosphere(double radius, Float3 centre, int subdivisions);

/// Volume enclosed by a closed outward surface (mm^3), by the divergence theorem.
double enclosedVolume(const std::vector<Float3>& positions, const std::vector<Triangle>& triangles);

}  // namespace tissue::sim::test
