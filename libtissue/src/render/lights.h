#pragma once
// The scene's lights as shader uniforms (shaders/common/lights.glsl), with the light-space
// matrices of the shadow maps. Private: GLM stays out of public headers.
#include <array>
#include <span>

#include <glm/glm.hpp>

#include "tissue/core/result.h"
#include "tissue/gl/gl_api.h"
#include "tissue/render/scene.h"

namespace tissue::render {

/// One frame's lights, ready to upload.
struct LightFrame {
  int count = 0;
  std::array<glm::vec4, kMaxLights>
      vector{};  ///< xyz position mm (w = 1) or unit direction toward the light (w = 0)
  std::array<glm::vec3, kMaxLights> radiance{};      ///< linear RGB, colour * intensity
  std::array<int, kMaxLights> shadowLayer{};         ///< layer of the shadow-map array, -1 = none
  std::array<glm::mat4, kMaxLights> shadowMatrix{};  ///< world (mm) to the shadow map's clip space
  std::array<float, kMaxLights> biasMm{};            ///< mm, normal offset before the lookup
  /// One shadow-map texel's width at a point, mm = x + y * (the point's light distance, mm): a
  /// directional light's orthographic texel (x), a point light's perspective one (y). The
  /// shaders widen the bias by it, so a map stretched over a large scene does not shadow the
  /// surfaces it stores (acne).
  std::array<glm::vec2, kMaxLights> texelMm{};
};

/// Builds the frame's lights; the shadow frusta enclose the sphere (centre, radius mm) around
/// every object; each map is `shadowMapSize` texels square. Fails on more than kMaxLights lights or a zero
/// direction.
Result<LightFrame> makeLightFrame(std::span<const Light> lights, glm::vec3 centre, float radiusMm,
                                  int shadowMapSize);

/// Sets the lights.glsl uniforms of the program in use (`program`); the shadow-map array is
/// on texture unit `shadowUnit`.
void setLightUniforms(const gl::GlApi& gl, GLuint program, const LightFrame& lights, int shadowUnit);

}  // namespace tissue::render
