// Linearised implicit Euler (Baraff & Witkin, "Large steps in cloth simulation", SIGGRAPH 1998),
// solved matrix-free with preconditioned conjugate gradients, warm-started from the last step.
// Every pass runs over contiguous vertex ranges on config.threads threads, and the dot products
// sum fixed blocks in a fixed order (parallel.h), so the result does not depend on the thread count.
#include <cmath>

#include "parallel.h"
#include "tissue/sim/integrators.h"

namespace tissue::sim {
namespace {

/// Pinned vertices take no part in the solve (Baraff & Witkin §5.3's filter S with all three
/// directions constrained): their entries are held at zero.
void filterPinned(const MassSpringSystem& system, std::span<Vec3d> a) {
  detail::parallelRanges(a.size(), system.config.threads, [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k)
      if (system.invMasses[k] == 0.0) a[k] = {};
  });
}

double dotAll(const MassSpringSystem& system, std::span<const Vec3d> a, std::span<const Vec3d> b) {
  return detail::parallelSum(a.size(), system.config.threads, [&](std::size_t k) { return dot(a[k], b[k]); });
}

/// body(k) for every vertex k, over config.threads threads.
template <class Body>
void forEachVertex(const MassSpringSystem& system, std::size_t n, const Body& body) {
  detail::parallelRanges(n, system.config.threads, [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k)
      body(k);
  });
}

/// out = A p with A = (1 + h alpha) M + (h beta + h^2) K + h C_springs, filtered.
void applySystemMatrix(const MassSpringSystem& system, std::span<const Vec3d> x, double h,
                       std::span<const Vec3d> p, std::span<Vec3d> out, ForceScratch& scratch) {
  const SystemConfig& c = system.config;
  springMatrixTimes(system, x, p, h * c.rayleighStiffness + h * h, h, out, scratch);
  detail::parallelRanges(p.size(), c.threads, [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k)
      out[k] = system.invMasses[k] == 0.0 ? Vec3d{}
                                          : out[k] + ((1.0 + h * c.rayleighMass) * system.masses[k]) * p[k];
  });
}

/// A cheap positive diagonal preconditioner (Jacobi-like): per vertex, the mass term plus the
/// weighted stiffness and damping of its springs, which bounds the diagonal block's entries.
void preconditionerDiagonal(const MassSpringSystem& system, double h, std::span<double> diag) {
  const SpringNetwork& s = system.springs;
  const SystemConfig& c = system.config;
  const double wk = h * c.rayleighStiffness + h * h;
  forEachVertex(system, diag.size(), [&](std::size_t v) {
    double d = (1.0 + h * c.rayleighMass) * system.masses[v];
    for (std::uint32_t k = s.vertexSpringOffsets[v]; k < s.vertexSpringOffsets[v + 1]; ++k) {
      const std::uint32_t e = s.vertexSprings[k];
      d += wk * s.stiffness[e] + h * s.damping[e];
    }
    diag[v] = d;
  });
}

}  // namespace

StepStats stepImplicitEuler(const MassSpringSystem& system, State& state, double h, StepWorkspace& ws,
                            const ImplicitSolverConfig& solver) {
  const std::size_t n = state.x.size();
  for (auto* a : {&ws.b, &ws.r, &ws.z, &ws.p, &ws.q, &ws.deltaV, &ws.a})
    a->resize(n);
  std::vector<double> diag(n);
  preconditionerDiagonal(system, h, diag);

  // Right-hand side b = h (f(x, v) - h K v); f already holds the damping forces, including
  // Rayleigh's -beta K v, whose Jacobian enters A through the h beta K term.
  ws.forces.resize(n);
  computeForces(system, state.x, state.v, ws.forces, ws.scratch);
  springMatrixTimes(system, state.x, state.v, h, 0.0, ws.a, ws.scratch);
  forEachVertex(system, n, [&](std::size_t k) { ws.b[k] = h * (ws.forces[k] - ws.a[k]); });
  filterPinned(system, ws.b);

  // Warm start from the previous step's dv, when the sizes still match.
  if (ws.previousDeltaV.size() == n)
    ws.deltaV = ws.previousDeltaV;
  else
    ws.deltaV.assign(n, Vec3d{});
  filterPinned(system, ws.deltaV);

  // Preconditioned conjugate gradients on A dv = b.
  StepStats stats;
  const double bNorm = std::sqrt(dotAll(system, ws.b, ws.b));
  applySystemMatrix(system, state.x, h, ws.deltaV, ws.q, ws.scratch);
  forEachVertex(system, n, [&](std::size_t k) { ws.r[k] = ws.b[k] - ws.q[k]; });
  double rNorm = std::sqrt(dotAll(system, ws.r, ws.r));
  const double target = solver.relativeTolerance * bNorm;
  if (bNorm == 0.0) {
    ws.deltaV.assign(n, Vec3d{});
    rNorm = 0.0;
  }
  double rz = 0.0;
  for (int it = 0; rNorm > target && it < solver.maxIterations; ++it) {
    forEachVertex(system, n, [&](std::size_t k) { ws.z[k] = (1.0 / diag[k]) * ws.r[k]; });
    const double rzNew = dotAll(system, ws.r, ws.z);
    if (it == 0) {
      ws.p = ws.z;
    } else {
      const double beta = rzNew / rz;
      forEachVertex(system, n, [&](std::size_t k) { ws.p[k] = ws.z[k] + beta * ws.p[k]; });
    }
    rz = rzNew;
    applySystemMatrix(system, state.x, h, ws.p, ws.q, ws.scratch);
    const double pq = dotAll(system, ws.p, ws.q);
    if (!(pq > 0.0)) break;  // A is positive definite on the free vertices; guards rounding
    const double alpha = rz / pq;
    forEachVertex(system, n, [&](std::size_t k) {
      ws.deltaV[k] += alpha * ws.p[k];
      ws.r[k] -= alpha * ws.q[k];
    });
    rNorm = std::sqrt(dotAll(system, ws.r, ws.r));
    stats.cgIterations = it + 1;
  }
  stats.cgRelativeResidual = bNorm > 0.0 ? rNorm / bNorm : 0.0;
  ws.previousDeltaV = ws.deltaV;

  // v(t+h) = v + dv, x(t+h) = x + h v(t+h).
  forEachVertex(system, n, [&](std::size_t k) {
    state.v[k] += ws.deltaV[k];
    state.x[k] += h * state.v[k];
  });
  return stats;
}

}  // namespace tissue::sim
