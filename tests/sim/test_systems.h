#pragma once
// Small systems with known answers, shared by the simulator tests.

#include <cstdint>
#include <vector>

#include "tissue/core/types.h"
#include "tissue/sim/system.h"

namespace tissue::sim::test {

/// One mass (g) on one spring (N/mm) of rest length `restLength` (mm) from a pinned anchor at
/// the origin along x, no gravity. Vertex 0 is the anchor, vertex 1 the mass.
MassSpringSystem oneSpring(double mass, double stiffness, double restLength = 10.0);

/// omega = sqrt(k / m) in rad/s for mass (g) and stiffness (N/mm).
double omega(double mass, double stiffness);

/// A flat nx by ny grid of vertices spaced `spacing` mm in the xy plane, two triangles per cell.
struct Patch {
  std::vector<Float3> positions;
  std::vector<Triangle> triangles;
};
Patch gridPatch(int nx, int ny, float spacing);

/// The patch as a system: edge and bending springs (N/mm), lumped `totalMass` (g), `pinned`.
MassSpringSystem patchSystem(const Patch& patch, double stiffness, double damping, double totalMass,
                             const std::vector<std::uint32_t>& pinned, const SystemConfig& config);

/// Deterministic pseudo-random velocities in [-scale, scale] mm/s (a fixed LCG, not <random>,
/// so that the numbers are the same with every standard library).
std::vector<Vec3d> pseudoRandomVelocities(std::size_t n, double scale);

/// Largest natural angular frequency (rad/s) of the undamped system linearised at `x`:
/// power iteration on M^-1/2 K M^-1/2 over the free vertices.
double largestOmega(const MassSpringSystem& system, const std::vector<Vec3d>& x);

}  // namespace tissue::sim::test
