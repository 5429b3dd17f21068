#pragma once
// Internal: the stiffness matrix at rest of a spring network, K = sum k n n^T (N/mm), on the
// degrees of freedom that are not held (for solveLinearStatic and indentSphere).
#include <Eigen/SparseCore>
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "tissue/sim/spring_network.h"
#include "tissue/sim/vec3.h"

namespace tissue::sim::detail {

using SparseMatrix = Eigen::SparseMatrix<double>;

/// K restricted to the free degrees of freedom, and the map from 3 * vertex + axis to its row.
struct FreeSystem {
  SparseMatrix k;
  std::vector<int> freeIndex;  ///< 3 * vertex + axis -> row, or -1 when held
};

/// Assembles K_ff at the rest positions (mm); `held` has 3 entries per vertex. The free degrees
/// of freedom are numbered vertex by vertex in `vertexOrder` (empty: 0, 1, 2, ...).
FreeSystem assembleFree(const SpringNetwork& network, std::span<const Vec3d> rest,
                        const std::vector<char>& held, std::span<const std::uint32_t> vertexOrder = {});

/// A nested-dissection order of the nodes of a grid of `cells` cells (nodes i + (nx+1)(j +
/// (ny+1) k)): each box is split by the node plane across its longest side, the two halves come
/// first and the plane last, so a Cholesky factor fills in O(n^(4/3)) (George 1973) instead of
/// the much larger fill of a minimum-degree order on a 3D grid.
std::vector<std::uint32_t> nestedDissectionOrder(std::array<int, 3> cells);

/// (K u) per degree of freedom (N) for displacements `u` (mm): the forces the supports must
/// apply to hold `u`.
std::vector<double> stiffnessTimes(const SpringNetwork& network, std::span<const Vec3d> rest,
                                   std::span<const Vec3d> u);

}  // namespace tissue::sim::detail
