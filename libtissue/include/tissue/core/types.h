#pragma once
/// \file
/// Plain vector types that connect the modules (mesh, simulator, renderer).
/// They are tightly packed so that a std::vector of them can be uploaded to GL or mapped to
/// Eigen without copying; maths lives in each module's own library (Eigen, GLM).

#include <array>
#include <cstdint>

namespace tissue {

/// Two floats (texture coordinates, unitless).
struct Float2 {
  float x = 0.0f;
  float y = 0.0f;
  friend bool operator==(const Float2&, const Float2&) = default;
};

/// Three floats: a position in mm, a unit direction or an RGB triple, as the field says.
struct Float3 {
  float x = 0.0f;
  float y = 0.0f;
  float z = 0.0f;
  friend bool operator==(const Float3&, const Float3&) = default;
};

/// Four floats: a tangent with handedness in w, or a plane (normal, offset in mm).
struct Float4 {
  float x = 0.0f;
  float y = 0.0f;
  float z = 0.0f;
  float w = 0.0f;
  friend bool operator==(const Float4&, const Float4&) = default;
};

/// A triangle as three vertex indices, counter-clockwise seen from outside.
using Triangle = std::array<std::uint32_t, 3>;

/// A tetrahedron as four vertex indices, positively oriented: (v1-v0, v2-v0, v3-v0) is a
/// right-handed frame, so its signed volume is positive.
using Tet = std::array<std::uint32_t, 4>;

static_assert(sizeof(Float2) == 8 && sizeof(Float3) == 12 && sizeof(Float4) == 16,
              "the plain vector types must be tightly packed for upload");

}  // namespace tissue
