#pragma once
// A static poke solved to rest with the Simulator (implicit Euler): the volume-keeping study.

#include <cstdint>
#include <vector>

#include "tissue/core/types.h"
#include "tissue/sim/spring_network.h"
#include "tissue/sim/vec3.h"

namespace tissue::sim::test {

/// Which surface vertices are held and which are pushed.
struct PokeSetup {
  std::vector<std::uint32_t> pinned;  ///< the lowest band of vertices (y)
  std::vector<std::uint32_t> poked;   ///< the vertices near the top vertex (max y)
  Vec3d direction{0.0, -1.0, 0.0};    ///< the push, unit
};

/// Pins the vertices below ymin + pinFraction * height; pokes those within pokeRadius (mm) of
/// the highest vertex.
PokeSetup makePokeSetup(const std::vector<Float3>& positions, double pinFraction, double pokeRadius);

/// The rest state under constant forces.
struct RestResult {
  std::vector<Vec3d> x;    ///< mm, the system's vertices (no anchors)
  int frames = 0;          ///< frames until rest
  bool converged = false;  ///< the largest move of a frame fell below the tolerance
};

/// Solves springs + masses (g) with `pinned` vertices and constant `forces` (g*mm/s^2, one per
/// vertex, zero for most) to rest with the Simulator (implicit Euler, no gravity, Rayleigh mass
/// damping). The Simulator has no external-force input, so each force is a soft spring to a
/// pinned anchor 2e5 mm away, stretched to twice its rest length: over a few mm of motion the
/// force changes by about 1e-5 of itself and turns by about 1e-5 rad.
RestResult solveToRest(SpringNetwork springs, std::vector<double> masses, const std::vector<Vec3d>& rest,
                       const std::vector<std::uint32_t>& pinned, const std::vector<Vec3d>& forces,
                       int maxFrames = 400, double moveTolerance = 1e-4);

}  // namespace tissue::sim::test
