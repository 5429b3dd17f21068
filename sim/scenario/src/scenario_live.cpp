// Live input to a running scenario: the tool pose and grasp state from a viewer, a replayed
// session or a host, in place of the scenario's scripted path and actions.
#include <cmath>

#include "tissue/scenario/scenario_run.h"

namespace tissue::scenario {

Result<void> ScenarioRun::setInstrumentTarget(const sim::ToolPose& pose) {
  if (!m_instrument)
    return Error{m_scenario.file.string() + ": the scenario has no instrument; add an \"instrument\" block"};
  if (!sim::isFinite(pose.position) || !sim::isFinite(pose.axis))
    return Error{"instrument pose: not finite (" + std::to_string(pose.position.x) + ", " +
                 std::to_string(pose.position.y) + ", " + std::to_string(pose.position.z) +
                 " mm); give finite coordinates"};
  m_live = true;
  m_instrument->setTarget(pose);
  return {};
}

Result<void> ScenarioRun::setInstrumentRadius(double radiusMm) {
  if (!m_instrument)
    return Error{m_scenario.file.string() + ": the scenario has no instrument; add an \"instrument\" block"};
  m_live = true;
  return m_instrument->setRadius(radiusMm);
}

Result<void> ScenarioRun::setGrasp(bool grasp) {
  if (!m_instrument)
    return Error{m_scenario.file.string() + ": the scenario has no instrument; add an \"instrument\" block"};
  m_live = true;
  if (grasp == m_instrument->grasping()) return {};
  if (grasp) {
    auto taken = m_instrument->grasp(m_simulator);
    if (!taken) return taken.error();
    return {};
  }
  return m_instrument->release(m_simulator);
}

}  // namespace tissue::scenario
