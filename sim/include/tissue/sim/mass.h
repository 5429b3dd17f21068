#pragma once
/// \file
/// Per-vertex masses for a surface mesh: a total mass or an areal density, spread uniformly
/// (every vertex the same, SOFA's UniformMass) or lumped by area (a third of each triangle);
/// and for a volume (tets): a total or a density, uniform or lumped by volume (a quarter of each
/// tet).

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

/// Where the masses of a volume come from: `total` when > 0, else `density`.
struct VolumeMassConfig {
  double total = 0.0;        ///< g, the whole volume; 0 to use density
  double density = 1.06e-3;  ///< g/mm^3 when total == 0 (liver about 1.06 g/cm^3)
  MassDistribution distribution = MassDistribution::Lumped;  ///< Lumped: by volume
};

/// Masses in g, one per vertex of `positions` (mm), from the tets: Lumped gives each vertex a
/// quarter of the volume of each of its tets, Uniform the same mass to every vertex. The total is
/// config.total, or config.density times the summed tet volume (mm^3). Fails when neither is
/// positive, on bad indices, on a tet of non-positive volume, or when a lumped vertex belongs to
/// no tet (it would get no mass).
Result<std::vector<double>> computeTetMasses(std::span<const Float3> positions, std::span<const Tet> tets,
                                             const VolumeMassConfig& config);

}  // namespace tissue::sim
