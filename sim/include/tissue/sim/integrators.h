#pragma once
/// \file
/// Time integrators: one step of size h (s) advances a State of a MassSpringSystem in place.
/// Steps never fail by themselves; the Simulator checks the result for divergence.

#include <cstdint>
#include <memory>
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
  FastMassSpring,   ///< backward Euler by local/global iterations on a prefactored matrix (Liu et al. 2013).
};

/// The name used in reports and on the command line ("explicit-euler", "symplectic-euler",
/// "verlet", "implicit-euler", "fast-mass-spring").
std::string_view integratorName(Integrator integrator);
/// The integrator named `name` (as integratorName), if any.
std::optional<Integrator> parseIntegrator(std::string_view name);

/// Settings of the implicit solvers: implicit Euler's conjugate gradients and the fast solver's
/// local/global iterations.
struct ImplicitSolverConfig {
  int maxIterations = 200;           ///< conjugate-gradient iterations per step (implicit Euler)
  double relativeTolerance = 1e-10;  ///< stop when |residual| <= tolerance * |right-hand side|
  int localGlobalIterations = 10;    ///< fast-mass-spring: local/global iterations per step (at most)
  /// fast-mass-spring: stop the iterations early once one moves no vertex by more than this
  /// times the step's largest displacement (unitless); 0 runs all localGlobalIterations.
  double localGlobalTolerance = 0.0;
};

/// What one step did.
struct StepStats {
  int cgIterations = 0;             ///< implicit Euler only
  double cgRelativeResidual = 0.0;  ///< implicit Euler only
  int localGlobalIterations = 0;    ///< fast-mass-spring only
  bool refactored = false;          ///< fast-mass-spring: the matrix was (re)factored in this step
  double factorMs = 0.0;            ///< fast-mass-spring: time spent factoring (ms), 0 when cached
};

/// The fast solver's prefactored matrix (M + h^2 L + damping terms, Eigen's sparse Cholesky),
/// cached between steps and keyed on h, the Rayleigh coefficients and a fingerprint of the
/// system (springs, stiffness, damping, masses, pins); a change of any of them refactors.
/// Eigen stays inside sim/src: this is an opaque handle. A copy starts empty (it refactors).
class FastSolverCache {
 public:
  struct Impl;
  FastSolverCache();
  ~FastSolverCache();
  FastSolverCache(const FastSolverCache&);
  FastSolverCache& operator=(const FastSolverCache&);
  FastSolverCache(FastSolverCache&&) noexcept;
  FastSolverCache& operator=(FastSolverCache&&) noexcept;
  /// The cache, created on first use.
  Impl& impl();
  /// Drops the factor; the next fast step refactors.
  void clear();
  /// A caller that owns the system and numbers its changes (the Simulator: every setKinematic
  /// is a new revision) may key the factor on `revision` instead of a fingerprint of the
  /// springs, masses and pins, which costs a pass over the arrays every step. 0 (the default,
  /// and after a copy) fingerprints.
  void setSystemRevision(std::uint64_t revision) { m_revision = revision; }
  std::uint64_t systemRevision() const { return m_revision; }

 private:
  std::unique_ptr<Impl> m_impl;
  std::uint64_t m_revision = 0;
};

/// Scratch reused between steps; `previousDeltaV` warm-starts the conjugate gradients and
/// `fast` keeps the fast solver's factor.
struct StepWorkspace {
  std::vector<Vec3d> forces, a, b, r, z, p, q, deltaV, previousDeltaV;
  ForceScratch scratch;
  FastSolverCache fast;
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

/// Fast mass-spring (Liu, Bargteil, O'Brien & Kavan 2013): backward Euler written as the
/// minimisation of g(x) = 1/2 (x - y)^T M (x - y) + h^2 E(x), y = x + h v, solved by
/// `solver.localGlobalIterations` alternations of a local step (each spring's direction at rest
/// length) and a global step (one solve with the prefactored M + h^2 L). Unconditionally stable.
/// Gravity is exact; Rayleigh mass damping is exact; Rayleigh stiffness damping uses L for K and
/// spring damping acts on the whole relative velocity (not only along the spring): see
/// docs/DECISIONS.md. Pinned vertices move with their own velocity and are not unknowns.
/// v(t+h) = (x(t+h) - x) / h.
StepStats stepFastMassSpring(const MassSpringSystem& system, State& state, double h, StepWorkspace& ws,
                             const ImplicitSolverConfig& solver);

/// One step of `integrator`.
StepStats step(Integrator integrator, const MassSpringSystem& system, State& state, double h,
               StepWorkspace& ws, const ImplicitSolverConfig& solver = {});

}  // namespace tissue::sim
