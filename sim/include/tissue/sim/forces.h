#pragma once
/// \file
/// Stateless kernels of the mass-spring model: one spring's force and stiffness block, and the
/// passes over a whole system (forces, stiffness-matrix products, energies, momentum).
/// Forces are in g*mm/s^2 (1e-6 N), energies in g*mm^2/s^2 (1e-9 J).

#include <span>
#include <vector>

#include "tissue/sim/system.h"
#include "tissue/sim/vec3.h"

namespace tissue::sim {

/// Force on end point i of a spring from i to j: (k (L - L0) + c (v_j - v_i).n) n, with
/// n = (x_j - x_i) / L. Positions mm, velocities mm/s, L0 mm, k g/s^2, c g/s. The force on j is
/// the negative. Zero when the end points coincide (no direction).
inline Vec3d springForce(const Vec3d& xi, const Vec3d& xj, const Vec3d& vi, const Vec3d& vj,
                         double restLength, double stiffness, double damping) {
  const Vec3d d = xj - xi;
  const double len = length(d);
  if (!(len > 0.0)) return {};
  const Vec3d n = (1.0 / len) * d;
  return (stiffness * (len - restLength) + damping * dot(vj - vi, n)) * n;
}

/// Product of one spring's stiffness block with `p` (Baraff & Witkin 1998 eq. 14-15, K = -df/dx):
/// K_e p = k [n n^T p + max(0, 1 - L0/L) (p - n n^T p)]. The transverse term is negative for a
/// compressed spring; clamping it at zero keeps K positive semi-definite (Choi & Ko 2002, §4).
inline Vec3d springStiffnessTimes(const Vec3d& xi, const Vec3d& xj, double restLength, double stiffness,
                                  const Vec3d& p) {
  const Vec3d d = xj - xi;
  const double len = length(d);
  if (!(len > 0.0)) return stiffness * p;
  const Vec3d n = (1.0 / len) * d;
  const double axial = dot(n, p);
  const double transverse = restLength < len ? 1.0 - restLength / len : 0.0;
  return stiffness * (axial * n + transverse * (p - axial * n));
}

/// Per-spring scratch of the gathering passes.
struct ForceScratch {
  std::vector<Vec3d> perSpring;  ///< #springs
  std::vector<Vec3d> perVertex;  ///< #vertices
};

/// Total force on every vertex (g*mm/s^2): springs with their damping, gravity m g, Rayleigh
/// damping -alpha m v - beta K v. Pinned vertices get their force too (it moves nothing).
void computeForces(const MassSpringSystem& system, std::span<const Vec3d> x, std::span<const Vec3d> v,
                   std::span<Vec3d> forces, ForceScratch& scratch);

/// out = sum over springs of w_k K_e (p_i - p_j) + w_c c_e n n^T (p_i - p_j), scattered with
/// opposite signs to i and j: the spring part of the implicit-Euler matrix applied to p.
/// K is evaluated at positions `x` (mm), with the clamp of springStiffnessTimes.
void springMatrixTimes(const MassSpringSystem& system, std::span<const Vec3d> x, std::span<const Vec3d> p,
                       double stiffnessWeight, double dampingWeight, std::span<Vec3d> out,
                       ForceScratch& scratch);

/// Kinetic energy sum m v^2 / 2 (g*mm^2/s^2).
double kineticEnergy(const MassSpringSystem& system, std::span<const Vec3d> v);
/// Elastic energy sum k (L - L0)^2 / 2 (g*mm^2/s^2).
double elasticEnergy(const MassSpringSystem& system, std::span<const Vec3d> x);
/// Gravitational energy -sum m g.x (g*mm^2/s^2), zero at the origin.
double gravityEnergy(const MassSpringSystem& system, std::span<const Vec3d> x);
/// Linear momentum sum m v (g*mm/s).
Vec3d linearMomentum(const MassSpringSystem& system, std::span<const Vec3d> v);
/// Largest L / L0 over all springs (unitless).
double maxStretch(const MassSpringSystem& system, std::span<const Vec3d> x);

}  // namespace tissue::sim
