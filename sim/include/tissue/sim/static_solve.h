#pragma once
/// \file
/// Static equilibrium of a mass-spring system: springs, gravity and pins, no motion.
///
/// Method: Levenberg-Marquardt Newton iterations built from the implicit-Euler machinery. One
/// linearised implicit-Euler step of size h taken from rest (v = 0) solves
///   (M + h^2 K) dx = h^2 f(x)                     (Baraff & Witkin 1998 eq. 18 with v = 0),
/// i.e. a Newton step on f(x) = 0 regularised by M / h^2: a large h gives Newton's step, a small
/// one a short, safe step along M^-1 f. A step is accepted when it lowers the potential energy
/// (elastic + gravity), and h then grows; otherwise it is retried with a smaller h (a trust
/// region). It stops when the largest force on a free vertex is below the tolerance (N).

#include <string>

#include "tissue/core/result.h"
#include "tissue/sim/integrators.h"
#include "tissue/sim/system.h"

namespace tissue::sim {

/// Settings of the static solve.
struct StaticSolveConfig {
  double toleranceN = 1e-6;   ///< stop when max |f| over free vertices <= this (N)
  int maxIterations = 500;    ///< accepted plus rejected steps
  double initialStep = 0.01;  ///< s, first h of the regularised Newton step
  double maxStep = 1e4;       ///< s, largest h (M / h^2 then negligible: plain Newton)
  ImplicitSolverConfig linear{.maxIterations = 2000, .relativeTolerance = 1e-10};
};

/// What the solve did.
struct StaticSolveReport {
  bool converged = false;
  int iterations = 0;  ///< steps tried (accepted and rejected)
  int acceptedSteps = 0;
  double residualN = 0.0;        ///< max |f| over free vertices at the end (N)
  double potentialEnergy = 0.0;  ///< elastic + gravity at the end (g*mm^2/s^2)
};

/// Largest force (N) on a vertex that is free to move (spring and gravity forces, no damping).
double maxFreeForceN(const MassSpringSystem& system, std::span<const Vec3d> x);

/// Moves `x` (mm; pinned vertices stay) to the static equilibrium. Never fails: when it does not
/// converge within maxIterations, `x` holds the lowest-energy state found and converged is false.
StaticSolveReport solveStatic(const MassSpringSystem& system, std::vector<Vec3d>& x,
                              const StaticSolveConfig& config = {});

}  // namespace tissue::sim
