#pragma once
/// \file
/// The Simulator advances a system by frames: substeps of one integrator, each checked for
/// divergence (non-finite values, energy blow-up, over-stretched springs). A diverged frame is
/// rolled back to its start and retried with more substeps, then with a more stable integrator;
/// every such event is reported, and the state handed out never holds NaN or Inf.

#include <string>
#include <vector>

#include "tissue/core/result.h"
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
};

/// How a diverged frame is recovered.
struct RecoveryConfig {
  int maxSubsteps = 64;          ///< substeps are doubled up to this before switching integrator
  bool switchIntegrator = true;  ///< then explicit -> symplectic -> implicit Euler, Verlet -> implicit;
                                 ///< implicit Euler and fast-mass-spring (both unconditionally
                                 ///< stable) end the chain
  /// After this many frames without divergence, a recovered simulator steps back towards the
  /// configured setting: substeps are halved (not below SimulatorConfig::substeps). A replaced
  /// integrator stays replaced (it failed at maxSubsteps). A transient (a tool backing off compressed tissue)
  /// then costs a few expensive frames instead of every later frame. 0 keeps the recovered setting for good.
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
  Integrator nextIntegrator{};  ///< the retry's integrator
  int nextSubsteps = 0;         ///< the retry's substeps
  bool recovered = false;       ///< false: every retry diverged; the frame-start state was kept at rest
};

/// What one frame did, phases timed in ms.
struct FrameReport {
  Integrator integrator{};  ///< the integrator that completed the frame
  int substeps = 0;         ///< its substeps
  int cgIterations = 0;     ///< summed over substeps (implicit Euler)
  std::vector<DivergenceEvent> events;
  double integrateMs = 0.0;  ///< forces and integration
  double checkMs = 0.0;      ///< divergence checks
  double rollbackMs = 0.0;   ///< saving and restoring state
  double hookMs = 0.0;       ///< the substep hook (contact, grasp), every try of the frame
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

 private:
  Simulator(MassSpringSystem system, State initial, const SimulatorConfig& config);
  /// Runs the frame's substeps from m_state; returns the divergence reason, empty when none.
  /// Counts quiet frames and, after RecoveryConfig::relaxAfterFrames of them, steps a recovered
  /// setting back towards the configured one.
  void relaxRecovery(bool quietFrame);
  std::string tryFrame(Integrator integrator, int substeps, double energyCeiling, FrameReport& report);

  MassSpringSystem m_system;
  State m_state;
  State m_frameStart;
  SimulatorConfig m_config;
  Integrator m_integrator;
  int m_substeps;
  int m_quietFrames = 0;  ///< frames since the last divergence event
  long m_frame = 0;
  double m_energyFloor = 0.0;
  StepWorkspace m_workspace;
  SubstepHook* m_hook = nullptr;
  std::vector<Vec3d> m_substepStartX;   ///< mm, positions before the current step (hook only)
  std::vector<double> m_baseInvMasses;  ///< inverse masses with the pins only (1/g)
};

}  // namespace tissue::sim
