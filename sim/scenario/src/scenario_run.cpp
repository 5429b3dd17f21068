// Running a scenario: frames, scripted grasps and releases, per-frame metrics.
#include "tissue/scenario/scenario_run.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "tissue/core/stopwatch.h"
#include "tissue/sim/forces.h"

namespace tissue::scenario {
namespace {

/// g*mm^2/s^2 per joule: 1 J = 1e3 g * 1e6 mm^2 / s^2.
constexpr double kEnergyPerJoule = 1e9;

bool stateFinite(const sim::State& s) {
  for (std::size_t k = 0; k < s.x.size(); ++k)
    if (!sim::isFinite(s.x[k]) || !sim::isFinite(s.v[k])) return false;
  return true;
}

}  // namespace

double maxSampleN(const FrameMetrics& f) {
  double m = 0.0;
  for (const sim::Vec3d& s : f.forceSamplesN)
    m = std::max(m, sim::length(s));
  return m;
}

ScenarioRun::ScenarioRun(Scenario scenario, ScenarioMesh mesh, sim::Simulator simulator)
    : m_scenario(std::move(scenario)), m_mesh(std::move(mesh)), m_simulator(std::move(simulator)) {}

Result<std::unique_ptr<ScenarioRun>> ScenarioRun::create(const Scenario& scenario) {
  auto mesh = loadScenarioMesh(scenario);
  if (!mesh) return mesh.error();
  auto system = buildSystem(scenario, *mesh);
  if (!system) return system.error();
  sim::SimulatorConfig config{.integrator = scenario.integrator,
                              .frameTime = scenario.frameTime,
                              .substeps = scenario.substeps,
                              .solver = scenario.solver,
                              .limits = {},
                              .recovery = scenario.recovery};
  // solver.tolerance also ends the fast solver's local/global iterations early (docs/SCENARIOS.md).
  config.solver.localGlobalTolerance = scenario.solver.relativeTolerance;
  auto simulator =
      sim::Simulator::create(std::move(*system), sim::restState(mesh->simulatedRestPositions()), config);
  if (!simulator) return Error{scenario.file.string() + ": " + simulator.error().message};
  std::unique_ptr<ScenarioRun> run(new ScenarioRun(scenario, std::move(*mesh), std::move(*simulator)));
  if (scenario.instrument) {
    auto tool = sim::Instrument::create(scenario.instrument->config, scenario.instrument->path);
    if (!tool) return Error{scenario.file.string() + ": instrument: " + tool.error().message};
    run->m_instrument.emplace(std::move(*tool));
    // On a lattice the tool touches the render surface; its corrections go to the nodes.
    if (const auto& lattice = run->m_mesh.lattice)
      if (auto ok = run->m_instrument->setEmbedding({lattice->vertexNodes, lattice->vertexWeights},
                                                    lattice->nodeCount());
          !ok)
        return Error{scenario.file.string() + ": instrument: " + ok.error().message};
    run->m_simulator.setSubstepHook(&*run->m_instrument);
  }
  return run;
}

std::vector<Float3> ScenarioRun::positions() const {
  if (!m_mesh.lattice) return sim::toFloat3(m_simulator.state().x);
  std::vector<Float3> surface(m_mesh.positions.size());
  sim::embedPositions(*m_mesh.lattice, m_simulator.state().x, surface);
  return surface;
}

Result<FrameMetrics> ScenarioRun::advance() {
  Stopwatch total;
  FrameMetrics m;
  m.frame = m_simulator.frame();
  // Scripted grasps and releases due before this frame starts.
  Stopwatch actions;
  const double start = static_cast<double>(m_simulator.frame()) * m_scenario.frameTime;
  if (m_instrument && !m_live) {
    const auto& list = m_scenario.instrument->actions;
    for (; m_nextAction < list.size() && list[m_nextAction].time <= start + 1e-9; ++m_nextAction) {
      if (list[m_nextAction].grasp) {
        if (auto taken = m_instrument->grasp(m_simulator); !taken) return taken.error();
      } else if (auto released = m_instrument->release(m_simulator); !released) {
        return released.error();
      }
    }
  }
  m.actionMs = actions.elapsedMs();

  const sim::FrameReport report = m_simulator.advanceFrame();
  const sim::State& state = m_simulator.state();
  const sim::MassSpringSystem& system = m_simulator.system();
  m.timeS = start + m_scenario.frameTime;
  m.integrator = report.integrator;
  m.substeps = report.substeps;
  m.divergenceEvents = static_cast<int>(report.events.size());
  if (!report.events.empty()) m.divergenceReason = report.events.front().reason;
  m.integrateMs = report.integrateMs;
  m.contactMs = report.hookMs;
  m.checkMs = report.checkMs;
  m.rollbackMs = report.rollbackMs;
  m.factorMs = report.factorMs;
  m.degrade = report.degrade;
  m.recoveryMs = report.recoveryMs;
  m.stepsRun = report.stepsRun;
  m.solverIterations = report.solverIterations;
  if (m_instrument) {
    auto tool = m_instrument->lastFrame();
    m.forceN = tool.forceN;
    m.contacts = tool.contacts;
    m.grasped = tool.grasped;
    m.contactDepthMm = tool.maxContactDepthMm;
    m.forceSamplesN = std::move(tool.forceSamplesN);
    m.sampleIntervalS = tool.sampleIntervalS;
    m.toolSubMoves = tool.subMoves;
    m.teleports = tool.teleports;
  }
  m.forceMagnitudeN = sim::length(m.forceN);
  m.maxStretch = sim::maxStretch(system, state.x);
  m.kineticJ = sim::kineticEnergy(system, state.v) / kEnergyPerJoule;
  m.elasticJ = sim::elasticEnergy(system, state.x) / kEnergyPerJoule;
  m.finite = stateFinite(state) && std::isfinite(m.forceMagnitudeN);
  m.totalMs = total.elapsedMs();
  return m;
}

RunSummary summarize(const std::vector<FrameMetrics>& frames) {
  RunSummary s;
  s.frames = static_cast<long>(frames.size());
  for (const FrameMetrics& f : frames) {
    if (!f.finite) ++s.nanFrames;
    if (std::isfinite(f.forceMagnitudeN)) s.maxForceN = std::max(s.maxForceN, f.forceMagnitudeN);
    if (!f.degrade.empty()) ++s.degradedFrames;
    s.maxFactorMs = std::max(s.maxFactorMs, f.factorMs);
    s.maxFrameSteps = std::max(s.maxFrameSteps, f.stepsRun);
    s.maxFrameSolverIterations = std::max(s.maxFrameSolverIterations, f.solverIterations);
    s.teleports += f.teleports;
    s.meanForceN += f.forceMagnitudeN;
    s.divergenceEvents += f.divergenceEvents;
    s.meanIntegrateMs += f.integrateMs;
    s.meanContactMs += f.contactMs;
    s.meanCheckMs += f.checkMs;
    s.meanRollbackMs += f.rollbackMs;
    s.meanActionMs += f.actionMs;
    s.meanTotalMs += f.totalMs;
  }
  if (s.frames > 0) {
    const double n = static_cast<double>(s.frames);
    for (double* x : {&s.meanForceN, &s.meanIntegrateMs, &s.meanContactMs, &s.meanCheckMs, &s.meanRollbackMs,
                      &s.meanActionMs, &s.meanTotalMs})
      *x /= n;
  }
  return s;
}

std::string framesCsv(const std::vector<FrameMetrics>& frames) {
  std::ostringstream out;
  out.precision(9);
  out << "frame,time_s,integrator,substeps,force_x_N,force_y_N,force_z_N,force_N,contacts,grasped,max_"
         "stretch,"
         "kinetic_J,elastic_J,divergence_events,integrate_ms,contact_ms,check_ms,rollback_ms,action_ms,total_"
         "ms,divergence_reason,degrade,recovery_ms,factor_ms,force_samples,max_sample_force_N,contact_depth_"
         "mm\n";
  for (const FrameMetrics& f : frames)
    out << f.frame << ',' << f.timeS << ',' << sim::integratorName(f.integrator) << ',' << f.substeps << ','
        << f.forceN.x << ',' << f.forceN.y << ',' << f.forceN.z << ',' << f.forceMagnitudeN << ','
        << f.contacts << ',' << f.grasped << ',' << f.maxStretch << ',' << f.kineticJ << ',' << f.elasticJ
        << ',' << f.divergenceEvents << ',' << f.integrateMs << ',' << f.contactMs << ',' << f.checkMs << ','
        << f.rollbackMs << ',' << f.actionMs << ',' << f.totalMs << ',' << f.divergenceReason << ','
        << f.degrade << ',' << f.recoveryMs << ',' << f.factorMs << ',' << f.forceSamplesN.size() << ','
        << maxSampleN(f) << ',' << f.contactDepthMm << '\n';
  return out.str();
}

}  // namespace tissue::scenario
