#pragma once
// Shadow maps: one layer of an R32F texture array per shadow-casting light, holding the
// distance (mm) from the light to the nearest surface (a point light: |P - light|; a
// directional light: P along the light's direction). Distances rather than depths let the
// separable method read thicknesses in mm for its transmittance (Jimenez et al. 2010).
// Lookups filter with 3x3 percentage-closer filtering (shaders/common/lights.glsl).
#include <span>

#include "lights.h"
#include "mesh_buffers.h"
#include "tissue/core/result.h"
#include "tissue/gl/objects.h"
#include "tissue/gl/shader_library.h"

namespace tissue::render {

/// One object drawn into the shadow maps: its mesh and model matrix (object mm to world mm).
struct ShadowCaster {
  const MeshBuffers* mesh = nullptr;
  glm::mat4 model{1.0f};
};

class ShadowMaps {
 public:
  /// Builds the shadow program; `size` pixels per map.
  static Result<ShadowMaps> create(const gl::GlApi& gl, const gl::ShaderLibrary& library, int size);
  /// Draws light `index`'s layer from `casters` (its matrix and layer from `lights`).
  Result<void> draw(const gl::GlApi& gl, const LightFrame& lights, int index,
                    std::span<const ShadowCaster> casters);
  /// The texture array (GL_TEXTURE_2D_ARRAY, R32F, kMaxLights layers).
  GLuint texture() const { return m_texture.id(); }

 private:
  int m_size = 0;
  gl::Program m_program;
  gl::Texture m_texture;
  gl::Renderbuffer m_depth;
  gl::Framebuffer m_framebuffer;
};

}  // namespace tissue::render
