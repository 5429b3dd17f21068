#include "tissue/sim/mass.h"

#include <cmath>
#include <string>

#include "tissue/sim/vec3.h"

namespace tissue::sim {
namespace {

double triangleArea(const Float3& a, const Float3& b, const Float3& c) {
  const Vec3d u{b.x - a.x, b.y - a.y, b.z - a.z};
  const Vec3d w{c.x - a.x, c.y - a.y, c.z - a.z};
  const Vec3d n{u.y * w.z - u.z * w.y, u.z * w.x - u.x * w.z, u.x * w.y - u.y * w.x};
  return 0.5 * length(n);
}

}  // namespace

Result<std::vector<double>> computeMasses(std::span<const Float3> positions,
                                          std::span<const Triangle> triangles, const MassConfig& config) {
  const bool useTotal = config.total > 0.0;
  if (!useTotal && !(config.arealDensity > 0.0))
    return Error{"mass: neither a positive total (g) nor a positive areal density (g/mm^2) was given"};
  if (positions.empty()) return Error{"mass: the mesh has no vertices"};

  // Area of each vertex's share (a third of each of its triangles), and the total area.
  std::vector<double> area(positions.size(), 0.0);
  double totalArea = 0.0;
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const Triangle& tri = triangles[t];
    if (tri[0] >= positions.size() || tri[1] >= positions.size() || tri[2] >= positions.size())
      return Error{"mass: triangle " + std::to_string(t) + " refers to a vertex out of range"};
    const double a = triangleArea(positions[tri[0]], positions[tri[1]], positions[tri[2]]);
    for (std::uint32_t v : tri)
      area[v] += a / 3.0;
    totalArea += a;
  }
  const double total = useTotal ? config.total : config.arealDensity * totalArea;

  std::vector<double> masses(positions.size());
  if (config.distribution == MassDistribution::Uniform) {
    masses.assign(positions.size(), total / static_cast<double>(positions.size()));
  } else {
    if (!(totalArea > 0.0)) return Error{"mass: the mesh has no area to lump masses by; use uniform"};
    for (std::size_t v = 0; v < positions.size(); ++v) {
      if (!(area[v] > 0.0))
        return Error{"mass: vertex " + std::to_string(v) +
                     " belongs to no triangle of positive area and would get no mass; use uniform"};
      masses[v] = total * area[v] / totalArea;
    }
  }
  if (!(total > 0.0) || !std::isfinite(total))
    return Error{"mass: the total mass is not positive and finite"};
  return masses;
}

}  // namespace tissue::sim
