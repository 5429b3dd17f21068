#pragma once
/// \file
/// The mouse and keys as the simulator's instrument: the right button puts the tool on the
/// surface point under the cursor (ray_pick) and pushes it in along the view ray; scroll (while
/// the button is held, or with Shift) and W/S or PageUp/PageDown move it in depth; on release it
/// backs off along its ray, unless it grasps, then it stays and holds the tissue. The result is
/// the tool centre handed to scene::OrganLoop each frame (InstrumentInput::pose). No GL, no
/// window: tests/viewer checks the geometry.

#include "ray_pick.h"
#include "tissue/core/types.h"

namespace tissue::viewer {

/// How the mouse drives the tool.
struct InstrumentControlSettings {
  float pressDepthMm = 4.0f;  ///< mm the tool's front passes the picked point at a press
  float depthStepMm = 1.0f;   ///< mm per scroll step or key press
  float minDepthMm = -40.0f;  ///< mm (negative: in front of the picked point, e.g. lifting)
  float maxDepthMm = 20.0f;   ///< mm
  float retractMm = 15.0f;    ///< mm the tool's front backs off the picked point on release
  float maxStepMm = 4.0f;     ///< mm: the longest move per frame (a jump would sweep through tissue)
};

/// The tool's centre over the frames.
class InstrumentControl {
 public:
  /// A tool of radius `radiusMm` (mm; a sphere, or a capsule's cap) parked at `startMm` (mm).
  InstrumentControl(Float3 startMm, float radiusMm, const InstrumentControlSettings& settings = {});

  /// The right button went down: `ray` (from the eye through the cursor) meets the surface
  /// `hitDistanceMm` (mm) along it. The tool's front will touch that point, then push
  /// pressDepthMm past it (or the depth of the last poke).
  void press(const Ray& ray, float hitDistanceMm);
  /// While held: the ray through the cursor now; the tool follows it at the same distance.
  void aim(const Ray& ray);
  /// The right button went up: the tool backs off retractMm along its ray, unless `grasping`
  /// (then it stays where it is, holding the tissue).
  void release(bool grasping);
  /// Moves the tool `steps` depth steps along its ray (positive: deeper into the tissue).
  void moveDepth(double steps);

  /// Where the tool is going (mm): on its ray at the picked distance + depth - radius.
  Float3 targetMm() const;
  /// Advances one frame: the tool moves towards the target by at most maxStepMm; returns its
  /// new centre (mm).
  Float3 step();

  Float3 positionMm() const { return m_position; }
  bool held() const { return m_held; }
  /// mm past the picked point of the tool's front (negative: in front of it).
  float depthMm() const { return m_depthMm; }
  float radiusMm() const { return m_radiusMm; }

 private:
  InstrumentControlSettings m_settings;
  float m_radiusMm;
  Float3 m_position;
  Ray m_ray{};
  float m_hitDistanceMm = 0.0f;
  float m_depthMm;
  bool m_held = false;
  bool m_aimed = false;  ///< a ray was picked at least once (else the tool stays parked)
  bool m_parked = true;  ///< released without a grasp: the target is the backed-off point
};

}  // namespace tissue::viewer
