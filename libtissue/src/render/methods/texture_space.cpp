// Texture-space diffusion as a pipeline method: irradiance in UV space, Gaussian chain, camera pass.
#include "texture_space.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <cmath>
#include <cstring>
#include <string>
#include <tuple>

#include "../camera_math.h"
#include "tissue/gl/program.h"

namespace tissue::render {
namespace {

Result<void> checkSettings(const TextureSpaceSettings& s, float objectId) {
  const std::string where =
      "renderer: texture-space object " + std::to_string(static_cast<int>(objectId) - 1);
  if (s.gaussians.empty() || s.gaussians.size() > static_cast<std::size_t>(kMaxTsdGaussians)) {
    return Error{where + " has " + std::to_string(s.gaussians.size()) + " Gaussians; give 1.." +
                 std::to_string(kMaxTsdGaussians) +
                 " {variance mm^2, RGB weight} terms (e.g. fitted to the "
                 "material's profile)"};
  }
  float previous = 0.0f;
  for (const ProfileGaussian& g : s.gaussians) {
    if (!std::isfinite(g.varianceMm2) || g.varianceMm2 <= previous || !std::isfinite(g.weight.x) ||
        !std::isfinite(g.weight.y) || !std::isfinite(g.weight.z))
      return Error{where + ": Gaussian variances must be finite, positive and increasing (mm^2)"};
    previous = g.varianceMm2;
  }
  if (s.mapSize < 16 || s.mapSize > 8192)
    return Error{where + " has mapSize " + std::to_string(s.mapSize) + "; give 16..8192 texels"};
  if (s.blurHalfTaps < 1 || s.blurHalfTaps > 8)
    return Error{where + " has blurHalfTaps " + std::to_string(s.blurHalfTaps) + "; give 1..8"};
  if (s.transmittance.size() > static_cast<std::size_t>(kMaxTransmittanceRows)) {
    return Error{where + " has " + std::to_string(s.transmittance.size()) + " transmittance rows; at most " +
                 std::to_string(kMaxTransmittanceRows)};
  }
  if (!(s.albedoPreScatter >= 0.0f && s.albedoPreScatter <= 1.0f))
    return Error{where + ": albedoPreScatter must be in 0..1"};
  return {};
}

// d_ref of eq. 3 (mm): given, or where one texel of the full map covers one pixel: a pixel
// spans 2 d tan(fov / 2) / H mm at distance d. The density measured at upload is per object-space
// mm; the model's scale s makes it 1 / s as many per world mm.
float referenceDistanceMm(const FrameContext& frame, const TextureSpaceSettings& s, const ObjectDraw& d) {
  if (s.referenceDistanceMm > 0.0f) return s.referenceDistanceMm;
  const float texelsPerMm =
      s.texelsPerMm > 0.0f ? s.texelsPerMm : d.mesh->uvDensity() * float(s.mapSize) / d.transform.scale;
  const float tanHalf = std::tan(glm::radians(frame.scene.camera.verticalFovDeg) * 0.5f);
  return texelsPerMm > 0.0f ? float(frame.height) / (2.0f * tanHalf * texelsPerMm) : 0.0f;
}

}  // namespace

Result<TextureSpaceMethod> TextureSpaceMethod::create(const gl::GlApi& gl, const gl::ShaderLibrary& library) {
  TextureSpaceMethod m;
  m.m_library = library;
  auto final = buildSurfacePrograms(gl, library, "texture_space/surface.frag");
  if (!final) return final.error();
  m.m_final = std::move(*final);
  for (const GLuint id : {m.m_final.flat.id(), m.m_final.mapped.id()}) {
    gl.UseProgram(id);
    gl.Uniform1i(gl.GetUniformLocation(id, "u_diffused"), kUnitMethod0);
  }
  m.m_copySource = gl::Framebuffer::create(gl);
  return m;
}

Result<TextureSpaceDiffusion*> TextureSpaceMethod::chain(const FrameContext& frame, int maxSize) {
  auto found = m_chains.find(maxSize);
  if (found != m_chains.end()) return &found->second;
  auto created = TextureSpaceDiffusion::create(frame.gl, m_library, maxSize);
  if (!created) return created.error();
  return &m_chains.emplace(maxSize, std::move(*created)).first->second;
}

Result<void> TextureSpaceMethod::draw(const FrameContext& frame, std::span<const ObjectDraw> objects) {
  for (const ObjectDraw& d : objects) {
    if (auto r = checkSettings(std::get<TextureSpaceSettings>(d.object->method), d.objectId); !r) return r;
  }
  const gl::GlApi& g = frame.gl;
  const IrradianceFrame view = cameraIrradianceFrame(frame.scene.camera, frame.width, frame.height);
  // Objects one after another, sharing the maps of their size (as Jimenez et al.'s heads).
  for (const ObjectDraw& d : objects) {
    const auto& s = std::get<TextureSpaceSettings>(d.object->method);
    auto tsd = chain(frame, s.mapSize);
    if (!tsd) return tsd.error();
    TextureSpaceDiffusion& maps = **tsd;
    m_last = &maps;
    const TextureSpaceDiffusionSettings passes{
        s.gaussians,
        {s.cull, s.clip, s.depthSize, s.clipD, referenceDistanceMm(frame, s, d)},
        s.blurHalfTaps};
    IrradianceFrame object = view;
    object.boundsLo = fromGlm(d.lo), object.boundsHi = fromGlm(d.hi);
    object.model = toArray(d.transform.model);
    object.normalMatrix = toArray(d.transform.normalMatrix);
    object.twoSided = d.object->doubleSided;
    object.ambient = d.object->material.ambient;
    const IrradianceLighting lighting{&frame.lights,         frame.shadowMaps,   d.baseColor,
                                      d.normalMap,           s.albedoPreScatter, s.transmittance,
                                      s.transmissionShrinkMm};
    auto r = frame.passes.run(
        "texture-space:irradiance",
        [&] {
          return maps.irradianceMap().render(d.mesh->vertexArray(), d.mesh->indexCount(), object,
                                             passes.irradiance, lighting, true);
        },
        d.index());
    if (!r) return r;
    GLuint diffused = 0;
    r = frame.passes.run(
        "texture-space:blur",
        [&]() -> Result<void> {
          if (auto done = maps.convolve(passes); !done) return done;
          auto sum = maps.combine(passes);
          if (!sum) return sum.error();
          diffused = *sum;
          return {};
        },
        d.index());
    if (!r) return r;
    r = frame.passes.run(
        "texture-space:final",
        [&] {
          beginGeometryPass(frame);
          const GLuint program = m_final.pick(d);
          setFrameUniforms(frame, program);
          g.Uniform1f(g.GetUniformLocation(program, "u_mapScale"), maps.irradianceMap().scale());
          g.Uniform1f(g.GetUniformLocation(program, "u_albedoPreScatter"), s.albedoPreScatter);
          g.ActiveTexture(GL_TEXTURE0 + kUnitMethod0);
          g.BindTexture(GL_TEXTURE_2D, diffused);
          drawSurface(frame, program, d);
          return gl::checkGlError(g, "renderer: texture-space final pass");
        },
        d.index());
    if (!r) return r;
  }
  return {};
}

Result<void> TextureSpaceMethod::post(const FrameContext& frame, bool separableBlurred) const {
  if (separableBlurred) return {};
  return frame.passes.run("texture-space:copy", [&] {
    const gl::GlApi& g = frame.gl;
    g.BindFramebuffer(GL_READ_FRAMEBUFFER, m_copySource.id());
    g.FramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, frame.targets.diffuse(),
                           0);
    g.ReadBuffer(GL_COLOR_ATTACHMENT0);
    g.BindFramebuffer(GL_DRAW_FRAMEBUFFER, frame.targets.blurredFramebuffer());
    g.Disable(GL_SCISSOR_TEST);
    g.BlitFramebuffer(0, 0, frame.width, frame.height, 0, 0, frame.width, frame.height, GL_COLOR_BUFFER_BIT,
                      GL_NEAREST);
    return gl::checkGlError(g, "renderer: texture-space copy of the diffuse target");
  });
}

Result<TextureSpaceMaps> TextureSpaceMethod::readMaps(const gl::GlApi& gl) const {
  if (!m_last) return Error{"renderer: readTextureSpaceMaps before any texture-space object was drawn"};
  const IrradianceMap& map = m_last->irradianceMap();
  const int t = map.size();
  TextureSpaceMaps out;
  out.size = t;
  out.maxSize = map.maxSize();
  for (auto [image, framebuffer, attachment] :
       {std::tuple{&out.irradiance, map.framebuffer(), GLenum(GL_COLOR_ATTACHMENT0)},
        std::tuple{&out.stretch, map.framebuffer(), GLenum(GL_COLOR_ATTACHMENT1)},
        std::tuple{&out.position, map.framebuffer(), GLenum(GL_COLOR_ATTACHMENT2)},
        std::tuple{&out.diffused, m_last->combinedFramebuffer(), GLenum(GL_COLOR_ATTACHMENT0)}}) {
    auto texels = readTexels(gl, framebuffer, attachment, t);
    if (!texels) return texels.error();
    *image = FloatImage{t, t, std::move(*texels)};
  }
  return out;
}

}  // namespace tissue::render
