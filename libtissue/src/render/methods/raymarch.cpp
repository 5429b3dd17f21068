// Ray-marched subsurface texture mapping on the GPU (shaders/raymarch/; François et al. 2006,
// Norberg 2010). The CPU twin is tissue::subsurface (plane mode).
#include <algorithm>
#include <cmath>
#include <glm/gtc/type_ptr.hpp>
#include <string>

#include "../camera_math.h"
#include "../mesh_buffers.h"
#include "../offscreen_target.h"
#include "../state_guard.h"
#include "../textures.h"
#include "tissue/core/stopwatch.h"
#include "tissue/gl/program.h"
#include "tissue/render/raymarch_renderer.h"

namespace tissue::render {
namespace {

constexpr int kMaxLayers = 9;  // TISSUE_MAX_LAYERS in shaders/raymarch/march.glsl

// Sets uniforms by name (looked up per frame: a handful of lookups is nothing next to the march).
struct Uniforms {
  const gl::GlApi& gl;
  GLuint program;
  GLint at(const std::string& name) const { return gl.GetUniformLocation(program, name.c_str()); }
  void set(const std::string& n, int v) const { gl.Uniform1i(at(n), v); }
  void set(const std::string& n, float v) const { gl.Uniform1f(at(n), v); }
  void set(const std::string& n, Float3 v) const { gl.Uniform3f(at(n), v.x, v.y, v.z); }
};

}  // namespace

struct RayMarchRenderer::Impl {
  std::shared_ptr<const gl::GlApi> api;
  gl::Program fixedCount, adaptive, fixedShow, adaptiveShow;
  MeshBuffers mesh;
  std::size_t vertexCount = 0;
  RayMarchMaterial material;  // layers and scales (maps live in the textures)
  gl::Texture maps[2];
  int texelsWide = 1;
  OffscreenTarget offscreen;
  double drawMs = 0.0;

  const gl::GlApi& gl() const { return *api; }

  void setUniforms(GLuint program, const Camera& camera, std::span<const RayMarchLight> lights,
                   const RayMarchRenderSettings& s, int width, int height) const {
    const gl::GlApi& g = gl();
    const Uniforms u{g, program};
    const glm::mat4 vp = viewProjection(camera, float(width) / float(height));
    g.UniformMatrix4fv(u.at("u_viewProjection"), 1, GL_FALSE, glm::value_ptr(vp));
    u.set("u_cameraPosition", camera.eye);
    // Layer stack.
    const int layers = int(material.layers.size());
    u.set("u_layerCount", layers);
    u.set("u_boundaryCount", int(material.subsurfaceMaps.size()) * 4);
    float sigmaMin = 1e30f;
    for (int i = 0; i < layers; ++i) {
      const RayMarchLayer& l = material.layers[i];
      u.set("u_sigmaS[" + std::to_string(i) + "]", l.sigma_s);
      u.set("u_sigmaT[" + std::to_string(i) + "]", l.sigma_t);
      u.set("u_schlickK[" + std::to_string(i) + "]", l.schlickK);
      sigmaMin = std::min({sigmaMin, l.sigma_t.x, l.sigma_t.y, l.sigma_t.z});
    }
    u.set("u_subsurface0", 0);
    u.set("u_subsurface1", 1);
    u.set("u_depthScale", material.depthScaleMm);
    u.set("u_uvPerMm", material.uvPerMm);
    // March.
    u.set("u_depthMax", s.depthMaxMm);
    u.set("u_tMaxCap", s.attenuationThreshold > 0.0f ? -std::log(s.attenuationThreshold) / sigmaMin : 1e30f);
    u.set("u_threshold", s.attenuationThreshold);
    u.set("u_minCosView", s.minCosView);
    u.set("u_samples", std::clamp(s.samples, 1, 256));
    u.set("u_jitter", s.jitter ? 1 : 0);
    g.Uniform1ui(u.at("u_seed"), s.seed);
    u.set("u_viewportHeight", height);
    g.Uniform2f(u.at("u_viewportOrigin"), 0.0f, 0.0f);
    u.set("u_exposure", s.exposure);
    // Adaptive quality.
    u.set("u_minSamples", std::clamp(s.minSamples, 1, 256));
    u.set("u_maxSamples", std::clamp(s.maxSamples, 1, 256));
    u.set("u_depthResolution", s.depthResolutionMm);
    u.set("u_texelsPerStep", s.texelsPerStep);
    u.set("u_cutoff", s.cutoff);
    u.set("u_sigmaMin", sigmaMin);
    u.set("u_texelMm", 1.0f / (material.uvPerMm * float(texelsWide)));
    u.set("u_pixelAngle", 2.0f * std::tan(glm::radians(camera.verticalFovDeg) * 0.5f) / float(height));
    // Lights.
    const int n = std::min<int>(int(lights.size()), kMaxLights);
    u.set("u_lightCount", n);
    for (int i = 0; i < n; ++i) {
      u.set("u_lightPosition[" + std::to_string(i) + "]", lights[i].positionMm);
      u.set("u_lightRadiance[" + std::to_string(i) + "]", lights[i].radiance);
    }
  }
};

RayMarchRenderer::RayMarchRenderer(std::unique_ptr<Impl> impl) : m_impl(std::move(impl)) {}
RayMarchRenderer::RayMarchRenderer(RayMarchRenderer&&) noexcept = default;
RayMarchRenderer& RayMarchRenderer::operator=(RayMarchRenderer&&) noexcept = default;
RayMarchRenderer::~RayMarchRenderer() = default;

Result<RayMarchRenderer> RayMarchRenderer::create(const gl::GetProcAddressFn& getProcAddress,
                                                  const gl::ShaderLibrarySettings& shaders) {
  auto api = gl::loadGl(getProcAddress);
  if (!api) return Error{"raymarch renderer: " + api.error().message};
  auto impl = std::make_unique<Impl>();
  impl->api = std::move(*api);
  StateGuard guard(impl->gl());
  const gl::ShaderLibrary library(shaders);
  const gl::ShaderDefine adaptive[] = {{"TISSUE_ADAPTIVE", "1"}};
  const gl::ShaderDefine show[] = {{"TISSUE_SHOW_SAMPLES", "1"}};
  const gl::ShaderDefine adaptiveShow[] = {{"TISSUE_ADAPTIVE", "1"}, {"TISSUE_SHOW_SAMPLES", "1"}};
  gl::Program* targets[] = {&impl->fixedCount, &impl->adaptive, &impl->fixedShow, &impl->adaptiveShow};
  const std::span<const gl::ShaderDefine> variants[] = {{}, adaptive, show, adaptiveShow};
  for (int i = 0; i < 4; ++i) {
    auto program = gl::buildProgram(impl->gl(), library,
                                    {"raymarch/raymarch.vert", "raymarch/raymarch.frag", variants[i]});
    if (!program) return Error{"raymarch renderer: " + program.error().message};
    *targets[i] = std::move(*program);
  }
  if (auto r = gl::checkGlError(impl->gl(), "raymarch renderer: create"); !r) return r.error();
  return RayMarchRenderer(std::move(impl));
}

Result<void> RayMarchRenderer::setMesh(const MeshArrays& mesh, std::span<const Float4> planes) {
  const gl::GlApi& g = m_impl->gl();
  StateGuard guard(g);
  if (planes.size() != mesh.positions.size())
    return Error{"raymarch renderer: " + std::to_string(planes.size()) + " planes for " +
                 std::to_string(mesh.positions.size()) + " vertices; give one (N_S, d) per render vertex"};
  // The fitted planes ride along as the mesh's plane attribute (kPlane, shared with the pipeline).
  MeshArrays withPlanes = mesh;
  withPlanes.planes = planes;
  if (auto r = m_impl->mesh.upload(g, withPlanes); !r) return r;
  m_impl->vertexCount = planes.size();
  return gl::checkGlError(g, "raymarch renderer: mesh upload");
}

Result<void> RayMarchRenderer::updateMesh(std::span<const Float3> positions, std::span<const Float3> normals,
                                          std::span<const Float4> tangents, std::span<const Float4> planes) {
  const gl::GlApi& g = m_impl->gl();
  StateGuard guard(g);
  if (planes.size() != m_impl->vertexCount)
    return Error{"raymarch renderer: updateMesh needs " + std::to_string(m_impl->vertexCount) + " planes"};
  MeshUpdate update;
  update.positions = positions, update.normals = normals, update.tangents = tangents, update.planes = planes;
  if (auto r = m_impl->mesh.update(g, update); !r) return r;
  return gl::checkGlError(g, "raymarch renderer: mesh update");
}

Result<void> RayMarchRenderer::setMaterial(const RayMarchMaterial& material) {
  const std::size_t maps = material.subsurfaceMaps.size();
  if (maps < 1 || maps > 2 || material.layers.size() != 4 * maps + 1 ||
      int(material.layers.size()) > kMaxLayers)
    return Error{"raymarch renderer: " + std::to_string(material.layers.size()) + " layers and " +
                 std::to_string(maps) + " subsurface maps; give 1 or 2 RGBA maps and 4N + 1 layers"};
  const gl::GlApi& g = m_impl->gl();
  StateGuard guard(g);
  for (std::size_t i = 0; i < maps; ++i) {
    g.ActiveTexture(GL_TEXTURE0);
    if (auto r = uploadTexture(g, m_impl->maps[i], material.subsurfaceMaps[i]); !r) return r;
    // Depths are data: no mip-maps (as the CPU model's bilinear lookup), no wrap-around.
    g.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    g.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    g.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  }
  m_impl->material = material;
  m_impl->material.subsurfaceMaps.clear();
  m_impl->material.subsurfaceMaps.resize(maps);  // keep the count only
  m_impl->texelsWide = material.subsurfaceMaps[0].width;
  return gl::checkGlError(g, "raymarch renderer: material upload");
}

Result<Image8> RayMarchRenderer::renderImage(const Camera& camera, std::span<const RayMarchLight> lights,
                                             const RayMarchRenderSettings& s, int width, int height) {
  Impl& m = *m_impl;
  const gl::GlApi& g = m.gl();
  if (m.mesh.empty()) return Error{"raymarch renderer: no mesh; call setMesh first"};
  if (!m.maps[0]) return Error{"raymarch renderer: no material; call setMaterial first"};
  StateGuard guard(g);
  if (auto r = m.offscreen.ensure(g, width, height, 0); !r) return r.error();
  g.BindFramebuffer(GL_FRAMEBUFFER, m.offscreen.drawFramebuffer());
  g.Viewport(0, 0, width, height);
  g.Disable(GL_BLEND);
  g.Disable(GL_SCISSOR_TEST);
  g.Disable(GL_FRAMEBUFFER_SRGB);
  g.Enable(GL_DEPTH_TEST);
  g.DepthFunc(GL_LESS);
  g.DepthMask(GL_TRUE);
  g.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  g.Enable(GL_CULL_FACE);
  g.CullFace(GL_BACK);
  g.FrontFace(GL_CCW);
  g.ClearColor(s.background.x, s.background.y, s.background.z, 1.0f);
  g.ClearDepth(1.0);
  g.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  const gl::Program& program = s.adaptive ? (s.showSamples ? m.adaptiveShow : m.adaptive)
                                          : (s.showSamples ? m.fixedShow : m.fixedCount);
  g.UseProgram(program.id());
  m.setUniforms(program.id(), camera, lights, s, width, height);
  for (int i = 0; i < 2; ++i) {
    g.ActiveTexture(GLenum(GL_TEXTURE0 + i));
    g.BindTexture(GL_TEXTURE_2D, m.maps[i] ? m.maps[i].id() : m.maps[0].id());
  }
  g.Finish();
  Stopwatch draw;
  g.BindVertexArray(m.mesh.vertexArray());
  g.DrawElements(GL_TRIANGLES, m.mesh.indexCount(), GL_UNSIGNED_INT, nullptr);
  g.Finish();  // llvmpipe rasterises lazily: time to completion
  m.drawMs = draw.elapsedMs();
  if (auto r = gl::checkGlError(g, "raymarch renderer: draw"); !r) return r.error();
  return m.offscreen.read(g);
}

double RayMarchRenderer::lastDrawMs() const {
  return m_impl->drawMs;
}

}  // namespace tissue::render
