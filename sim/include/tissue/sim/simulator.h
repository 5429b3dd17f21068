#pragma once
/// \file
/// The Simulator advances a system by frames: substeps of one integrator, each checked for
/// divergence (non-finite values, energy blow-up, over-stretched springs). A diverged frame is
/// rolled back to its start and retried once with a more stable integrator at the same substeps,
/// if the frame's time budget allows; otherwise (or when the retry diverges too) it is relaxed:
/// the frame-start positions are kept at rest. A frame thus never runs more than two tries of its
/// substeps (frameWorkBound(), counted in steps and solver iterations), whatever happens; in wall
/// time a diverged frame's retry stays within the budget, while a slow fallback integrator that
/// completes its frames (implicit Euler on a very stiff system) costs its own steps' time. Every such event
/// is reported, and the state handed out never holds NaN or Inf.

#include <string>
#include <vector>

#include "tissue/core/result.h"
#include "tissue/core/stopwatch.h"
#include "tissue/sim/integrators.h"
#include "tissue/sim/substep_hook.h"
#include "tissue/sim/system.h"

namespace tissue::sim {

/// When a substep counts as diverged.
struct DivergenceLimits {
  double maxStretch = 3.0;     ///< L / L0 of any spring above this (unitless)
  double energyGrowth = 10.0;  ///< kinetic + elastic energy above this times the frame-start energy
                               ///< (g*mm^2/s^2), floored as below so that a system at rest may start
  double floorStrain = 0.1;    ///< floor: every spring strained this much (unitless) plus every mass
                               ///< dropped by the mean rest length under gravity
  /// The stretch and energy tests (a pass over the springs) run at this many evenly spread
  /// substeps of a frame, and at its last; non-finite values are tested every substep. 0: every
  /// substep. A divergence caught late is rolled back to the frame start all the same.
  int checksPerFrame = 4;
};

/// How a diverged frame is recovered: a bounded degrade (at most one retry, never more substeps).
struct RecoveryConfig {
  /// Retry a diverged frame once with the next more stable integrator (explicit -> symplectic
  /// -> implicit Euler, Verlet -> implicit Euler) at the same substeps; implicit Euler and
  /// fast-mass-spring (both unconditionally stable) have none and go straight to relaxing.
  bool switchIntegrator = true;
  /// ms of wall time one frame may spend: the retry starts only while less than half of it is
  /// spent, and is abandoned (the frame relaxed) once the frame has spent all of it. <= 0: no limit.
  double frameBudgetMs = 16.0;
  /// After this many frames without divergence a replaced integrator is replaced back by the
  /// configured one (a transient, such as a tool backing off compressed tissue, then costs a few
  /// frames instead of every later frame). 0 keeps the fallback for good. When the configured
  /// integrator diverges again within this many frames of coming back (it is unstable for the
  /// system, not hit by a transient: explicit Euler at h far above 2/omega), the wait doubles,
  /// up to 64 times this, so that a hopeless setting costs a retry ever more rarely.
  int relaxAfterFrames = 10;
};

/// Simulator settings.
struct SimulatorConfig {
  Integrator integrator = Integrator::ImplicitEuler;
  double frameTime = 1.0 / 60.0;  ///< s advanced by one advanceFrame()
  int substeps = 1;               ///< steps per frame, h = frameTime / substeps
  ImplicitSolverConfig solver{};
  DivergenceLimits limits{};
  RecoveryConfig recovery{};
};

/// One divergence and what was done about it.
struct DivergenceEvent {
  long frame = 0;               ///< frame index (0 = first advanceFrame)
  std::string reason;           ///< "non-finite", "energy blow-up" or "over-stretched spring"
  Integrator integrator{};      ///< the one that diverged
  int substeps = 0;             ///< with this many substeps
  Integrator nextIntegrator{};  ///< the retry's integrator (the same one when the frame was relaxed)
  int nextSubsteps = 0;         ///< the retry's substeps (always `substeps`: never raised)
  bool recovered = false;       ///< false: the frame was relaxed: its start positions kept, at rest
  std::string action;           ///< "retry with <integrator>" or "relaxed to rest"
};

/// What one frame did, phases timed in ms.
struct FrameReport {
  Integrator integrator{};  ///< the integrator that completed the frame
  int substeps = 0;         ///< its substeps
  int cgIterations = 0;     ///< summed over substeps (implicit Euler)
  /// The frame's work, counted rather than timed (every try included): integrator steps run,
  /// and the solver iterations (conjugate-gradient plus fast-mass-spring local/global) in them.
  /// Never above Simulator::frameWorkBound().
  int stepsRun = 0;
  int solverIterations = 0;
  std::vector<DivergenceEvent> events;
  double integrateMs = 0.0;  ///< forces and integration
  double checkMs = 0.0;      ///< divergence checks
  double rollbackMs = 0.0;   ///< saving and restoring state
  double hookMs = 0.0;       ///< the substep hook (contact, grasp), every try of the frame
  double factorMs = 0.0;     ///< fast-mass-spring: (re)factoring the matrix, part of integrateMs
  bool refactored = false;   ///< fast-mass-spring: the matrix was factored in this frame
  /// "" (no divergence), "fallback <integrator>" (a retry completed the frame) or "relaxed"
  /// (the frame-start positions were kept at rest).
  std::string degrade;
  double recoveryMs = 0.0;  ///< wall time of the tries that diverged (the degrade's cost)
};

/// The most work one advanceFrame() may do: at most two tries (the configured or current
/// integrator, one retry) of `substeps` steps each, each step at most the solver's iteration
/// limit (ImplicitSolverConfig::maxIterations for CG, localGlobalIterations for the fast solver).
struct FrameWorkBound {
  int steps = 0;
  int solverIterations = 0;
};

/// A system, its state and the frame loop. After a recovery the more stable setting is kept
/// for later frames (reported in each FrameReport) until RecoveryConfig::relaxAfterFrames quiet
/// frames step it back towards the configured one.
class Simulator {
 public:
  /// Fails on a state whose sizes do not match the system, non-finite values, or bad settings.
  static Result<Simulator> create(MassSpringSystem system, State initial, const SimulatorConfig& config);

  /// Advances one frame (config.frameTime seconds).
  FrameReport advanceFrame();

  /// Runs `hook` inside every substep (nullptr: none). Not owned; it must outlive its use.
  void setSubstepHook(SubstepHook* hook) { m_hook = hook; }
  /// Makes `vertices` kinematic (inverse mass 0: no force moves them, a hook sets their motion)
  /// in addition to the pinned ones, replacing the previous kinematic set; an empty span frees
  /// them again (inverse mass 1/m, unless pinned). Fails on an index out of range.
  Result<void> setKinematic(std::span<const std::uint32_t> vertices);

  const State& state() const { return m_state; }
  const MassSpringSystem& system() const { return m_system; }
  Integrator integrator() const { return m_integrator; }
  int substeps() const { return m_substeps; }
  long frame() const { return m_frame; }
  /// The stated bound on one frame's work (FrameReport::stepsRun, solverIterations).
  FrameWorkBound frameWorkBound() const;

 private:
  Simulator(MassSpringSystem system, State initial, const SimulatorConfig& config);
  /// Runs the frame's substeps from m_state; returns the divergence reason, empty when none.
  /// Counts quiet frames and, after RecoveryConfig::relaxAfterFrames of them, steps a recovered
  /// setting back towards the configured one.
  void relaxRecovery(bool quietFrame);
  std::string tryFrame(Integrator integrator, int substeps, double energyCeiling, FrameReport& report,
                       double deadlineMs, const Stopwatch& frameClock);

  MassSpringSystem m_system;
  State m_state;
  State m_frameStart;
  SimulatorConfig m_config;
  Integrator m_integrator;
  int m_substeps;
  int m_quietFrames = 0;   ///< frames since the last divergence event
  int m_backoff = 1;       ///< relaxAfterFrames multiplier: doubled each time a restore fails
  long m_restoredAt = -1;  ///< frame at which the configured integrator was last restored
  long m_frame = 0;
  double m_energyFloor = 0.0;
  StepWorkspace m_workspace;
  SubstepHook* m_hook = nullptr;
  std::vector<Vec3d> m_substepStartX;   ///< mm, positions before the current step (hook only)
  std::vector<double> m_baseInvMasses;  ///< inverse masses with the pins only (1/g)
  /// Elastic energy change (g*mm^2/s^2) of the hook's moves: over the springs of the vertices
  /// whose position differs from m_afterStepX.
  double hookElasticChange();
  std::vector<Vec3d> m_afterStepX;             ///< mm, positions after the step, before the hook
  std::vector<std::uint8_t> m_springMarks;     ///< scratch of hookElasticChange
  std::vector<std::uint32_t> m_markedSprings;  ///< scratch of hookElasticChange
  std::uint64_t m_revision = 1;                ///< bumped on every change of the system (fast solver key)
};

}  // namespace tissue::sim
