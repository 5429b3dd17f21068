#pragma once
/// \file
/// A hook that runs inside every substep of Simulator::advanceFrame, after the integrator's
/// step: kinematic contact and grasping (instrument.h) move vertices there, so that they act at
/// the substep rate and are rolled back with the frame when it diverges.

#include <span>

#include "tissue/sim/system.h"
#include "tissue/sim/vec3.h"

namespace tissue::sim {

/// Where a substep sits in time.
struct SubstepInfo {
  long frame = 0;                  ///< frame index (0 = first advanceFrame)
  double frameStart = 0.0;         ///< s, simulated time at the start of the frame
  double frameTime = 0.0;          ///< s, the frame's length
  double t0 = 0.0;                 ///< s, start of this substep
  double h = 0.0;                  ///< s, substep length
  int index = 0;                   ///< substep within the frame
  int count = 0;                   ///< substeps in the frame
  std::span<const Vec3d> xBefore;  ///< mm, positions before the integrator's step (swept contact)
};

/// Per-substep callbacks (an open set: an instrument, a haptic coupling, a test probe).
/// The Simulator calls beginFrame once per frame, then for every try of the frame (a retry
/// after a divergence starts with restartFrame) afterSubstep after each integrator step.
class SubstepHook {
 public:
  virtual ~SubstepHook() = default;
  /// The frame starts from `state`; save what a retry must restore.
  virtual void beginFrame(const MassSpringSystem& system, const State& state, long frame) = 0;
  /// The frame was rolled back to its start and is tried again: restore what beginFrame saved.
  virtual void restartFrame() = 0;
  /// After the integrator's step: may change positions and velocities (mm, mm/s) of the
  /// vertices the system lets move (invMass > 0) and set those of kinematic ones (invMass 0).
  virtual void afterSubstep(const MassSpringSystem& system, State& state, const SubstepInfo& info) = 0;
};

}  // namespace tissue::sim
