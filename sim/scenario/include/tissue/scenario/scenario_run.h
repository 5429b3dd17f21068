#pragma once
/// \file
/// Running a scenario frame by frame: the simulator, the instrument with its scripted grasps and
/// releases, and the per-frame metrics that `tissue-sim simulate` writes and the demo reports.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "tissue/scenario/scenario.h"
#include "tissue/sim/simulator.h"

namespace tissue::scenario {

/// What one frame did.
struct FrameMetrics {
  long frame = 0;                ///< 0-based
  double timeS = 0.0;            ///< s at the end of the frame
  sim::Integrator integrator{};  ///< the one that completed the frame
  int substeps = 0;
  sim::Vec3d forceN{};           ///< N, on the tool (zero without an instrument)
  double forceMagnitudeN = 0.0;  ///< N
  std::uint32_t contacts = 0;    ///< vertices the tool's last sub-move projected
  std::uint32_t grasped = 0;     ///< vertices held
  double maxStretch = 0.0;       ///< largest L / L0
  double kineticJ = 0.0;         ///< J
  double elasticJ = 0.0;         ///< J
  int divergenceEvents = 0;      ///< rollbacks in this frame
  std::string divergenceReason;  ///< the first rollback's reason ("non-finite", "energy blow-up", ...)
  bool finite = true;            ///< every position, velocity and the force are finite
  double integrateMs = 0.0;      ///< forces and integration
  double contactMs = 0.0;        ///< the instrument (contact, grasp), inside the substeps
  double checkMs = 0.0;          ///< divergence checks
  double rollbackMs = 0.0;       ///< saving and restoring state
  double actionMs = 0.0;         ///< scripted grasps and releases
  double totalMs = 0.0;          ///< the whole frame
  double factorMs = 0.0;         ///< fast-mass-spring: (re)factoring in this frame (part of integrateMs)
  std::string degrade;           ///< "" or the bounded degrade taken ("fallback <integrator>", "relaxed")
  double recoveryMs = 0.0;       ///< wall time of the frame's diverged tries
  /// The tool force per substep (N), sampleIntervalS apart: the haptic-rate samples.
  std::vector<sim::Vec3d> forceSamplesN;
  double sampleIntervalS = 0.0;  ///< s
  double contactDepthMm = 0.0;   ///< lattice: deepest surface vertex left inside the tool (mm)
  int stepsRun = 0;              ///< integrator steps, every try (sim::FrameReport::stepsRun)
  int solverIterations = 0;      ///< CG and local/global iterations, every try
  int toolSubMoves = 0;          ///< the tool's sub-moves (last try)
  int teleports = 0;             ///< substeps whose tool sweep exceeded InstrumentConfig::maxSubMoves
};

/// The largest |F| (N) among a frame's per-substep force samples.
double maxSampleN(const FrameMetrics& frame);

/// A scenario being run: owns the simulator and the instrument (whose address the simulator
/// keeps, hence created behind a unique_ptr).
class ScenarioRun {
 public:
  /// Loads the mesh and builds the system, the simulator and the instrument.
  static Result<std::unique_ptr<ScenarioRun>> create(const Scenario& scenario);

  /// Applies the scripted actions that are due, then advances one frame.
  Result<FrameMetrics> advance();

  // Live input (viewer, replayed session, host): defined in scenario_live.cpp.
  /// The tool moves linearly to `pose` (mm) over the next frame; the scripted path and actions
  /// stop from now on. Fails without an instrument or on a non-finite pose (naming it).
  Result<void> setInstrumentTarget(const sim::ToolPose& pose);
  /// The tool's radius (mm, > 0) from the next frame on. Fails without an instrument or on a
  /// bad radius.
  Result<void> setInstrumentRadius(double radiusMm);
  /// Grasps (true) or releases (false) now; a no-op when already in that state.
  Result<void> setGrasp(bool grasp);

  const Scenario& scenario() const { return m_scenario; }
  const ScenarioMesh& mesh() const { return m_mesh; }
  const sim::Simulator& simulator() const { return m_simulator; }
  /// The stated bound on one frame's steps and solver iterations (FrameMetrics never exceed it).
  sim::FrameWorkBound frameWorkBound() const { return m_simulator.frameWorkBound(); }
  /// nullptr when the scenario has no instrument.
  const sim::Instrument* instrument() const { return m_instrument ? &*m_instrument : nullptr; }
  /// Positions (mm) per geometric vertex, as floats for the mesh module and the renderer.
  /// With a lattice, the surface vertices follow the simulated nodes by the embedding weights.
  std::vector<Float3> positions() const;

 private:
  ScenarioRun(Scenario scenario, ScenarioMesh mesh, sim::Simulator simulator);

  Scenario m_scenario;
  ScenarioMesh m_mesh;
  sim::Simulator m_simulator;
  std::optional<sim::Instrument> m_instrument;
  std::size_t m_nextAction = 0;
  bool m_live = false;  ///< live input replaced the scripted path and actions
};

/// Summary over frames: counts, NaN frames, the largest and mean |F| (N), divergence events,
/// mean ms per phase.
struct RunSummary {
  long frames = 0;
  long nanFrames = 0;
  double maxForceN = 0.0;
  double meanForceN = 0.0;
  long divergenceEvents = 0;
  long degradedFrames = 0;           ///< frames that took a fallback integrator or were relaxed
  double maxFactorMs = 0.0;          ///< the longest fast-solver (re)factoring of a frame, ms
  int maxFrameSteps = 0;             ///< the most integrator steps of a frame (all tries)
  int maxFrameSolverIterations = 0;  ///< the most solver iterations of a frame (all tries)
  long teleports = 0;                ///< tool substeps past the sub-move cap
  double meanIntegrateMs = 0.0, meanContactMs = 0.0, meanCheckMs = 0.0, meanRollbackMs = 0.0,
         meanActionMs = 0.0, meanTotalMs = 0.0;
};
RunSummary summarize(const std::vector<FrameMetrics>& frames);

/// The metrics as CSV: a header line, then one line per frame.
std::string framesCsv(const std::vector<FrameMetrics>& frames);

}  // namespace tissue::scenario
