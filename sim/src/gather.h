#pragma once
// The per-vertex gather shared by the spring passes (forces.cpp, fast_mass_spring.cpp).

#include <span>

#include "tissue/sim/system.h"

namespace tissue::sim::detail {

/// out_v = sum over v's springs of +perSpring (v is end i) or -perSpring (v is end j), in the
/// fixed order of the incidence lists: the same sums, bit for bit, however the pass is split.
void gatherPerVertex(const MassSpringSystem& system, std::span<const Vec3d> perSpring, std::span<Vec3d> out);

}  // namespace tissue::sim::detail
