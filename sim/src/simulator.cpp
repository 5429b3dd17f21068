#include "tissue/sim/simulator.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "tissue/core/stopwatch.h"

namespace tissue::sim {
namespace {

bool allFinite(const State& s) {
  for (std::size_t k = 0; k < s.x.size(); ++k)
    if (!isFinite(s.x[k]) || !isFinite(s.v[k])) return false;
  return true;
}

/// The next, more stable integrator to fall back to; the same one when there is none.
Integrator moreStable(Integrator integrator) {
  switch (integrator) {
    case Integrator::ExplicitEuler:
      return Integrator::SymplecticEuler;
    case Integrator::SymplecticEuler:
    case Integrator::VelocityVerlet:
      return Integrator::ImplicitEuler;
    case Integrator::ImplicitEuler:
    case Integrator::FastMassSpring:  // unconditionally stable, like implicit Euler: the end of the chain
      return integrator;
  }
  return integrator;
}

/// Elastic energy (g*mm^2/s^2) and the largest L / L0 in one pass over the springs (the
/// divergence check runs every substep; two separate passes would double its cost). NaN in a
/// position makes the stretch NaN.
struct SpringCheck {
  double energy = 0.0, maxStretch = 0.0;
};
SpringCheck checkSprings(const MassSpringSystem& system, std::span<const Vec3d> x) {
  const SpringNetwork& s = system.springs;
  SpringCheck c;
  for (std::size_t k = 0; k < s.size(); ++k) {
    const double len = length(x[s.j[k]] - x[s.i[k]]);
    const double stretch = len - s.restLength[k];
    c.energy += 0.5 * s.stiffness[k] * stretch * stretch;
    const double ratio = len / s.restLength[k];
    if (!(ratio <= c.maxStretch)) c.maxStretch = ratio;  // NaN propagates
  }
  return c;
}

}  // namespace

Result<Simulator> Simulator::create(MassSpringSystem system, State initial, const SimulatorConfig& config) {
  if (initial.x.size() != system.vertexCount() || initial.v.size() != system.vertexCount())
    return Error{"simulator: the state has " + std::to_string(initial.x.size()) + " positions and " +
                 std::to_string(initial.v.size()) + " velocities for " +
                 std::to_string(system.vertexCount()) + " vertices; give one of each per vertex"};
  if (!allFinite(initial)) return Error{"simulator: the initial state holds NaN or Inf"};
  if (!(config.frameTime > 0.0) || !std::isfinite(config.frameTime))
    return Error{"simulator: frameTime must be a positive number of seconds"};
  if (config.substeps < 1 || config.substeps > 4096)
    return Error{"simulator: substeps must be between 1 and 4096"};
  if (!std::isfinite(config.recovery.frameBudgetMs))
    return Error{"simulator: recovery.frameBudgetMs must be a number of ms (<= 0: no limit)"};
  if (!(config.limits.maxStretch > 1.0) || !(config.limits.energyGrowth > 1.0) ||
      !(config.limits.floorStrain > 0.0))
    return Error{"simulator: limits.maxStretch and limits.energyGrowth must be > 1, limits.floorStrain > 0"};
  if (config.limits.checksPerFrame < 0) return Error{"simulator: limits.checksPerFrame must be >= 0"};
  return Simulator(std::move(system), std::move(initial), config);
}

Simulator::Simulator(MassSpringSystem system, State initial, const SimulatorConfig& config)
    : m_system(std::move(system)),
      m_state(std::move(initial)),
      m_config(config),
      m_integrator(config.integrator),
      m_substeps(config.substeps),
      m_baseInvMasses(m_system.invMasses) {
  // Energy floor of the blow-up test: every spring strained by floorStrain, plus every mass
  // dropped by the mean rest length under gravity (what a release from rest may gain).
  const SpringNetwork& s = m_system.springs;
  double meanRest = 0.0;
  for (std::size_t e = 0; e < s.size(); ++e) {
    const double stretch = m_config.limits.floorStrain * s.restLength[e];
    m_energyFloor += 0.5 * s.stiffness[e] * stretch * stretch;
    meanRest += s.restLength[e] / static_cast<double>(s.size());
  }
  const double g = length(m_system.config.gravity);
  for (double m : m_system.masses)
    m_energyFloor += m * g * meanRest;
}

Result<void> Simulator::setKinematic(std::span<const std::uint32_t> vertices) {
  for (std::uint32_t k : vertices)
    if (k >= m_system.vertexCount())
      return Error{"simulator: kinematic vertex " + std::to_string(k) + " is out of range (" +
                   std::to_string(m_system.vertexCount()) + " vertices)"};
  m_system.invMasses = m_baseInvMasses;
  for (std::uint32_t k : vertices)
    m_system.invMasses[k] = 0.0;
  m_workspace.previousDeltaV.clear();  // the warm start belonged to the old set of free vertices
  m_workspace.fast.setSystemRevision(++m_revision);  // the fast solver refactors (pins changed)
  return {};
}

std::string Simulator::tryFrame(Integrator integrator, int substeps, double energyCeiling,
                                FrameReport& report, double deadlineMs, const Stopwatch& frameClock) {
  const double h = m_config.frameTime / substeps;
  // Only this simulator edits its system (setKinematic bumps the revision): the fast solver may
  // key its factor on the revision instead of fingerprinting the arrays every step.
  m_workspace.fast.setSystemRevision(m_revision);
  for (int k = 0; k < substeps; ++k) {
    if (deadlineMs > 0.0 && frameClock.elapsedMs() > deadlineMs) return "over the frame budget";
    if (m_hook) m_substepStartX = m_state.x;  // for the hook's swept contact
    Stopwatch integrate;
    const StepStats stats = step(integrator, m_system, m_state, h, m_workspace, m_config.solver);
    report.cgIterations += stats.cgIterations;
    report.stepsRun += 1;
    report.solverIterations += stats.cgIterations + stats.localGlobalIterations;
    report.integrateMs += integrate.elapsedMs();
    report.factorMs += stats.factorMs;
    report.refactored = report.refactored || stats.refactored;
    double hookInput = 0.0;
    if (m_hook) {
      // Energy a kinematic hook puts in (a tool pushing or pulling) is not a divergence: the
      // blow-up ceiling rises by it. Its elastic part is summed over the springs of the
      // vertices the hook moved only (no full spring pass).
      Stopwatch save;
      m_afterStepX = m_state.x;
      const double kineticBefore = kineticEnergy(m_system, m_state.v);
      report.checkMs += save.elapsedMs();
      Stopwatch hook;
      const double frameStart = static_cast<double>(m_frame) * m_config.frameTime;
      m_hook->afterSubstep(
          m_system, m_state,
          {m_frame, frameStart, m_config.frameTime, frameStart + k * h, h, k, substeps, m_substepStartX});
      report.hookMs += hook.elapsedMs();
      Stopwatch input;
      hookInput = kineticEnergy(m_system, m_state.v) - kineticBefore + hookElasticChange();
      report.checkMs += input.elapsedMs();
    }
    if (hookInput > 0.0) energyCeiling += m_config.limits.energyGrowth * hookInput;

    // Divergence check within the frame: non-finite values every substep (one pass over the
    // vertices); over-stretched springs and energy blow-up (a pass over the springs) at
    // checksPerFrame evenly spread substeps and the last one. A blow-up caught a few substeps
    // late is rolled back all the same: the frame restarts from its start either way.
    Stopwatch check;
    std::string reason;
    const int every =
        m_config.limits.checksPerFrame > 0
            ? std::max(1, (substeps + m_config.limits.checksPerFrame - 1) / m_config.limits.checksPerFrame)
            : 1;
    if (!allFinite(m_state)) {
      reason = "non-finite";
    } else if ((k + 1) % every == 0 || k + 1 == substeps) {
      const SpringCheck springs = checkSprings(m_system, m_state.x);
      const double energy = kineticEnergy(m_system, m_state.v) + springs.energy;
      if (!std::isfinite(energy))
        reason = "non-finite";
      else if (!(springs.maxStretch <= m_config.limits.maxStretch))
        reason = "over-stretched spring";
      else if (!(energy <= energyCeiling))
        reason = "energy blow-up";
    }
    report.checkMs += check.elapsedMs();
    if (!reason.empty()) return reason;
  }
  return {};
}

FrameReport Simulator::advanceFrame() {
  FrameReport report;
  Stopwatch frameClock;
  Stopwatch save;
  m_frameStart = m_state;
  const double startEnergy = kineticEnergy(m_system, m_state.v) + checkSprings(m_system, m_state.x).energy;
  const double energyCeiling = m_config.limits.energyGrowth * std::max(startEnergy, m_energyFloor);
  report.rollbackMs += save.elapsedMs();
  if (m_hook) m_hook->beginFrame(m_system, m_state, m_frame);

  // A bounded degrade: the configured (or current) integrator; on divergence one retry with a
  // more stable integrator at the same substeps, only while the frame has time for it; else the
  // frame is relaxed to its start at rest. Substeps are never raised, so h, and with it the fast
  // solver's factor, stays as configured.
  const double budget = m_config.recovery.frameBudgetMs;
  Integrator integrator = m_integrator;
  bool retried = false;
  for (;;) {
    Stopwatch attempt;
    std::string reason =
        tryFrame(integrator, m_substeps, energyCeiling, report, retried ? budget : 0.0, frameClock);
    if (reason.empty()) break;
    report.recoveryMs += attempt.elapsedMs();

    Stopwatch rollback;
    m_state = m_frameStart;
    m_workspace.previousDeltaV.clear();
    if (m_hook) m_hook->restartFrame();
    report.rollbackMs += rollback.elapsedMs();
    DivergenceEvent event{m_frame, reason, integrator, m_substeps, integrator, m_substeps, true, {}};
    const Integrator next = moreStable(integrator);
    const bool timeLeft = budget <= 0.0 || frameClock.elapsedMs() < 0.5 * budget;
    if (!retried && m_config.recovery.switchIntegrator && next != integrator && timeLeft) {
      event.nextIntegrator = next;
      event.action = "retry with " + std::string(integratorName(next));
      report.events.push_back(event);
      integrator = next;
      retried = true;
      continue;
    }
    // Relax: keep the last good positions, at rest, and say so.
    for (Vec3d& v : m_state.v)
      v = {};
    event.recovered = false;
    event.action = "relaxed to rest";
    report.events.push_back(event);
    report.degrade = "relaxed";
    break;
  }
  if (retried && report.degrade.empty())
    report.degrade = "fallback " + std::string(integratorName(integrator));
  report.integrator = integrator;
  report.substeps = m_substeps;
  m_integrator = integrator;
  relaxRecovery(report.events.empty());
  ++m_frame;
  return report;
}

FrameWorkBound Simulator::frameWorkBound() const {
  const int perStep = std::max({m_config.solver.maxIterations, m_config.solver.localGlobalIterations, 1});
  return {.steps = 2 * m_substeps, .solverIterations = 2 * m_substeps * perStep};
}

double Simulator::hookElasticChange() {
  const SpringNetwork& s = m_system.springs;
  m_springMarks.resize(s.size(), 0);
  m_markedSprings.clear();
  double change = 0.0;
  for (std::size_t v = 0; v < m_state.x.size(); ++v) {
    if (m_state.x[v] == m_afterStepX[v]) continue;
    for (std::uint32_t q = s.vertexSpringOffsets[v]; q < s.vertexSpringOffsets[v + 1]; ++q) {
      const std::uint32_t e = s.vertexSprings[q];
      if (m_springMarks[e]) continue;
      m_springMarks[e] = 1;
      m_markedSprings.push_back(e);
      const double now = length(m_state.x[s.j[e]] - m_state.x[s.i[e]]) - s.restLength[e];
      const double before = length(m_afterStepX[s.j[e]] - m_afterStepX[s.i[e]]) - s.restLength[e];
      change += 0.5 * s.stiffness[e] * (now * now - before * before);
    }
  }
  for (std::uint32_t e : m_markedSprings)
    m_springMarks[e] = 0;
  return change;
}

void Simulator::relaxRecovery(bool quietFrame) {
  m_quietFrames = quietFrame ? m_quietFrames + 1 : 0;
  const int after = m_config.recovery.relaxAfterFrames;
  if (after <= 0) return;
  if (m_restoredAt >= 0 && m_frame - m_restoredAt < after) {
    // The restored integrator diverged again soon: unstable for this system, not a transient.
    if (!quietFrame) {
      m_backoff = std::min(2 * m_backoff, 64);
      m_restoredAt = -1;
    }
  } else if (m_restoredAt >= 0) {
    m_backoff = 1;  // it held for `after` frames: the divergence was a transient after all
    m_restoredAt = -1;
  }
  if (m_integrator == m_config.integrator || m_quietFrames < after * m_backoff) return;
  // A fallback integrator is replaced back by the configured one after quiet frames; should the
  // transient return, the next divergence costs one bounded retry again.
  m_integrator = m_config.integrator;
  m_quietFrames = 0;
  m_restoredAt = m_frame;
}

}  // namespace tissue::sim
