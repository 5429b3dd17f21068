#pragma once
/// \file
/// An orbit camera: it circles a target point at some distance, yaw about the world's y axis
/// and pitch above the horizon, and produces the renderer's look-at Camera each frame.

#include "tissue/core/types.h"
#include "tissue/render/scene.h"

namespace tissue::viewer {

/// How the mouse maps to the camera.
struct OrbitSettings {
  float degreesPerPixel = 0.3f;  ///< degrees of yaw or pitch per pixel dragged
  float zoomPerStep = 0.9f;      ///< distance factor per scroll step (unitless, < 1 zooms in)
  float maxPitchDeg = 89.0f;     ///< degrees; keeps the up vector away from the view direction
};

/// A camera orbiting the centre of a bounding box; its home view frames the whole box.
class OrbitCamera {
 public:
  /// Frames the box [lo, hi] (mm) for an image of `aspect` = width / height, looking along
  /// `direction` (unitless), as render::frameBoundingBox does; that view is the home view.
  OrbitCamera(Float3 lo, Float3 hi, float aspect, Float3 direction = {-0.3f, -0.35f, -1.0f},
              const OrbitSettings& settings = {});

  /// Turns the camera by a mouse drag of (`dxPixels`, `dyPixels`): right turns the tissue
  /// right, down tilts the camera up over it.
  void orbit(double dxPixels, double dyPixels);
  /// Moves towards the target by `steps` scroll steps (negative moves away).
  void zoom(double steps);
  /// Back to the home view.
  void reset();

  /// The look-at camera now, near and far planes around the box's bounding sphere.
  render::Camera camera() const;
  float distanceMm() const { return m_distanceMm; }

 private:
  OrbitSettings m_settings;
  Float3 m_target;   ///< mm, the box centre
  float m_radiusMm;  ///< mm, the box's bounding sphere
  float m_homeDistanceMm, m_homeYawDeg, m_homePitchDeg;
  float m_distanceMm, m_yawDeg, m_pitchDeg;
};

}  // namespace tissue::viewer
