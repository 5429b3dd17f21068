// The reusable irradiance-map pass (texture-space diffusion; Jimenez et al. §3-5).
#include "irradiance_map.h"

#include <string>

#include "tissue/gl/program.h"

namespace tissue::render {

Result<gl::Texture> createFloatTexture(const gl::GlApi& gl, int size, GLenum internal) {
  gl::Texture t = gl::Texture::create(gl);
  gl.BindTexture(GL_TEXTURE_2D, t.id());
  gl.TexImage2D(GL_TEXTURE_2D, 0, GLint(internal), size, size, 0, GL_RGBA, GL_FLOAT, nullptr);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  if (auto r = gl::checkGlError(gl, "texture space: float texture"); !r) return r.error();
  return t;
}

Result<IrradianceMap> IrradianceMap::create(const gl::GlApi& gl, const gl::ShaderLibrary& library,
                                            int maxSize) {
  if (maxSize < 16) return Error{"texture space: the irradiance map needs at least 16 texels"};
  IrradianceMap map;
  map.m_gl = &gl;
  map.m_maxSize = map.m_size = maxSize;
  auto program =
      gl::buildProgram(gl, library, {"texture_space/irradiance.vert", "texture_space/irradiance.frag", {}});
  if (!program) return program.error();
  map.m_program = std::move(*program);
  const GLuint id = map.m_program.id();
  map.m_view = gl.GetUniformLocation(id, "u_view");
  map.m_clipPlanes = gl.GetUniformLocation(id, "u_clipPlanes");
  map.m_clip = gl.GetUniformLocation(id, "u_clip");
  map.m_cull = gl.GetUniformLocation(id, "u_cull");
  map.m_cullCosine = gl.GetUniformLocation(id, "u_cullCosine");
  map.m_mapSize = gl.GetUniformLocation(id, "u_mapSize");
  map.m_offset = gl.GetUniformLocation(id, "u_offset");
  map.m_lightPosition = gl.GetUniformLocation(id, "u_lightPosition");
  map.m_lightRadiance = gl.GetUniformLocation(id, "u_lightRadiance");
  map.m_ambient = gl.GetUniformLocation(id, "u_ambient");
  // Targets: allocated once at T_max (§4: "we only allocate memory once").
  auto irradiance = createFloatTexture(gl, maxSize, GL_RGBA16F);
  auto stretch = createFloatTexture(gl, maxSize, GL_RGBA16F);
  auto position = createFloatTexture(gl, maxSize, GL_RGBA32F);
  if (!irradiance || !stretch || !position)
    return Error{"texture space: cannot allocate the irradiance maps"};
  map.m_irradiance = std::move(*irradiance);
  map.m_stretch = std::move(*stretch);
  map.m_position = std::move(*position);
  map.m_framebuffer = gl::Framebuffer::create(gl);
  gl.BindFramebuffer(GL_FRAMEBUFFER, map.m_framebuffer.id());
  gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, map.m_irradiance.id(), 0);
  gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, map.m_stretch.id(), 0);
  gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT2, GL_TEXTURE_2D, map.m_position.id(), 0);
  if (gl.CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    return Error{"texture space: the irradiance framebuffer is incomplete (RGBA16F/32F targets)"};
  return map;
}

Result<void> IrradianceMap::render(GLuint vertexArray, GLsizei indexCount, const IrradianceFrame& frame,
                                   const IrradianceMapSettings& settings, bool writePositions) {
  const gl::GlApi& g = *m_gl;
  // Step 1: the map size of this frame, eq. 3-4 with d to the nearest box corner (Fig. 4).
  m_size = m_maxSize;
  if (settings.depthSize && settings.referenceDistanceMm > 0.0f) {
    const Float3 lo{frame.boundsLo.x + frame.offsetMm.x, frame.boundsLo.y + frame.offsetMm.y,
                    frame.boundsLo.z + frame.offsetMm.z};
    const Float3 hi{frame.boundsHi.x + frame.offsetMm.x, frame.boundsHi.y + frame.offsetMm.y,
                    frame.boundsHi.z + frame.offsetMm.z};
    const float s =
        irradianceMapScale(nearestBoxCornerDistance(frame.eye, lo, hi), settings.referenceDistanceMm);
    m_size = irradianceMapSize(s, m_maxSize);
  }
  m_scale = float(m_size) / float(m_maxSize);
  // Step 2: clear the used square only (alpha 0: nothing there), draw in UV space.
  g.BindFramebuffer(GL_FRAMEBUFFER, m_framebuffer.id());
  const GLenum buffers[3] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1,
                             writePositions ? GLenum(GL_COLOR_ATTACHMENT2) : GLenum(GL_NONE)};
  g.DrawBuffers(3, buffers);
  g.Viewport(0, 0, m_size, m_size);
  g.Enable(GL_SCISSOR_TEST);
  g.Scissor(0, 0, m_size, m_size);
  g.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  g.ClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  g.Clear(GL_COLOR_BUFFER_BIT);
  g.Disable(GL_SCISSOR_TEST);
  g.Disable(GL_DEPTH_TEST);
  g.Disable(GL_CULL_FACE);  // charts may be mirrored in UV space
  g.Disable(GL_BLEND);
  // Step 3: uniforms; the frustum planes in eye space (eq. 6).
  g.UseProgram(m_program.id());
  g.UniformMatrix4fv(m_view, 1, GL_FALSE, frame.view.data());
  const auto planes = eyeSpaceFrustumPlanes(frame.projection, settings.clipD);
  g.Uniform4fv(m_clipPlanes, 6, &planes[0].x);
  g.Uniform1i(m_clip, settings.clip ? 1 : 0);
  g.Uniform1i(m_cull, settings.cull ? 1 : 0);
  g.Uniform1f(m_cullCosine, kCullCosine);
  g.Uniform1f(m_mapSize, float(m_size));
  g.Uniform3f(m_offset, frame.offsetMm.x, frame.offsetMm.y, frame.offsetMm.z);
  g.Uniform3f(m_lightPosition, frame.lightPosition.x, frame.lightPosition.y, frame.lightPosition.z);
  g.Uniform3f(m_lightRadiance, frame.lightRadiance.x, frame.lightRadiance.y, frame.lightRadiance.z);
  g.Uniform3f(m_ambient, frame.ambient.x, frame.ambient.y, frame.ambient.z);
  for (int i = 0; i < 6; ++i)
    settings.clip ? g.Enable(GLenum(GL_CLIP_DISTANCE0 + i)) : g.Disable(GLenum(GL_CLIP_DISTANCE0 + i));
  g.BindVertexArray(vertexArray);
  g.DrawElements(GL_TRIANGLES, indexCount, GL_UNSIGNED_INT, nullptr);
  for (int i = 0; i < 6; ++i)
    g.Disable(GLenum(GL_CLIP_DISTANCE0 + i));
  const GLenum one = GL_COLOR_ATTACHMENT0;
  g.DrawBuffers(1, &one);
  return gl::checkGlError(g, "texture space: irradiance pass");
}

}  // namespace tissue::render
