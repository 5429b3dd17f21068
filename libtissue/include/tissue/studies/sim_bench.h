#pragma once
/// \file
/// The step cost of the mass-spring integrators on generated patches of a chosen size, and of the
/// force pass alone: what `tissue-sim sim-bench` reports. GL-free. Lengths in mm, masses in g,
/// times in s (steps) and ms (timings: the median and the best of the timed steps, which resist
/// the noise of a shared machine).

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "tissue/core/result.h"
#include "tissue/core/statistics.h"
#include "tissue/scenario/scenario.h"
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
  std::string skipped;            ///< why it was not run (then no timings), e.g. a factor too large
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

/// One integrator on the organ's per-frame path: mean ms per frame of each phase.
struct FramePathTiming {
  sim::Integrator integrator = sim::Integrator::SymplecticEuler;
  int substepsPerFrame = 1;  ///< explicit: below 0.9 of 2/omega_max; implicit: one step a frame
  std::size_t vertices = 0, springs = 0;
  double simulateMs = 0, positionsInMs = 0, normalsMs = 0, planesMs = 0, tangentsMs = 0;  ///< ms per frame
  double meanRefittedPlaneFraction = 0;  ///< planes re-fitted / vertices, mean over frames
  double factorMsOnce = 0;  ///< fast-mass-spring: the one-off factorisation, ms (not in simulateMs)
  double totalMs() const { return simulateMs + positionsInMs + normalsMs + planesMs + tangentsMs; }
};

/// The organ as a spring network (0.1 N/mm edges, 0.02 N/mm bending, 1e-5 N*s/mm damping,
/// 0.0106 g/mm^2, the lowest 10% in z pinned, no gravity, Rayleigh alpha 2 /s), released from a
/// poke (the top 5% of vertices pushed in 8 mm); per 1/60 s frame one simulation step, then
/// DeformableSurface::update (positions in, normals, incremental plane re-fit, tangents).
struct FramePathBench {
  std::filesystem::path mesh;
  int frames = 0;
  double frameTimeS = 1.0 / 60.0;              ///< s
  float moveToleranceMm = 1e-3f;               ///< mm: vertices that move less keep their planes
  std::vector<FramePathTiming> integrators{};  ///< symplectic Euler, implicit Euler, fast-mass-spring
};
/// `mesh`: an OBJ with UVs, mm; `sigmaTPerMm`: its first layer's smallest extinction (mm^-1).
Result<FramePathBench> benchFramePath(const std::filesystem::path& mesh, float sigmaTPerMm, int frames,
                                      int threads);

/// A scenario run frame by frame as `tissue-sim simulate` runs it, contact and grasp included.
struct ScenarioBench {
  std::filesystem::path scenario;
  sim::Integrator integrator = sim::Integrator::SymplecticEuler;
  int substeps = 1, frames = 0;
  std::size_t simulatedVertices = 0, springs = 0, surfaceVertices = 0;
  SampleSummary frameMs{}, substepMs{};  ///< ms: per frame, and per frame / substeps
  double forceUpdateHz = 0;              ///< force samples per simulated second
  long divergenceEvents = 0, degradedFrames = 0;
  double maxForceN = 0, maxFactorMs = 0;
  std::optional<double> refactorFrameMsMax{};  ///< ms, the slowest frame that refactored during a grasp
  double explicitLimitMs = 0;                  ///< ms, 2 / omega_max (Gershgorin) of the simulated system
};
/// `frames` 0: the scenario's; `integrator`: instead of the scenario's.
Result<ScenarioBench> benchScenario(const std::filesystem::path& scenario,
                                    const scenario::ScenarioPaths& paths, int frames,
                                    std::optional<sim::Integrator> integrator);

/// Everything `tissue-sim sim-bench` measures.
struct SimBenchConfig {
  std::size_t maxSprings = 1000000;  ///< patches of 1e3, 1e4, 1e5, 1e6 springs up to this
  int threads = 2;                   ///< threads of the simulator passes
  /// The fast solver is run on patches up to this size: the sparse Cholesky factor's fill (AMD
  /// ordering) grows about as n^1.5 on these grids: 4.5 million entries at 10^5 springs, over
  /// 10^8 (more than a gigabyte, minutes to factor) at 10^6.
  std::size_t fastSolverMaxSprings = 300000;
  std::filesystem::path framePathMesh;  ///< empty: no frame path
  float framePathSigmaTPerMm = 1.5f;    ///< mm^-1
  int framePathFrames = 30;
  std::filesystem::path scenario;  ///< empty: no scenario measurement
  scenario::ScenarioPaths scenarioPaths;
  int scenarioFrames = 0;                             ///< 0: the scenario's
  std::optional<sim::Integrator> scenarioIntegrator;  ///< instead of the scenario's
};

struct SimBench {
  int threads = 0;
  std::vector<IntegratorTiming> results{};   ///< per patch, every integrator
  std::vector<ForcePassTiming> forcePass{};  ///< per patch, at 1 and `threads` threads
  std::optional<FramePathBench> framePath{};
  std::optional<ScenarioBench> scenario{};
  double benchS = 0;  ///< s, wall time of it all
};
Result<SimBench> runSimBench(const SimBenchConfig& config);

/// The bench as JSON text: threads, frame_time_s, model, results (integrator, springs,
/// ms_per_step, springs_per_second, ...), force_pass, frame_path, scenario, bench_s.
std::string simBenchJson(const SimBench& bench);
/// The bench as readable tables.
std::string simBenchText(const SimBench& bench);

}  // namespace tissue::studies
