#pragma once
/// \file
/// Spring networks from a tetrahedral mesh: one spring per unique tet edge. For scenes that
/// supply a volume mesh (tissue::volume::loadTetMesh reads .vtk, .vtu and .msh).

#include <span>

#include "tissue/core/result.h"
#include "tissue/core/types.h"
#include "tissue/sim/spring_network.h"

namespace tissue::sim {

/// What a tet build found (for reports).
struct TetSpringReport {
  std::size_t tets = 0;         ///< tets read
  std::size_t edgeSprings = 0;  ///< one per unique tet edge
};

/// One spring per unique edge of `tets`, rest lengths from `positions` (mm), stiffness by
/// config.law as buildSurfaceSprings (Constant: N/mm; PerRestLength: k_i = k / L0_i, SOFA's
/// MeshSpringForceField), damping config.damping (N*s/mm); config.bendingStiffness is unused.
/// Fails on an index out of range or coincident vertices.
Result<SpringNetwork> buildTetEdgeSprings(std::span<const Float3> positions, std::span<const Tet> tets,
                                          const SpringConfig& config, TetSpringReport* report = nullptr);

}  // namespace tissue::sim
