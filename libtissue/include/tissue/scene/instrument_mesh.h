#pragma once
/// \file
/// The instrument as something to draw: a sphere (or capsule) tip on a cylindrical shaft, as
/// plain arrays for the renderer, built once at the rest pose and moved rigidly every frame.

#include <vector>

#include "tissue/core/types.h"
#include "tissue/sim/contact.h"

namespace tissue::scene {

/// A triangle mesh of the instrument in its own frame (tip centre at the origin, mm).
struct InstrumentMesh {
  std::vector<Float3> positions;  ///< mm
  std::vector<Float3> normals;    ///< unit
  std::vector<Float4> tangents;   ///< (unit T, handedness +1)
  std::vector<Float2> uvs;        ///< longitude, latitude in [0, 1]
  std::vector<Triangle> triangles;
};

/// How to draw it (plain struct with defaults).
struct InstrumentLook {
  double shaftLengthMm = 60.0;              ///< mm, from the tip centre along the shaft direction
  double shaftRadiusFraction = 0.45;        ///< shaft radius as a fraction of the tip radius
  Float3 shaftDirection{0.0f, 0.0f, 1.0f};  ///< unit, tip towards the handle (a sphere has no axis)
  int segments = 32;                        ///< around the axis
};

/// The tip (`shape`: a sphere of its radius, or a capsule of its length along the shaft) and
/// the shaft, counter-clockwise seen from outside.
InstrumentMesh makeInstrumentMesh(const sim::ToolShape& shape, const InstrumentLook& look = {});

}  // namespace tissue::scene
