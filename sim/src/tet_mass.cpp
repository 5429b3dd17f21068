// Masses of a tet volume: a quarter of each tet's volume to each of its vertices, or uniform.
#include <cmath>
#include <string>

#include "tissue/sim/mass.h"
#include "tissue/sim/vec3.h"

namespace tissue::sim {
namespace {

Vec3d toVec(const Float3& p) {
  return {p.x, p.y, p.z};
}

/// det(b - a, c - a, d - a) / 6, in double.
double tetVolume(const Float3& a, const Float3& b, const Float3& c, const Float3& d) {
  const Vec3d u = toVec(b) - toVec(a), v = toVec(c) - toVec(a), w = toVec(d) - toVec(a);
  return (u.x * (v.y * w.z - v.z * w.y) - u.y * (v.x * w.z - v.z * w.x) + u.z * (v.x * w.y - v.y * w.x)) /
         6.0;
}

}  // namespace

Result<std::vector<double>> computeTetMasses(std::span<const Float3> positions, std::span<const Tet> tets,
                                             const VolumeMassConfig& config) {
  const bool useTotal = config.total > 0.0;
  if (!useTotal && !(config.density > 0.0))
    return Error{"mass: neither a positive total (g) nor a positive density (g/mm^3) was given"};
  if (positions.empty() || tets.empty()) return Error{"mass: the volume has no vertices or no tets"};

  // Each vertex's share of volume (a quarter of each of its tets), and the total volume.
  std::vector<double> share(positions.size(), 0.0);
  double volume = 0.0;
  for (std::size_t t = 0; t < tets.size(); ++t) {
    const Tet& q = tets[t];
    if (q[0] >= positions.size() || q[1] >= positions.size() || q[2] >= positions.size() ||
        q[3] >= positions.size())
      return Error{"mass: tet " + std::to_string(t + 1) + " (1-based) refers to a vertex out of range"};
    const double v = tetVolume(positions[q[0]], positions[q[1]], positions[q[2]], positions[q[3]]);
    if (!(v > 0.0))
      return Error{"mass: tet " + std::to_string(t + 1) +
                   " (1-based) has no positive volume; load tets through loadTetMesh, which orients them"};
    for (std::uint32_t i : q)
      share[i] += v / 4.0;
    volume += v;
  }
  const double total = useTotal ? config.total : config.density * volume;
  if (!(total > 0.0) || !std::isfinite(total))
    return Error{"mass: the total mass is not positive and finite"};

  std::vector<double> masses(positions.size(), total / static_cast<double>(positions.size()));
  if (config.distribution == MassDistribution::Lumped) {
    for (std::size_t v = 0; v < positions.size(); ++v) {
      if (!(share[v] > 0.0))
        return Error{"mass: vertex " + std::to_string(v + 1) +
                     " (1-based) belongs to no tet and would get no mass; remove it or use uniform"};
      masses[v] = total * share[v] / volume;
    }
  }
  return masses;
}

}  // namespace tissue::sim
