// The tool's centre from the mouse: picked distance along the view ray, depth, speed limit.
#include "instrument_control.h"

#include <algorithm>

#include "vec3_ops.h"

namespace tissue::viewer {

InstrumentControl::InstrumentControl(Float3 startMm, float radiusMm,
                                     const InstrumentControlSettings& settings)
    : m_settings(settings), m_radiusMm(radiusMm), m_position(startMm), m_depthMm(settings.pressDepthMm) {}

void InstrumentControl::press(const Ray& ray, float hitDistanceMm) {
  m_ray = ray;
  m_hitDistanceMm = hitDistanceMm;
  m_held = m_aimed = true;
  m_parked = false;
}

void InstrumentControl::aim(const Ray& ray) {
  if (m_held) m_ray = ray;
}

void InstrumentControl::release(bool grasping) {
  m_held = false;
  m_parked = !grasping;  // grasping: stay, holding the tissue
}

void InstrumentControl::moveDepth(double steps) {
  m_depthMm = std::clamp(m_depthMm + float(steps) * m_settings.depthStepMm, m_settings.minDepthMm,
                         m_settings.maxDepthMm);
}

Float3 InstrumentControl::targetMm() const {
  if (!m_aimed) return m_position;
  // The front of the tool (the centre plus the radius along the ray) sits `depth` past the
  // picked point; parked, it sits retractMm in front of it.
  const float front = m_parked ? m_hitDistanceMm - m_settings.retractMm : m_hitDistanceMm + m_depthMm;
  return m_ray.origin + m_ray.direction * (front - m_radiusMm);
}

Float3 InstrumentControl::step() {
  const Float3 to = targetMm() - m_position;
  const float d = length(to);
  m_position = d <= m_settings.maxStepMm ? targetMm() : m_position + to * (m_settings.maxStepMm / d);
  return m_position;
}

}  // namespace tissue::viewer
