#pragma once
/// \file
/// The step cost of the mass-spring integrators on generated patches of a chosen size, and of the
/// force pass alone: what `tissue-sim sim-bench` reports. GL-free. Lengths in mm, masses in g,
/// times in s (steps) and ms (timings: the median and the best of the timed steps, which resist
/// the noise of a shared machine).

#include <cstddef>

#include "tissue/core/result.h"
#include "tissue/sim/integrators.h"
#include "tissue/sim/system.h"

namespace tissue::studies {

/// A square patch, 1 mm spacing, of about `targetSprings` springs (edge and bending springs,
/// about 6 per vertex): 0.1 N/mm edges, 0.02 N/mm bending, 1e-6 N*s/mm spring damping,
/// 1e-3 g/mm^2 (1 mm of 1 g/cm^3), Rayleigh alpha 1 /s, gravity, the x = 0 column pinned.
struct BenchPatch {
  sim::MassSpringSystem system;
  sim::State rest;
};
Result<BenchPatch> makeBenchPatch(std::size_t targetSprings, int threads);

/// A bound on the largest natural angular frequency (rad/s) of `system` at rest, by
/// Gershgorin on M^-1/2 K M^-1/2: omega^2 <= max_i sum over i's springs k (1/m_i + 1/sqrt(m_i m_j)).
/// Explicit integrators are stable below h = 2 / omega_max.
double omegaBound(const sim::MassSpringSystem& system);

struct IntegratorBenchConfig {
  double frameTimeS = 1.0 / 60.0;  ///< s, the frame the substeps must cover
  double budgetMs = 300.0;         ///< ms of timed steps (at least one step)
  int maxTimedSteps = 200;
  sim::ImplicitSolverConfig solver{100, 1e-6, 10, 0.0};  ///< CG to 1e-6 in <= 100; 10 local/global
};

struct IntegratorTiming {
  sim::Integrator integrator = sim::Integrator::SymplecticEuler;
  std::size_t springs = 0, vertices = 0;
  double stepS = 0.0;          ///< s, h
  double msPerStep = 0.0;      ///< ms, median
  double msPerStepBest = 0.0;  ///< ms, smallest
  int stepsTimed = 0;
  int substepsPerFrame = 1;       ///< ceil(frame time / h)
  double cgIterationsMean = 0;    ///< implicit Euler: conjugate-gradient iterations per timed step
  double factorMsOnce = 0;        ///< fast-mass-spring: the first (untimed) step's factorisation, ms
  int localGlobalIterations = 0;  ///< fast-mass-spring: the solver's setting
  double msPerFrame() const { return msPerStep * substepsPerFrame; }
  double springsPerSecond() const { return double(springs) / (msPerStep * 1e-3); }
};

/// Times steps of `integrator` at step `stepS` from rest, after one untimed step (which factors
/// the fast solver's matrix and warms the conjugate gradients).
IntegratorTiming timeIntegrator(sim::Integrator integrator, const BenchPatch& patch, double stepS,
                                const IntegratorBenchConfig& config = {});

struct ForcePassTiming {
  std::size_t springs = 0;
  int threads = 1;
  double ms = 0.0, msBest = 0.0;  ///< ms, median and smallest
  double springsPerSecond() const { return double(springs) / (ms * 1e-3); }
  double springsPerSecondBest() const { return double(springs) / (msBest * 1e-3); }
};

/// The force pass alone (springs with damping, gravity, Rayleigh) at `threads` threads (set in
/// the patch's system config), at least 5 passes and 200 ms, at most 1000 passes.
ForcePassTiming timeForcePass(BenchPatch& patch, int threads);

}  // namespace tissue::studies
