#include "model_transform.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace tissue::render {

Result<ModelTransform> makeModelTransform(const std::array<float, 16>& model) {
  for (const float v : model)
    if (!std::isfinite(v)) return Error{"its model matrix has a non-finite entry"};
  // Column-major: row 3 is model[3], model[7], model[11], model[15].
  if (model[3] != 0.0f || model[7] != 0.0f || model[11] != 0.0f || model[15] != 1.0f) {
    return Error{"its model matrix must be affine (last row 0, 0, 0, 1); got " + std::to_string(model[3]) +
                 ", " + std::to_string(model[7]) + ", " + std::to_string(model[11]) + ", " +
                 std::to_string(model[15])};
  }
  ModelTransform t;
  t.model = glm::make_mat4(model.data());
  const glm::mat3 m3(t.model);
  const float det = glm::determinant(m3);
  // Relative to the columns' lengths, so that a small but regular scale (e.g. m to mm) passes.
  const float size = glm::length(m3[0]) * glm::length(m3[1]) * glm::length(m3[2]);
  if (!(det > 1e-6f * size)) {
    return Error{"its model matrix's upper 3x3 has determinant " + std::to_string(det) +
                 "; it must be positive (mirrored and singular transforms are not supported)"};
  }
  t.normalMatrix = glm::transpose(glm::inverse(m3));
  t.scale = std::cbrt(det);
  return t;
}

std::array<float, 16> toArray(const glm::mat4& m) {
  std::array<float, 16> out{};
  const float* p = glm::value_ptr(m);
  std::copy(p, p + 16, out.begin());
  return out;
}

std::array<float, 9> toArray(const glm::mat3& m) {
  std::array<float, 9> out{};
  const float* p = glm::value_ptr(m);
  std::copy(p, p + 9, out.begin());
  return out;
}

void transformBounds(const glm::mat4& model, Float3 lo, Float3 hi, glm::vec3& outLo, glm::vec3& outHi) {
  for (int c = 0; c < 8; ++c) {
    const glm::vec3 corner{(c & 1) ? hi.x : lo.x, (c & 2) ? hi.y : lo.y, (c & 4) ? hi.z : lo.z};
    const glm::vec3 p = glm::vec3(model * glm::vec4(corner, 1.0f));
    outLo = c == 0 ? p : glm::min(outLo, p);
    outHi = c == 0 ? p : glm::max(outHi, p);
  }
}

}  // namespace tissue::render
