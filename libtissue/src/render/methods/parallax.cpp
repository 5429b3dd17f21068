// Layered parallax multi-texturing (Oat 2006; Norberg 2010 §2.2, §3.2). The lightmap reuses the
// irradiance pass of texture-space diffusion (IrradianceMap) with its culling and clipping.
#include "parallax.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <cmath>
#include <cstring>
#include <string>

#include "../camera_math.h"
#include "tissue/gl/program.h"
#include "tissue/render/parallax_math.h"

namespace tissue::render {
namespace {

constexpr int kDiscSamples = 16;     // per blur pass (shaders/parallax/blur.frag: at most 32)
constexpr float kFarLightMm = 1e6f;  // a directional light becomes a point this far away

Result<void> checkSettings(const ParallaxSettings& s, float objectId) {
  const std::string where = "renderer: parallax object " + std::to_string(static_cast<int>(objectId) - 1);
  if (s.layers.empty() || s.layers.size() > static_cast<std::size_t>(kMaxParallaxLayers)) {
    return Error{where + " has " + std::to_string(s.layers.size()) + " inner layers; give 1.." +
                 std::to_string(kMaxParallaxLayers)};
  }
  float previous = 0.0f;
  for (const ParallaxLayer& l : s.layers) {
    if (!std::isfinite(l.depthMm) || l.depthMm <= previous) {
      return Error{where + ": inner-layer depths must be finite, positive and increasing (mm); got " +
                   std::to_string(l.depthMm) + " after " + std::to_string(previous)};
    }
    previous = l.depthMm;
  }
  if (!(s.refractiveIndex >= 1.0f && s.refractiveIndex < 10.0f))
    return Error{where + ": refractiveIndex must be in [1, 10) (n_inside / n_outside)"};
  if (!(s.innerBlurPerMm >= 0.0f) || !(s.maxTransmissionMm > 0.0f))
    return Error{where + ": innerBlurPerMm must be >= 0 and maxTransmissionMm > 0 (mm)"};
  const ParallaxLightmapSettings& m = s.lightmap;
  const int r = m.reduction;
  if (m.size < 16 || m.size > 2048 || (r != 1 && r != 2 && r != 4 && r != 8) || m.size % r != 0) {
    return Error{where +
                 ": lightmap size must be 16..2048 texels and reduction 1, 2, 4 or 8 dividing it; got " +
                 std::to_string(m.size) + " / " + std::to_string(r)};
  }
  if (m.blurPasses < 0 || m.blurPasses > 16 || !(m.blurRadiusMm >= 0.0f))
    return Error{where + ": lightmap blurPasses must be 0..16 and blurRadiusMm >= 0 (mm)"};
  return {};
}

void fullScreenState(const gl::GlApi& g, GLuint framebuffer, int size) {
  g.BindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  g.Viewport(0, 0, size, size);
  g.Disable(GL_DEPTH_TEST);
  g.Disable(GL_CULL_FACE);
  g.Disable(GL_SCISSOR_TEST);
  g.DepthMask(GL_FALSE);
}

}  // namespace

Result<ParallaxMethod> ParallaxMethod::create(const gl::GlApi& gl, const gl::ShaderLibrary& library) {
  ParallaxMethod m;
  m.m_library = library;
  auto geometry = buildSurfacePrograms(gl, library, "parallax/geometry.frag");
  if (!geometry) return geometry.error();
  m.m_geometry = std::move(*geometry);
  for (const GLuint p : {m.m_geometry.flat.id(), m.m_geometry.mapped.id()}) {
    gl.UseProgram(p);
    gl.Uniform1i(gl.GetUniformLocation(p, "u_lightmap"), kUnitMethod0);
    gl.Uniform1i(gl.GetUniformLocation(p, "u_opacityMap"), kUnitMethod0 + 1);
    gl.Uniform1i(gl.GetUniformLocation(p, "u_inner0"), kUnitMethod0 + 2);
    gl.Uniform1i(gl.GetUniformLocation(p, "u_inner1"), kUnitMethod0 + 3);
    gl.Uniform1i(gl.GetUniformLocation(p, "u_inner2"), kUnitMethod0 + 4);
  }
  auto gather = gl::buildProgram(gl, library, {"post/fullscreen.vert", "parallax/gather.frag", {}});
  if (!gather) return gather.error();
  m.m_gather = std::move(*gather);
  auto blur = gl::buildProgram(gl, library, {"post/fullscreen.vert", "parallax/blur.frag", {}});
  if (!blur) return blur.error();
  m.m_blur = std::move(*blur);
  gl.UseProgram(m.m_gather.id());
  gl.Uniform1i(gl.GetUniformLocation(m.m_gather.id(), "u_irradiance"), kUnitMethod0);
  gl.UseProgram(m.m_blur.id());
  gl.Uniform1i(gl.GetUniformLocation(m.m_blur.id(), "u_input"), kUnitMethod0);
  gl.Uniform1i(gl.GetUniformLocation(m.m_blur.id(), "u_stretch"), kUnitMethod0 + 1);
  m.m_disc = poissonDisc(kDiscSamples);
  gl.Uniform2fv(gl.GetUniformLocation(m.m_blur.id(), "u_disc"), kDiscSamples, &m.m_disc[0].x);
  gl.Uniform1i(gl.GetUniformLocation(m.m_blur.id(), "u_discCount"), kDiscSamples);
  return m;
}

Result<ParallaxMethod::Lightmap*> ParallaxMethod::ensureLightmap(const gl::GlApi& g,
                                                                 const ParallaxLightmapSettings& s) const {
  const std::pair key{s.size, s.reduction};
  if (const auto found = m_lightmaps.find(key); found != m_lightmaps.end()) return found->second.get();
  auto l = std::make_unique<Lightmap>();
  auto irradiance = IrradianceMap::create(g, m_library, s.size);
  if (!irradiance) return Error{"renderer: parallax lightmap: " + irradiance.error().message};
  l->irradiance = std::move(*irradiance);
  for (int i = 0; i < 2; ++i) {
    auto map = createFloatTexture(g, s.size / s.reduction, GL_RGBA16F);
    if (!map) return Error{"renderer: parallax lightmap: " + map.error().message};
    l->maps[i] = std::move(*map);
    l->framebuffers[i] = gl::Framebuffer::create(g);
    g.BindFramebuffer(GL_FRAMEBUFFER, l->framebuffers[i].id());
    g.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, l->maps[i].id(), 0);
    if (g.CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
      return Error{"renderer: parallax lightmap framebuffer incomplete (RGBA16F)"};
  }
  l->size = s.size;
  l->reduction = s.reduction;
  return m_lightmaps.emplace(key, std::move(l)).first->second.get();
}

Result<int> ParallaxMethod::lightmap(const FrameContext& frame, const ObjectDraw& object, Lightmap& l) const {
  const gl::GlApi& g = frame.gl;
  const auto& s = std::get<ParallaxSettings>(object.object->method);
  const int reduced = s.lightmap.size / s.lightmap.reduction;
  // parallax:lightmap — per light: irradiance in UV space (culled, clipped), then box-filtered
  // into maps[0]; the first light overwrites (rgb and a), later ones add rgb.
  auto drawn = frame.passes.run(
      "parallax:lightmap",
      [&]() -> Result<void> {
        IrradianceFrame f = cameraIrradianceFrame(frame.scene.camera, frame.width, frame.height);
        f.boundsLo = fromGlm(object.lo), f.boundsHi = fromGlm(object.hi);
        f.model = toArray(object.transform.model);
        f.normalMatrix = toArray(object.transform.normalMatrix);
        const IrradianceMapSettings settings{s.lightmap.cull, s.lightmap.clip, false, 1.0f, 0.0f};
        const glm::vec3 centre = 0.5f * (toGlm(f.boundsLo) + toGlm(f.boundsHi));
        for (int i = 0; i < std::max(frame.lights.count, 1); ++i) {
          if (frame.lights.count > 0) {
            const glm::vec4 v = frame.lights.vector[static_cast<std::size_t>(i)];
            const glm::vec3 position = v.w > 0.5f ? glm::vec3(v) : centre + glm::vec3(v) * kFarLightMm;
            f.lightPosition = fromGlm(position);
            f.lightRadiance = fromGlm(frame.lights.radiance[static_cast<std::size_t>(i)]);
          } else {
            f.lightRadiance = {};
          }
          f.ambient = i == 0 ? object.object->material.ambient : Float3{};
          if (auto r =
                  l.irradiance.render(object.mesh->vertexArray(), object.mesh->indexCount(), f, settings);
              !r)
            return r;
          fullScreenState(g, l.framebuffers[0].id(), reduced);
          if (i == 0) {
            g.Disable(GL_BLEND);
            g.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
          } else {
            g.Enable(GL_BLEND);
            g.BlendFunc(GL_ONE, GL_ONE);
            g.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_FALSE);  // the visible fraction is the same
          }
          g.UseProgram(m_gather.id());
          g.Uniform1i(g.GetUniformLocation(m_gather.id(), "u_reduction"), s.lightmap.reduction);
          g.ActiveTexture(GL_TEXTURE0 + kUnitMethod0);
          g.BindTexture(GL_TEXTURE_2D, l.irradiance.irradiance());
          drawFullScreen(frame);
        }
        g.Disable(GL_BLEND);
        g.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        return gl::checkGlError(g, "renderer: parallax lightmap pass");
      },
      object.index());
  if (!drawn) return drawn.error();
  // parallax:lightmap-blur — Poisson-disc passes, ping-pong (§3.2).
  const float radiusMm = poissonPassRadiusMm(s.lightmap.blurRadiusMm, s.lightmap.blurPasses);
  if (s.lightmap.blurPasses == 0 || radiusMm <= 0.0f) return 0;
  int current = 0;
  auto blurred = frame.passes.run(
      "parallax:lightmap-blur",
      [&]() -> Result<void> {
        const GLuint p = m_blur.id();
        g.UseProgram(p);
        g.Uniform1f(g.GetUniformLocation(p, "u_radiusMm"), radiusMm);
        g.Uniform1f(g.GetUniformLocation(p, "u_size"), float(reduced));
        g.ActiveTexture(GL_TEXTURE0 + kUnitMethod0 + 1);
        g.BindTexture(GL_TEXTURE_2D, l.irradiance.stretch());
        for (int pass = 0; pass < s.lightmap.blurPasses; ++pass) {
          fullScreenState(g, l.framebuffers[1 - current].id(), reduced);
          g.Disable(GL_BLEND);
          g.ActiveTexture(GL_TEXTURE0 + kUnitMethod0);
          g.BindTexture(GL_TEXTURE_2D, l.maps[current].id());
          drawFullScreen(frame);
          current = 1 - current;
        }
        return gl::checkGlError(g, "renderer: parallax lightmap blur");
      },
      object.index());
  if (!blurred) return blurred.error();
  return current;
}

Result<void> ParallaxMethod::geometry(const FrameContext& frame, const ObjectDraw& object,
                                      GLuint lightmapTexture) const {
  return frame.passes.run(
      "parallax:geometry",
      [&]() -> Result<void> {
        const gl::GlApi& g = frame.gl;
        const auto& s = std::get<ParallaxSettings>(object.object->method);
        beginGeometryPass(frame);
        const GLuint p = m_geometry.pick(object);
        setFrameUniforms(frame, p);
        auto at = [&](const char* name) { return g.GetUniformLocation(p, name); };
        const int layers = static_cast<int>(s.layers.size());
        float depths[kMaxParallaxLayers] = {}, opacities[kMaxParallaxLayers] = {};
        for (int i = 0; i < layers; ++i) {
          depths[i] = s.layers[static_cast<std::size_t>(i)].depthMm;
          opacities[i] = s.layers[static_cast<std::size_t>(i)].opacity;
        }
        g.Uniform1i(at("u_layerCount"), layers);
        g.Uniform1fv(at("u_layerDepthMm"), kMaxParallaxLayers, depths);
        g.Uniform1fv(at("u_layerOpacity"), kMaxParallaxLayers, opacities);
        g.Uniform1f(at("u_refractiveIndex"), s.refractiveIndex);
        g.Uniform1f(at("u_innerBlurPerMm"), s.innerBlurPerMm);
        g.Uniform1f(at("u_maxTransmissionMm"), s.maxTransmissionMm);
        g.Uniform1i(at("u_hasOpacityMap"), object.methodTextures[0] ? 1 : 0);
        g.Uniform1f(at("u_opacity"), s.opacity);
        g.ActiveTexture(GL_TEXTURE0 + kUnitMethod0);
        g.BindTexture(GL_TEXTURE_2D, lightmapTexture);
        g.ActiveTexture(GL_TEXTURE0 + kUnitMethod0 + 1);
        g.BindTexture(GL_TEXTURE_2D, object.methodTextures[0] ? object.methodTextures[0] : object.baseColor);
        for (int i = 0; i < kMaxParallaxLayers; ++i) {  // a layer without a texture: the object's base
          const GLuint t = object.methodTextures[static_cast<std::size_t>(i) + 1];
          g.ActiveTexture(GLenum(GL_TEXTURE0 + kUnitMethod0 + 2 + i));
          g.BindTexture(GL_TEXTURE_2D, t ? t : object.baseColor);
        }
        drawSurface(frame, p, object);
        return gl::checkGlError(g, "renderer: parallax geometry pass");
      },
      object.index());
}

Result<void> ParallaxMethod::draw(const FrameContext& frame, std::span<const ObjectDraw> objects) const {
  for (const ObjectDraw& d : objects) {
    if (auto r = checkSettings(std::get<ParallaxSettings>(d.object->method), d.objectId); !r) return r;
  }
  for (const ObjectDraw& d : objects) {
    const auto& s = std::get<ParallaxSettings>(d.object->method);
    auto l = ensureLightmap(frame.gl, s.lightmap);
    if (!l) return l.error();
    auto current = lightmap(frame, d, **l);
    if (!current) return current.error();
    if (auto r = geometry(frame, d, (*l)->maps[*current].id()); !r) return r;
  }
  return {};
}

}  // namespace tissue::render
