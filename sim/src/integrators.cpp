// The explicit integrators and the dispatch; implicit Euler is in implicit_euler.cpp, the fast
// mass-spring solver in fast_mass_spring.cpp.
#include "tissue/sim/integrators.h"

#include <array>
#include <utility>

#include "parallel.h"

namespace tissue::sim {
namespace {

constexpr std::array<std::pair<Integrator, std::string_view>, 5> kNames{{
    {Integrator::ExplicitEuler, "explicit-euler"},
    {Integrator::SymplecticEuler, "symplectic-euler"},
    {Integrator::VelocityVerlet, "verlet"},
    {Integrator::ImplicitEuler, "implicit-euler"},
    {Integrator::FastMassSpring, "fast-mass-spring"},
}};

/// ws.forces = f(x, v) for the state's sizes.
void evaluateForces(const MassSpringSystem& system, std::span<const Vec3d> x, std::span<const Vec3d> v,
                    StepWorkspace& ws) {
  ws.forces.resize(x.size());
  computeForces(system, x, v, ws.forces, ws.scratch);
}

}  // namespace

std::string_view integratorName(Integrator integrator) {
  for (const auto& [value, name] : kNames)
    if (value == integrator) return name;
  return "unknown";
}

std::optional<Integrator> parseIntegrator(std::string_view name) {
  for (const auto& [value, n] : kNames)
    if (n == name) return value;
  return std::nullopt;
}

// The vector updates run over contiguous vertex ranges on config.threads threads; each vertex is
// written by one thread, so the results do not depend on the thread count.

void stepExplicitEuler(const MassSpringSystem& system, State& state, double h, StepWorkspace& ws) {
  evaluateForces(system, state.x, state.v, ws);
  detail::parallelRanges(state.x.size(), system.config.threads, [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k) {
      state.x[k] += h * state.v[k];
      state.v[k] += (h * system.invMasses[k]) * ws.forces[k];
    }
  });
}

void stepSymplecticEuler(const MassSpringSystem& system, State& state, double h, StepWorkspace& ws) {
  evaluateForces(system, state.x, state.v, ws);
  detail::parallelRanges(state.x.size(), system.config.threads, [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k) {
      state.v[k] += (h * system.invMasses[k]) * ws.forces[k];
      state.x[k] += h * state.v[k];
    }
  });
}

void stepVelocityVerlet(const MassSpringSystem& system, State& state, double h, StepWorkspace& ws) {
  // Half kick with a(t), drift, half kick with a(t+h) (velocity damping sees the half-step v).
  evaluateForces(system, state.x, state.v, ws);
  detail::parallelRanges(state.x.size(), system.config.threads, [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k) {
      state.v[k] += (0.5 * h * system.invMasses[k]) * ws.forces[k];
      state.x[k] += h * state.v[k];
    }
  });
  evaluateForces(system, state.x, state.v, ws);
  detail::parallelRanges(state.x.size(), system.config.threads, [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k)
      state.v[k] += (0.5 * h * system.invMasses[k]) * ws.forces[k];
  });
}

StepStats step(Integrator integrator, const MassSpringSystem& system, State& state, double h,
               StepWorkspace& ws, const ImplicitSolverConfig& solver) {
  switch (integrator) {
    case Integrator::ExplicitEuler:
      stepExplicitEuler(system, state, h, ws);
      return {};
    case Integrator::SymplecticEuler:
      stepSymplecticEuler(system, state, h, ws);
      return {};
    case Integrator::VelocityVerlet:
      stepVelocityVerlet(system, state, h, ws);
      return {};
    case Integrator::ImplicitEuler:
      return stepImplicitEuler(system, state, h, ws, solver);
    case Integrator::FastMassSpring:
      return stepFastMassSpring(system, state, h, ws, solver);
  }
  return {};
}

}  // namespace tissue::sim
