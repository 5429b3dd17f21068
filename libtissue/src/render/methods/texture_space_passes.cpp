// Texture-space diffusion: the Gaussian chain and the combined map (d'Eon et al. 2007).
#include "texture_space_passes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "tissue/gl/program.h"

namespace tissue::render {

Result<TextureSpaceDiffusion> TextureSpaceDiffusion::create(const gl::GlApi& gl,
                                                            const gl::ShaderLibrary& library, int maxSize) {
  TextureSpaceDiffusion tsd;
  tsd.m_gl = &gl;
  auto irradiance = IrradianceMap::create(gl, library, maxSize);
  if (!irradiance) return irradiance.error();
  tsd.m_irradiance = std::move(*irradiance);
  auto blur = gl::buildProgram(gl, library, {"texture_space/fullscreen.vert", "texture_space/blur.frag", {}});
  if (!blur) return blur.error();
  auto combine =
      gl::buildProgram(gl, library, {"texture_space/fullscreen.vert", "texture_space/combine.frag", {}});
  if (!combine) return combine.error();
  tsd.m_blur = std::move(*blur);
  tsd.m_combine = std::move(*combine);
  // The temporary and one map per Gaussian, all T_max^2 RGBA16F.
  const auto target = [&](gl::Texture& texture, gl::Framebuffer& framebuffer) -> Result<void> {
    auto t = createFloatTexture(gl, maxSize, GL_RGBA16F);
    if (!t) return t.error();
    texture = std::move(*t);
    framebuffer = gl::Framebuffer::create(gl);
    gl.BindFramebuffer(GL_FRAMEBUFFER, framebuffer.id());
    gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture.id(), 0);
    if (gl.CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
      return Error{"texture space: a blur framebuffer is incomplete"};
    return {};
  };
  if (auto r = target(tsd.m_temp, tsd.m_tempFramebuffer); !r) return r.error();
  tsd.m_maps.resize(kMaxTsdGaussians);
  tsd.m_mapFramebuffers.resize(kMaxTsdGaussians);
  for (int i = 0; i < kMaxTsdGaussians; ++i)
    if (auto r = target(tsd.m_maps[std::size_t(i)], tsd.m_mapFramebuffers[std::size_t(i)]); !r)
      return r.error();
  // Every blur target shares the irradiance map's visibility depth (culled texels skipped, §3).
  const auto attachDepth = [&](const gl::Framebuffer& f) {
    gl.BindFramebuffer(GL_FRAMEBUFFER, f.id());
    gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER,
                               tsd.m_irradiance.visibilityDepth());
  };
  attachDepth(tsd.m_tempFramebuffer);
  for (const gl::Framebuffer& f : tsd.m_mapFramebuffers)
    attachDepth(f);
  tsd.m_emptyVertexArray = gl::VertexArray::create(gl);
  // Samplers: combine reads the maps on units 0..7.
  gl.UseProgram(tsd.m_combine.id());
  for (int i = 0; i < kMaxTsdGaussians; ++i)
    gl.Uniform1i(gl.GetUniformLocation(tsd.m_combine.id(), ("u_maps[" + std::to_string(i) + "]").c_str()), i);
  gl.UseProgram(tsd.m_blur.id());
  gl.Uniform1i(gl.GetUniformLocation(tsd.m_blur.id(), "u_source"), 0);
  gl.Uniform1i(gl.GetUniformLocation(tsd.m_blur.id(), "u_stretch"), 1);
  if (auto r = gl::checkGlError(gl, "texture space: create"); !r) return r.error();
  return tsd;
}

Result<void> TextureSpaceDiffusion::blur(GLuint source, GLuint target, float sigmaMm, bool horizontal,
                                         const TextureSpaceDiffusionSettings& settings) {
  const gl::GlApi& g = *m_gl;
  const GLuint id = m_blur.id();
  const float scale = m_irradiance.scale();
  bindTexels(target, settings.irradiance.cull);
  g.UseProgram(id);
  g.Uniform2f(g.GetUniformLocation(id, "u_direction"), horizontal ? 1.0f : 0.0f, horizontal ? 0.0f : 1.0f);
  g.Uniform1f(g.GetUniformLocation(id, "u_sigmaMm"), sigmaMm);
  g.Uniform1f(g.GetUniformLocation(id, "u_mapScale"), scale);
  g.Uniform1f(g.GetUniformLocation(id, "u_maxCoord"), scale - 0.5f / float(m_irradiance.maxSize()));
  g.Uniform1i(g.GetUniformLocation(id, "u_skipEmpty"), settings.irradiance.cull ? 1 : 0);
  const auto taps = gaussianBlurTaps(std::clamp(settings.blurHalfTaps, 1, 8));
  std::vector<float> offsets, weights;
  for (const BlurTap& t : taps)
    offsets.push_back(t.offsetSigma), weights.push_back(t.weight);
  g.Uniform1i(g.GetUniformLocation(id, "u_tapCount"), GLint(taps.size()));
  g.Uniform1fv(g.GetUniformLocation(id, "u_tapOffsets"), GLsizei(taps.size()), offsets.data());
  g.Uniform1fv(g.GetUniformLocation(id, "u_tapWeights"), GLsizei(taps.size()), weights.data());
  g.ActiveTexture(GL_TEXTURE0);
  g.BindTexture(GL_TEXTURE_2D, source);
  g.ActiveTexture(GL_TEXTURE1);
  g.BindTexture(GL_TEXTURE_2D, m_irradiance.stretch());
  g.BindVertexArray(m_emptyVertexArray.id());
  g.DrawArrays(GL_TRIANGLES, 0, 3);
  return {};
}

Result<void> TextureSpaceDiffusion::diffuse(GLuint vertexArray, GLsizei indexCount,
                                            const IrradianceFrame& frame,
                                            const TextureSpaceDiffusionSettings& settings,
                                            bool writePositions) {
  if (settings.gaussians.empty() || int(settings.gaussians.size()) > kMaxTsdGaussians)
    return Error{"texture space: the profile needs 1 to " + std::to_string(kMaxTsdGaussians) + " Gaussians"};
  if (auto r = m_irradiance.render(vertexArray, indexCount, frame, settings.irradiance, writePositions); !r)
    return r;
  return convolve(settings);
}

Result<void> TextureSpaceDiffusion::convolve(const TextureSpaceDiffusionSettings& settings) {
  if (settings.gaussians.empty() || int(settings.gaussians.size()) > kMaxTsdGaussians)
    return Error{"texture space: the profile needs 1 to " + std::to_string(kMaxTsdGaussians) + " Gaussians"};
  const gl::GlApi& g = *m_gl;
  g.Disable(GL_DEPTH_TEST);
  g.Disable(GL_CULL_FACE);
  g.Disable(GL_BLEND);
  // Each Gaussian blurs the previous one by the variance it adds (d'Eon: G(v1) * G(v2) = G(v1 + v2)).
  const auto steps = incrementalVariances(settings.gaussians);
  GLuint source = m_irradiance.irradiance();
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const float sigma = std::sqrt(steps[i]);
    if (auto r = blur(source, m_tempFramebuffer.id(), sigma, true, settings); !r) return r;
    if (auto r = blur(m_temp.id(), m_mapFramebuffers[i].id(), sigma, false, settings); !r) return r;
    source = m_maps[i].id();
  }
  g.Disable(GL_DEPTH_TEST);
  return gl::checkGlError(g, "texture space: convolution");
}

Result<GLuint> TextureSpaceDiffusion::combine(const TextureSpaceDiffusionSettings& settings) {
  const gl::GlApi& g = *m_gl;
  const GLuint id = m_combine.id();
  std::array<Float3, kMaxTsdGaussians> weights{};
  for (std::size_t i = 0; i < settings.gaussians.size() && i < weights.size(); ++i)
    weights[i] = settings.gaussians[i].weight;
  // The temporary is free once the chain is done: the sum goes there.
  bindTexels(m_tempFramebuffer.id(), settings.irradiance.cull);
  g.Disable(GL_CULL_FACE);
  g.Disable(GL_BLEND);
  g.UseProgram(id);
  g.Uniform1f(g.GetUniformLocation(id, "u_mapScale"), m_irradiance.scale());
  g.Uniform1i(g.GetUniformLocation(id, "u_gaussianCount"), GLint(settings.gaussians.size()));
  g.Uniform3fv(g.GetUniformLocation(id, "u_weights"), kMaxTsdGaussians, &weights[0].x);
  for (int i = 0; i < kMaxTsdGaussians; ++i) {
    g.ActiveTexture(GLenum(GL_TEXTURE0 + i));
    g.BindTexture(GL_TEXTURE_2D, m_maps[std::size_t(i)].id());
  }
  g.ActiveTexture(GL_TEXTURE0);
  g.BindVertexArray(m_emptyVertexArray.id());
  g.DrawArrays(GL_TRIANGLES, 0, 3);
  g.Disable(GL_DEPTH_TEST);
  if (auto r = gl::checkGlError(g, "texture space: combine"); !r) return r.error();
  return m_temp.id();
}

void TextureSpaceDiffusion::bindTexels(GLuint target, bool skipCulled) const {
  const gl::GlApi& g = *m_gl;
  const int size = m_irradiance.size();
  g.BindFramebuffer(GL_FRAMEBUFFER, target);
  g.Viewport(0, 0, size, size);
  if (!skipCulled || !m_irradiance.visibilityInDepth()) {
    g.Disable(GL_DEPTH_TEST);
    return;
  }
  // Culled and empty texels (depth 1) fail GL_GREATER for the full-screen triangle (depth 0.5)
  // before shading (§3's "convolution skipped where alpha is 0"); they keep the cleared 0.
  g.Enable(GL_SCISSOR_TEST);
  g.Scissor(0, 0, size, size);
  g.ClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  g.Clear(GL_COLOR_BUFFER_BIT);
  g.Disable(GL_SCISSOR_TEST);
  g.Enable(GL_DEPTH_TEST);
  g.DepthFunc(GL_GREATER);
  g.DepthMask(GL_FALSE);
}

}  // namespace tissue::render
