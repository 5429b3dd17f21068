#pragma once
/// \file
/// The mass-spring system (what does not change during a step: springs, masses, pins, gravity,
/// Rayleigh damping) and its state (what does: positions and velocities), struct-of-arrays.
/// A zero inverse mass pins a particle: no force moves it (it keeps its velocity, normally 0).

#include <cstdint>
#include <span>
#include <vector>

#include "tissue/core/result.h"
#include "tissue/core/types.h"
#include "tissue/sim/spring_network.h"
#include "tissue/sim/vec3.h"

namespace tissue::sim {

/// Positions and velocities, one entry per vertex.
struct State {
  std::vector<Vec3d> x;  ///< positions, mm
  std::vector<Vec3d> v;  ///< velocities, mm/s
};

/// Global forces of a system.
struct SystemConfig {
  Vec3d gravity{0.0, -9806.65, 0.0};  ///< mm/s^2 (y up); {0,0,0} for none
  double rayleighMass = 0.0;          ///< alpha in 1/s: force -alpha * m * v (drag towards rest frame)
  double rayleighStiffness = 0.0;     ///< beta in s: force -beta * K * v (K the stiffness matrix)
  int threads = 1;  ///< threads of the spring passes (large systems only); bit-identical for any count
};

/// Everything constant during a step.
struct MassSpringSystem {
  SpringNetwork springs;
  std::vector<double> masses;     ///< g, #vertices, > 0
  std::vector<double> invMasses;  ///< 1/g, #vertices; 0 pins the vertex
  SystemConfig config;

  std::size_t vertexCount() const { return masses.size(); }
};

/// Assembles a system from a finalised network, masses (g) and pinned vertex indices. Fails on
/// a size mismatch, a mass that is not positive and finite, or a pinned index out of range.
Result<MassSpringSystem> makeSystem(SpringNetwork springs, std::vector<double> masses,
                                    std::span<const std::uint32_t> pinned, const SystemConfig& config);

/// The state at rest in `positions` (mm), zero velocities.
State restState(std::span<const Float3> positions);

/// Positions as floats for the mesh module and the renderer (mm).
std::vector<Float3> toFloat3(std::span<const Vec3d> positions);

}  // namespace tissue::sim
