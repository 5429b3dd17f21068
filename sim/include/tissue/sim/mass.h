#pragma once
/// \file
/// Per-vertex masses for a surface mesh: a total mass or an areal density, spread uniformly
/// (every vertex the same, SOFA's UniformMass) or lumped by area (a third of each triangle).

#include <span>
#include <vector>

#include "tissue/core/result.h"
#include "tissue/core/types.h"

namespace tissue::sim {

/// How masses are spread over the vertices.
enum class MassDistribution {
  Uniform,  ///< every vertex the same mass
  Lumped,   ///< each vertex a third of the area of its triangles
};

/// Where the masses come from: `total` when > 0, else `arealDensity`.
struct MassConfig {
  double total = 10.0;        ///< g, the whole mesh; 0 to use arealDensity
  double arealDensity = 0.0;  ///< g/mm^2 (tissue density times sheet thickness), when total == 0
  MassDistribution distribution = MassDistribution::Lumped;
};

/// Masses in g, one per vertex of `positions` (mm). Fails when neither a positive total nor a
/// positive density is given, on bad indices, or when a lumped vertex would get no mass.
Result<std::vector<double>> computeMasses(std::span<const Float3> positions,
                                          std::span<const Triangle> triangles, const MassConfig& config);

}  // namespace tissue::sim
