// Framing a bounding box, and the camera's matrices.
#include "camera_math.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace tissue::render {

Camera frameBoundingBox(Float3 lo, Float3 hi, float aspect, Float3 direction) {
  const glm::vec3 center = 0.5f * (toGlm(lo) + toGlm(hi));
  const float radius = std::max(0.5f * glm::length(toGlm(hi) - toGlm(lo)), 1e-3f);  // mm
  glm::vec3 dir = toGlm(direction);
  dir = glm::length(dir) > 0.0f ? glm::normalize(dir) : glm::vec3(0.0f, 0.0f, -1.0f);
  Camera camera;
  // The sphere fits when its tangent cone fits the smaller half-angle: d = r / sin(half).
  const float halfVertical = glm::radians(camera.verticalFovDeg) * 0.5f;
  const float halfHorizontal = std::atan(std::tan(halfVertical) * std::max(aspect, 1e-3f));
  const float distance = radius / std::sin(std::min(halfVertical, halfHorizontal)) * 1.05f;
  camera.target = fromGlm(center);
  camera.eye = fromGlm(center - dir * distance);
  camera.up = std::abs(dir.y) > 0.99f ? Float3{0.0f, 0.0f, -1.0f} : Float3{0.0f, 1.0f, 0.0f};
  camera.nearMm = std::max(distance - radius * 1.5f, distance * 0.01f);
  camera.farMm = distance + radius * 1.5f;
  return camera;
}

glm::mat4 viewProjection(const Camera& camera, float aspect) {
  const glm::mat4 view = glm::lookAt(toGlm(camera.eye), toGlm(camera.target), toGlm(camera.up));
  const glm::mat4 projection =
      glm::perspective(glm::radians(camera.verticalFovDeg), aspect, camera.nearMm, camera.farMm);
  return projection * view;
}

}  // namespace tissue::render
