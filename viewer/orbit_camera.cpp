// The orbit camera: spherical coordinates about the target, y up.
#include "orbit_camera.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "vec3_ops.h"

namespace tissue::viewer {
namespace {

constexpr float kDegToRad = std::numbers::pi_v<float> / 180.0f;

}  // namespace

OrbitCamera::OrbitCamera(Float3 lo, Float3 hi, float aspect, Float3 direction, const OrbitSettings& settings)
    : m_settings(settings) {
  const render::Camera home = render::frameBoundingBox(lo, hi, aspect, direction);
  m_target = home.target;
  m_radiusMm = std::max(0.5f * length(hi - lo), 1e-3f);
  // The home eye in spherical coordinates about the target (y up).
  const Float3 offset = home.eye - home.target;
  m_homeDistanceMm = length(offset);
  m_homePitchDeg = std::asin(std::clamp(offset.y / m_homeDistanceMm, -1.0f, 1.0f)) / kDegToRad;
  m_homePitchDeg = std::clamp(m_homePitchDeg, -m_settings.maxPitchDeg, m_settings.maxPitchDeg);
  m_homeYawDeg = std::atan2(offset.x, offset.z) / kDegToRad;
  reset();
}

void OrbitCamera::orbit(double dxPixels, double dyPixels) {
  m_yawDeg -= float(dxPixels) * m_settings.degreesPerPixel;
  m_pitchDeg = std::clamp(m_pitchDeg + float(dyPixels) * m_settings.degreesPerPixel, -m_settings.maxPitchDeg,
                          m_settings.maxPitchDeg);
}

void OrbitCamera::zoom(double steps) {
  const float factor = std::pow(m_settings.zoomPerStep, float(steps));
  // Never inside the tissue's bounding sphere's core, never lost in the distance.
  m_distanceMm = std::clamp(m_distanceMm * factor, 0.2f * m_radiusMm, 10.0f * m_homeDistanceMm);
}

void OrbitCamera::reset() {
  m_distanceMm = m_homeDistanceMm;
  m_yawDeg = m_homeYawDeg;
  m_pitchDeg = m_homePitchDeg;
}

render::Camera OrbitCamera::camera() const {
  const float yaw = m_yawDeg * kDegToRad;
  const float pitch = m_pitchDeg * kDegToRad;
  const Float3 offset{std::cos(pitch) * std::sin(yaw), std::sin(pitch), std::cos(pitch) * std::cos(yaw)};
  render::Camera camera;
  camera.target = m_target;
  camera.eye = m_target + offset * m_distanceMm;
  camera.up = {0.0f, 1.0f, 0.0f};
  camera.nearMm = std::max(m_distanceMm - 1.5f * m_radiusMm, 0.01f * m_distanceMm);
  camera.farMm = m_distanceMm + 1.5f * m_radiusMm;
  return camera;
}

}  // namespace tissue::viewer
