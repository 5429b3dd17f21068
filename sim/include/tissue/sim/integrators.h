#pragma once
/// \file
/// Time integrators: one step of size h (s) advances a State of a MassSpringSystem in place.
/// Steps never fail by themselves; the Simulator checks the result for divergence.

#include <optional>
#include <string_view>
#include <vector>

#include "tissue/sim/forces.h"
#include "tissue/sim/system.h"

namespace tissue::sim {

/// The integrators (a closed set).
enum class Integrator {
  ExplicitEuler,    ///< x += h v(t); v += h a(t). Unstable at every h without damping; kept to show it.
  SymplecticEuler,  ///< v += h a(x(t)); x += h v(t+h). Stable for h < 2/omega_max.
  VelocityVerlet,   ///< half kick, drift, half kick. Stable for h < 2/omega_max, second order.
  ImplicitEuler,    ///< linearised backward Euler (Baraff & Witkin 1998), conjugate gradients.
};

/// The name used in reports and on the command line ("explicit-euler", "symplectic-euler",
/// "verlet", "implicit-euler").
std::string_view integratorName(Integrator integrator);
/// The integrator named `name` (as integratorName), if any.
std::optional<Integrator> parseIntegrator(std::string_view name);

/// Settings of the implicit-Euler linear solve.
struct ImplicitSolverConfig {
  int maxIterations = 200;           ///< conjugate-gradient iterations per step
  double relativeTolerance = 1e-10;  ///< stop when |residual| <= tolerance * |right-hand side|
};

/// What one step did.
struct StepStats {
  int cgIterations = 0;             ///< implicit Euler only
  double cgRelativeResidual = 0.0;  ///< implicit Euler only
};

/// Scratch reused between steps; `previousDeltaV` warm-starts the conjugate gradients.
struct StepWorkspace {
  std::vector<Vec3d> forces, a, b, r, z, p, q, deltaV, previousDeltaV;
  ForceScratch scratch;
};

/// Explicit (forward) Euler: x(t+h) = x + h v, v(t+h) = v + h M^-1 f(x, v).
void stepExplicitEuler(const MassSpringSystem& system, State& state, double h, StepWorkspace& ws);
/// Symplectic (semi-implicit) Euler: v(t+h) = v + h M^-1 f(x, v), x(t+h) = x + h v(t+h).
void stepSymplecticEuler(const MassSpringSystem& system, State& state, double h, StepWorkspace& ws);
/// Velocity Verlet: v' = v + h/2 a(x, v); x(t+h) = x + h v'; v(t+h) = v' + h/2 a(x(t+h), v').
void stepVelocityVerlet(const MassSpringSystem& system, State& state, double h, StepWorkspace& ws);
/// Linearised implicit Euler (Baraff & Witkin 1998 eq. 18):
/// (M + h C + h^2 K) dv = h (f(x, v) - h K v), v += dv, x += h v, with C = alpha M + beta K +
/// spring damping, K clamped for compressed springs, pinned rows filtered out (their dv = 0).
StepStats stepImplicitEuler(const MassSpringSystem& system, State& state, double h, StepWorkspace& ws,
                            const ImplicitSolverConfig& solver);

/// One step of `integrator`.
StepStats step(Integrator integrator, const MassSpringSystem& system, State& state, double h,
               StepWorkspace& ws, const ImplicitSolverConfig& solver = {});

}  // namespace tissue::sim
