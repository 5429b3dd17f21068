#include "lights.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <string>

#include "camera_math.h"

namespace tissue::render {
namespace {

glm::vec3 upFor(glm::vec3 forward) {
  return std::abs(forward.y) > 0.99f ? glm::vec3(0.0f, 0.0f, 1.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
}

// A point light sees the bounding sphere through the narrowest cone that holds it; a light
// inside the sphere falls back to a wide 150-degree frustum.
float pointShadowFov(glm::vec3 light, glm::vec3 centre, float radius) {
  const float distance = glm::length(centre - light);
  return distance > radius * 1.01f ? 2.0f * std::asin(radius / distance) * 1.05f : glm::radians(150.0f);
}

glm::mat4 pointShadowMatrix(glm::vec3 light, glm::vec3 centre, float radius) {
  const glm::vec3 toCentre = centre - light;
  const float distance = glm::length(toCentre);
  const glm::vec3 forward = distance > 1e-3f ? toCentre / distance : glm::vec3(0.0f, 0.0f, -1.0f);
  const glm::mat4 view = glm::lookAt(light, light + forward, upFor(forward));
  const float fov = pointShadowFov(light, centre, radius);
  float nearMm = std::max(radius * 1e-3f, 0.1f);
  if (distance > radius * 1.01f) nearMm = std::max(distance - radius, nearMm);
  return glm::perspective(fov, 1.0f, nearMm, distance + radius) * view;
}

// A directional light sees the sphere through an orthographic box along its direction.
glm::mat4 directionalShadowMatrix(glm::vec3 towardLight, glm::vec3 centre, float radius) {
  const glm::vec3 eye = centre + towardLight * (2.0f * radius);
  const glm::mat4 view = glm::lookAt(eye, centre, upFor(-towardLight));
  return glm::ortho(-radius, radius, -radius, radius, radius * 0.5f, radius * 3.5f) * view;
}

}  // namespace

Result<LightFrame> makeLightFrame(std::span<const Light> lights, glm::vec3 centre, float radiusMm,
                                  int shadowMapSize) {
  const float texels = float(std::max(shadowMapSize, 1));
  if (lights.size() > static_cast<std::size_t>(kMaxLights)) {
    return Error{"renderer: the scene has " + std::to_string(lights.size()) + " lights; at most " +
                 std::to_string(kMaxLights) + " are supported"};
  }
  LightFrame f;
  f.count = static_cast<int>(lights.size());
  int layer = 0;
  for (int i = 0; i < f.count; ++i) {
    const Light& l = lights[static_cast<std::size_t>(i)];
    if (l.type == LightType::Point) {
      f.vector[i] = glm::vec4(toGlm(l.positionMm), 1.0f);
      f.shadowMatrix[i] = pointShadowMatrix(toGlm(l.positionMm), centre, radiusMm);
      f.texelMm[i] = {0.0f,
                      2.0f * std::tan(0.5f * pointShadowFov(toGlm(l.positionMm), centre, radiusMm)) / texels};
    } else {
      const glm::vec3 d = toGlm(l.direction);
      if (glm::length(d) <= 0.0f) {
        return Error{"renderer: light " + std::to_string(i) + " is directional with a zero direction"};
      }
      const glm::vec3 towardLight = -glm::normalize(d);
      f.vector[i] = glm::vec4(towardLight, 0.0f);
      f.shadowMatrix[i] = directionalShadowMatrix(towardLight, centre, radiusMm);
      f.texelMm[i] = {2.0f * radiusMm / texels, 0.0f};
    }
    f.radiance[i] = toGlm(l.color) * l.intensity;
    f.shadowLayer[i] = l.castsShadows ? layer++ : -1;
    f.biasMm[i] = l.shadowBiasMm;
  }
  return f;
}

void setLightUniforms(const gl::GlApi& gl, GLuint program, const LightFrame& f, int shadowUnit) {
  auto at = [&](const char* name) { return gl.GetUniformLocation(program, name); };
  gl.Uniform1i(at("u_lightCount"), f.count);
  gl.Uniform4fv(at("u_lightVector"), kMaxLights, glm::value_ptr(f.vector[0]));
  gl.Uniform3fv(at("u_lightRadiance"), kMaxLights, glm::value_ptr(f.radiance[0]));
  gl.Uniform1iv(at("u_lightShadowLayer"), kMaxLights, f.shadowLayer.data());
  gl.UniformMatrix4fv(at("u_lightShadowMatrix"), kMaxLights, GL_FALSE, glm::value_ptr(f.shadowMatrix[0]));
  gl.Uniform1fv(at("u_lightBiasMm"), kMaxLights, f.biasMm.data());
  gl.Uniform2fv(at("u_lightTexelMm"), kMaxLights, glm::value_ptr(f.texelMm[0]));
  gl.Uniform1i(at("u_shadowMaps"), shadowUnit);
}

}  // namespace tissue::render
