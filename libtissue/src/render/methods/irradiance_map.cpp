// The reusable irradiance-map pass (texture-space diffusion; Jimenez et al. §3-5).
#include "irradiance_map.h"

#include <cstring>
#include <string>
#include <tuple>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "../camera_math.h"
#include "tissue/render/shading.h"

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

Result<std::vector<Float4>> readTexels(const gl::GlApi& gl, GLuint framebuffer, GLenum attachment, int size) {
  std::vector<Float4> texels(std::size_t(size) * std::size_t(size));
  gl.BindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
  gl.ReadBuffer(attachment);
  gl.BindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  gl.PixelStorei(GL_PACK_ALIGNMENT, 4);
  gl.ReadPixels(0, 0, size, size, GL_RGBA, GL_FLOAT, texels.data());
  gl.ReadBuffer(GL_COLOR_ATTACHMENT0);
  if (auto r = gl::checkGlError(gl, "texture space: readback"); !r) return r.error();
  return texels;
}

Result<IrradianceMap> IrradianceMap::create(const gl::GlApi& gl, const gl::ShaderLibrary& library,
                                            int maxSize) {
  if (maxSize < 16) return Error{"texture space: the irradiance map needs at least 16 texels"};
  IrradianceMap map;
  map.m_gl = &gl;
  map.m_maxSize = map.m_size = maxSize;
  // Programs: one point light, and the scene's lights in two variants (samplers on the surface
  // shaders' units: base colour 0, normal map 1, shadow maps 2).
  auto program =
      gl::buildProgram(gl, library, {"texture_space/irradiance.vert", "texture_space/irradiance.frag", {}});
  if (!program) return program.error();
  map.m_program = std::move(*program);
  map.m_lightPosition = gl.GetUniformLocation(map.m_program.id(), "u_lightPosition");
  map.m_lightRadiance = gl.GetUniformLocation(map.m_program.id(), "u_lightRadiance");
  const gl::ShaderDefine mapped[] = {{"TISSUE_NORMAL_MAP", "1"}};
  for (int v = 0; v < 2; ++v) {
    auto scene = gl::buildProgram(gl, library,
                                  {"texture_space/irradiance.vert", "texture_space/irradiance_scene.frag",
                                   v ? std::span(mapped) : std::span<const gl::ShaderDefine>()});
    if (!scene) return scene.error();
    const GLuint id = scene->id();
    gl.UseProgram(id);
    gl.Uniform1i(gl.GetUniformLocation(id, "u_baseColor"), 0);
    gl.Uniform1i(gl.GetUniformLocation(id, "u_normalMap"), 1);
    map.m_scene[v] = std::move(*scene);
  }
  // Targets: allocated once at T_max (§4: "we only allocate memory once").
  auto irradiance = createFloatTexture(gl, maxSize, GL_RGBA16F);
  auto stretch = createFloatTexture(gl, maxSize, GL_RGBA16F);
  auto position = createFloatTexture(gl, maxSize, GL_RGBA32F);
  if (!irradiance || !stretch || !position)
    return Error{"texture space: cannot allocate the irradiance maps"};
  map.m_irradiance = std::move(*irradiance);
  map.m_stretch = std::move(*stretch);
  map.m_position = std::move(*position);
  map.m_depth = gl::Renderbuffer::create(gl);
  gl.BindRenderbuffer(GL_RENDERBUFFER, map.m_depth.id());
  gl.RenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, maxSize, maxSize);
  map.m_framebuffer = gl::Framebuffer::create(gl);
  gl.BindFramebuffer(GL_FRAMEBUFFER, map.m_framebuffer.id());
  gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, map.m_depth.id());
  gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, map.m_irradiance.id(), 0);
  gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, map.m_stretch.id(), 0);
  gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT2, GL_TEXTURE_2D, map.m_position.id(), 0);
  if (gl.CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    return Error{"texture space: the irradiance framebuffer is incomplete (RGBA16F/32F targets)"};
  return map;
}

void IrradianceMap::begin(GLuint program, const IrradianceFrame& frame, const IrradianceMapSettings& settings,
                          bool writePositions) {
  const gl::GlApi& g = *m_gl;
  // Step 1: the map size of this frame, eq. 3-4 with d to the nearest box corner (Fig. 4).
  m_size = m_maxSize;
  if (settings.depthSize && settings.referenceDistanceMm > 0.0f) {
    const float s = irradianceMapScale(nearestBoxCornerDistance(frame.eye, frame.boundsLo, frame.boundsHi),
                                       settings.referenceDistanceMm);
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
  g.ClearDepth(1.0);
  g.DepthMask(GL_TRUE);
  g.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  g.Disable(GL_SCISSOR_TEST);
  g.Disable(GL_DEPTH_TEST);
  g.Disable(GL_CULL_FACE);  // charts may be mirrored in UV space
  g.Disable(GL_BLEND);
  // Step 3: uniforms; the frustum planes in eye space (eq. 6).
  g.UseProgram(program);
  auto at = [&](const char* name) { return g.GetUniformLocation(program, name); };
  g.UniformMatrix4fv(at("u_view"), 1, GL_FALSE, frame.view.data());
  const auto planes = eyeSpaceFrustumPlanes(frame.projection, settings.clipD);
  g.Uniform4fv(at("u_clipPlanes"), 6, &planes[0].x);
  g.Uniform1i(at("u_clip"), settings.clip ? 1 : 0);
  g.Uniform1i(at("u_cull"), settings.cull ? 1 : 0);
  g.Uniform1i(at("u_twoSided"), frame.twoSided ? 1 : 0);  // -1 (no such uniform) in irradiance.frag: a no-op
  g.Uniform1f(at("u_cullCosine"), kCullCosine);
  g.Uniform1f(at("u_mapSize"), float(m_size));
  g.UniformMatrix4fv(at("u_model"), 1, GL_FALSE, frame.model.data());
  g.UniformMatrix3fv(at("u_normalMatrix"), 1, GL_FALSE, frame.normalMatrix.data());
  g.Uniform3f(at("u_ambient"), frame.ambient.x, frame.ambient.y, frame.ambient.z);
}

Result<void> IrradianceMap::draw(GLuint vertexArray, GLsizei indexCount, bool clip) {
  const gl::GlApi& g = *m_gl;
  for (int i = 0; i < 6; ++i)
    clip ? g.Enable(GLenum(GL_CLIP_DISTANCE0 + i)) : g.Disable(GLenum(GL_CLIP_DISTANCE0 + i));
  g.BindVertexArray(vertexArray);
  g.DrawElements(GL_TRIANGLES, indexCount, GL_UNSIGNED_INT, nullptr);
  for (int i = 0; i < 6; ++i)
    g.Disable(GLenum(GL_CLIP_DISTANCE0 + i));
  const GLenum one = GL_COLOR_ATTACHMENT0;
  g.DrawBuffers(1, &one);
  return gl::checkGlError(g, "texture space: irradiance pass");
}

Result<void> IrradianceMap::render(GLuint vertexArray, GLsizei indexCount, const IrradianceFrame& frame,
                                   const IrradianceMapSettings& settings, bool writePositions) {
  const gl::GlApi& g = *m_gl;
  begin(m_program.id(), frame, settings, writePositions);
  m_visibilityInDepth = false;
  g.Uniform3f(m_lightPosition, frame.lightPosition.x, frame.lightPosition.y, frame.lightPosition.z);
  g.Uniform3f(m_lightRadiance, frame.lightRadiance.x, frame.lightRadiance.y, frame.lightRadiance.z);
  return draw(vertexArray, indexCount, settings.clip);
}

Result<void> IrradianceMap::render(GLuint vertexArray, GLsizei indexCount, const IrradianceFrame& frame,
                                   const IrradianceMapSettings& settings, const IrradianceLighting& lighting,
                                   bool writePositions) {
  const gl::GlApi& g = *m_gl;
  if (!lighting.lights) return Error{"texture space: the scene irradiance pass needs the frame's lights"};
  if (lighting.transmittance.size() > std::size_t(kMaxTransmittanceRows))
    return Error{"texture space: at most " + std::to_string(kMaxTransmittanceRows) + " transmittance rows"};
  const GLuint program = m_scene[lighting.normalMap ? 1 : 0].id();
  begin(program, frame, settings, writePositions);
  // Visibility into depth (irradiance_scene.frag: 0 visible, 1 culled), every texel written.
  g.Enable(GL_DEPTH_TEST);
  g.DepthFunc(GL_ALWAYS);
  m_visibilityInDepth = true;
  auto at = [&](const char* name) { return g.GetUniformLocation(program, name); };
  constexpr int kShadowUnit = 2;
  setLightUniforms(g, program, *lighting.lights, kShadowUnit);
  g.Uniform1f(at("u_albedoPreScatter"), lighting.albedoPreScatter);
  g.Uniform1i(at("u_transmittanceRows"), GLint(lighting.transmittance.size()));
  if (!lighting.transmittance.empty())
    g.Uniform4fv(at("u_transmittance"), GLsizei(lighting.transmittance.size()), &lighting.transmittance[0].x);
  g.Uniform1f(at("u_transmissionShrinkMm"), lighting.transmissionShrinkMm);
  for (auto [unit, target, texture] :
       {std::tuple{0, GLenum(GL_TEXTURE_2D), lighting.baseColor},
        std::tuple{1, GLenum(GL_TEXTURE_2D), lighting.normalMap},
        std::tuple{kShadowUnit, GLenum(GL_TEXTURE_2D_ARRAY), lighting.shadowMaps}}) {
    g.ActiveTexture(GLenum(GL_TEXTURE0 + unit));
    g.BindTexture(target, texture);
  }
  g.ActiveTexture(GL_TEXTURE0);
  return draw(vertexArray, indexCount, settings.clip);
}

IrradianceFrame cameraIrradianceFrame(const Camera& c, int width, int height) {
  const auto toMat = [](const glm::mat4& m) {
    Mat4 out;
    std::memcpy(out.data(), glm::value_ptr(m), sizeof(float) * 16);
    return out;
  };
  IrradianceFrame f;
  f.view = toMat(glm::lookAt(toGlm(c.eye), toGlm(c.target), toGlm(c.up)));
  f.projection = toMat(
      glm::perspective(glm::radians(c.verticalFovDeg), float(width) / float(height), c.nearMm, c.farMm));
  f.eye = c.eye;
  return f;
}

}  // namespace tissue::render
