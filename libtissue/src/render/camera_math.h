#pragma once
// GLM helpers of the renderer (private: GLM stays out of public headers).
#include <glm/glm.hpp>

#include "tissue/render/scene.h"

namespace tissue::render {

inline glm::vec3 toGlm(Float3 v) {
  return {v.x, v.y, v.z};
}
inline Float3 fromGlm(glm::vec3 v) {
  return {v.x, v.y, v.z};
}

/// Projection * view of `camera` for an image of `aspect` = width / height (world mm to clip).
glm::mat4 viewProjection(const Camera& camera, float aspect);

}  // namespace tissue::render
