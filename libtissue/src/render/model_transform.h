#pragma once
// Per-object model matrices (SceneObject::model): validation, the normal matrix and the world
// bounds, computed on the CPU once per object and frame (a 3x3 inverse is nothing next to a
// draw). Private: GLM stays out of public headers.
#include <array>

#include <glm/glm.hpp>

#include "tissue/core/result.h"
#include "tissue/core/types.h"

namespace tissue::render {

/// One object's transform, ready for the shaders (u_model, u_normalMatrix).
struct ModelTransform {
  glm::mat4 model{1.0f};         ///< object (mm) to world (mm)
  glm::mat3 normalMatrix{1.0f};  ///< (M3^-1)^T: normals and plane normals
  float scale = 1.0f;            ///< cbrt(det M3): the geometric-mean linear scale, unitless
};

/// Checks `model` (column-major) and derives the normal matrix and scale. Errors: non-finite,
/// a last row other than (0, 0, 0, 1), det(M3) <= 0 (singular or mirrored).
Result<ModelTransform> makeModelTransform(const std::array<float, 16>& model);

/// Column-major copies of GLM matrices (for structs that keep GLM out, e.g. IrradianceFrame).
std::array<float, 16> toArray(const glm::mat4& m);
std::array<float, 9> toArray(const glm::mat3& m);

/// The axis-aligned world bounds of the object-space box [lo, hi] (its eight corners through
/// `model`), into outLo, outHi (mm).
void transformBounds(const glm::mat4& model, Float3 lo, Float3 hi, glm::vec3& outLo, glm::vec3& outHi);

}  // namespace tissue::render
