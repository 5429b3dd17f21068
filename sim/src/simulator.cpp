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

}  // namespace

Result<Simulator> Simulator::create(MassSpringSystem system, State initial, const SimulatorConfig& config) {
  if (initial.x.size() != system.vertexCount() || initial.v.size() != system.vertexCount())
    return Error{"simulator: the state has " + std::to_string(initial.x.size()) + " positions and " +
                 std::to_string(initial.v.size()) + " velocities for " +
                 std::to_string(system.vertexCount()) + " vertices; give one of each per vertex"};
  if (!allFinite(initial)) return Error{"simulator: the initial state holds NaN or Inf"};
  if (!(config.frameTime > 0.0) || !std::isfinite(config.frameTime))
    return Error{"simulator: frameTime must be a positive number of seconds"};
  if (config.substeps < 1 || config.recovery.maxSubsteps < config.substeps)
    return Error{"simulator: substeps must be >= 1 and <= recovery.maxSubsteps"};
  if (!(config.limits.maxStretch > 1.0) || !(config.limits.energyGrowth > 1.0) ||
      !(config.limits.floorStrain > 0.0))
    return Error{"simulator: limits.maxStretch and limits.energyGrowth must be > 1, limits.floorStrain > 0"};
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
  return {};
}

std::string Simulator::tryFrame(Integrator integrator, int substeps, double energyCeiling,
                                FrameReport& report) {
  const double h = m_config.frameTime / substeps;
  for (int k = 0; k < substeps; ++k) {
    if (m_hook) m_substepStartX = m_state.x;  // for the hook's swept contact
    Stopwatch integrate;
    report.cgIterations += step(integrator, m_system, m_state, h, m_workspace, m_config.solver).cgIterations;
    report.integrateMs += integrate.elapsedMs();
    if (m_hook) {
      // Energy a kinematic hook puts in (a tool pushing or pulling) is not a divergence: the
      // blow-up ceiling rises by it.
      Stopwatch hook;
      const double before = kineticEnergy(m_system, m_state.v) + elasticEnergy(m_system, m_state.x);
      const double frameStart = static_cast<double>(m_frame) * m_config.frameTime;
      m_hook->afterSubstep(
          m_system, m_state,
          {m_frame, frameStart, m_config.frameTime, frameStart + k * h, h, k, substeps, m_substepStartX});
      const double after = kineticEnergy(m_system, m_state.v) + elasticEnergy(m_system, m_state.x);
      if (after > before) energyCeiling += m_config.limits.energyGrowth * (after - before);
      report.hookMs += hook.elapsedMs();
    }

    // Divergence check within the step: non-finite, over-stretched, energy blow-up.
    Stopwatch check;
    std::string reason;
    if (!allFinite(m_state))
      reason = "non-finite";
    else if (!(maxStretch(m_system, m_state.x) <= m_config.limits.maxStretch))
      reason = "over-stretched spring";
    else if (!(kineticEnergy(m_system, m_state.v) + elasticEnergy(m_system, m_state.x) <= energyCeiling))
      reason = "energy blow-up";
    report.checkMs += check.elapsedMs();
    if (!reason.empty()) return reason;
  }
  return {};
}

FrameReport Simulator::advanceFrame() {
  FrameReport report;
  Stopwatch save;
  m_frameStart = m_state;
  const double startEnergy = kineticEnergy(m_system, m_state.v) + elasticEnergy(m_system, m_state.x);
  const double energyCeiling = m_config.limits.energyGrowth * std::max(startEnergy, m_energyFloor);
  report.rollbackMs += save.elapsedMs();
  if (m_hook) m_hook->beginFrame(m_system, m_state, m_frame);

  Integrator integrator = m_integrator;
  int substeps = m_substeps;
  for (;;) {
    std::string reason = tryFrame(integrator, substeps, energyCeiling, report);
    if (reason.empty()) break;

    // Roll back to the frame start; retry with twice the substeps, then a more stable integrator.
    Stopwatch rollback;
    m_state = m_frameStart;
    m_workspace.previousDeltaV.clear();
    if (m_hook) m_hook->restartFrame();
    report.rollbackMs += rollback.elapsedMs();
    DivergenceEvent event{m_frame, reason, integrator, substeps, integrator, substeps, true};
    if (substeps * 2 <= m_config.recovery.maxSubsteps) {
      event.nextSubsteps = substeps * 2;
    } else if (m_config.recovery.switchIntegrator && moreStable(integrator) != integrator) {
      event.nextIntegrator = moreStable(integrator);
      event.nextSubsteps = m_config.substeps;
    } else {
      // Nothing left to try: keep the last good state, at rest, and say so.
      for (Vec3d& v : m_state.v)
        v = {};
      if (m_hook) m_hook->restartFrame();  // the hook, too, stays at the frame start
      event.recovered = false;
      report.events.push_back(event);
      break;
    }
    report.events.push_back(event);
    integrator = event.nextIntegrator;
    substeps = event.nextSubsteps;
  }
  report.integrator = integrator;
  report.substeps = substeps;
  m_integrator = integrator;
  m_substeps = substeps;
  relaxRecovery(report.events.empty());
  ++m_frame;
  return report;
}

void Simulator::relaxRecovery(bool quietFrame) {
  m_quietFrames = quietFrame ? m_quietFrames + 1 : 0;
  const int after = m_config.recovery.relaxAfterFrames;
  if (after <= 0 || m_quietFrames < after) return;
  // Only the substeps relax: an integrator is replaced only after failing at maxSubsteps, so the
  // configured one is not tried again.
  const int base = m_integrator == m_config.integrator ? m_config.substeps : 1;
  if (m_substeps > base) m_substeps = std::max(base, m_substeps / 2);
  m_quietFrames = 0;
}

}  // namespace tissue::sim
