#include "shadow_maps.h"

#include <glm/gtc/type_ptr.hpp>

#include <string>

#include "tissue/gl/program.h"

namespace tissue::render {

Result<ShadowMaps> ShadowMaps::create(const gl::GlApi& gl, const gl::ShaderLibrary& library, int size) {
  if (size < 16 || size > 8192) {
    return Error{"renderer: shadowMapSize " + std::to_string(size) + " is outside 16..8192 pixels"};
  }
  ShadowMaps s;
  s.m_size = size;
  auto program = gl::buildProgram(gl, library, {"shadow/distance.vert", "shadow/distance.frag", {}});
  if (!program) return program.error();
  s.m_program = std::move(*program);
  // Step 1: the distance array; linear filtering is off (PCF compares, then averages).
  s.m_texture = gl::Texture::create(gl);
  gl.BindTexture(GL_TEXTURE_2D_ARRAY, s.m_texture.id());
  gl.TexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_R32F, size, size, kMaxLights, 0, GL_RED, GL_FLOAT, nullptr);
  gl.TexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  gl.TexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  gl.TexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  gl.TexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  gl.BindTexture(GL_TEXTURE_2D_ARRAY, 0);
  // Step 2: a depth buffer shared by the layers, and the framebuffer.
  s.m_depth = gl::Renderbuffer::create(gl);
  gl.BindRenderbuffer(GL_RENDERBUFFER, s.m_depth.id());
  gl.RenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, size, size);
  s.m_framebuffer = gl::Framebuffer::create(gl);
  gl.BindFramebuffer(GL_FRAMEBUFFER, s.m_framebuffer.id());
  gl.FramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, s.m_texture.id(), 0, 0);
  gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, s.m_depth.id());
  if (gl.CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    return Error{"renderer: the shadow-map framebuffer (R32F array layer) is incomplete"};
  }
  if (auto r = gl::checkGlError(gl, "renderer: shadow maps"); !r) return r.error();
  return s;
}

Result<void> ShadowMaps::draw(const gl::GlApi& gl, const LightFrame& lights, int index,
                              std::span<const ShadowCaster> casters) {
  const int layer = lights.shadowLayer[static_cast<std::size_t>(index)];
  gl.BindFramebuffer(GL_FRAMEBUFFER, m_framebuffer.id());
  gl.FramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, m_texture.id(), 0, layer);
  gl.Viewport(0, 0, m_size, m_size);
  gl.Disable(GL_BLEND);
  gl.Disable(GL_SCISSOR_TEST);
  gl.Enable(GL_DEPTH_TEST);
  gl.DepthFunc(GL_LESS);
  gl.DepthMask(GL_TRUE);
  gl.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  gl.Disable(GL_CULL_FACE);                // open meshes (a patch) must still cast shadows from both sides
  gl.ClearColor(1e30f, 0.0f, 0.0f, 0.0f);  // "no occluder": farther than anything
  gl.ClearDepth(1.0);
  gl.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  gl.UseProgram(m_program.id());
  const GLuint p = m_program.id();
  gl.UniformMatrix4fv(gl.GetUniformLocation(p, "u_shadowMatrix"), 1, GL_FALSE,
                      glm::value_ptr(lights.shadowMatrix[static_cast<std::size_t>(index)]));
  gl.Uniform4fv(gl.GetUniformLocation(p, "u_light"), 1,
                glm::value_ptr(lights.vector[static_cast<std::size_t>(index)]));
  const GLint model = gl.GetUniformLocation(p, "u_model");
  for (const ShadowCaster& c : casters) {
    gl.UniformMatrix4fv(model, 1, GL_FALSE, glm::value_ptr(c.model));
    gl.BindVertexArray(c.mesh->vertexArray());
    gl.DrawElements(GL_TRIANGLES, c.mesh->indexCount(), GL_UNSIGNED_INT, nullptr);
  }
  return gl::checkGlError(gl, "renderer: shadow pass");
}

}  // namespace tissue::render
