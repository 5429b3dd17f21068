#include "tissue/sim/system.h"

#include <cmath>
#include <string>
#include <utility>

namespace tissue::sim {

Result<MassSpringSystem> makeSystem(SpringNetwork springs, std::vector<double> masses,
                                    std::span<const std::uint32_t> pinned, const SystemConfig& config) {
  if (springs.vertexCount() != masses.size())
    return Error{"system: the spring network has " + std::to_string(springs.vertexCount()) +
                 " vertices but " + std::to_string(masses.size()) +
                 " masses were given; finalise the network with the vertex count"};
  for (std::size_t k = 0; k < masses.size(); ++k)
    if (!(masses[k] > 0.0) || !std::isfinite(masses[k]))
      return Error{"system: vertex " + std::to_string(k) + " has mass " + std::to_string(masses[k]) +
                   " g; masses must be positive (pin a vertex instead of giving it no mass)"};
  MassSpringSystem system;
  system.invMasses.resize(masses.size());
  for (std::size_t k = 0; k < masses.size(); ++k)
    system.invMasses[k] = 1.0 / masses[k];
  for (std::uint32_t p : pinned) {
    if (p >= masses.size())
      return Error{"system: pinned vertex " + std::to_string(p) + " is out of range (" +
                   std::to_string(masses.size()) + " vertices)"};
    system.invMasses[p] = 0.0;
  }
  system.springs = std::move(springs);
  system.masses = std::move(masses);
  system.config = config;
  return system;
}

State restState(std::span<const Float3> positions) {
  State s;
  s.x.reserve(positions.size());
  for (const Float3& p : positions)
    s.x.push_back({p.x, p.y, p.z});
  s.v.assign(positions.size(), Vec3d{});
  return s;
}

std::vector<Float3> toFloat3(std::span<const Vec3d> positions) {
  std::vector<Float3> out;
  out.reserve(positions.size());
  for (const Vec3d& p : positions)
    out.push_back({static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z)});
  return out;
}

}  // namespace tissue::sim
