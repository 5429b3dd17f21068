// The renderer core: one lit pass (Blinn-Phong through a tangent-space normal map) into the
// offscreen target or a host framebuffer, each pass timed on the CPU and with GL timer queries.
#include "tissue/render/renderer.h"

#include <glm/gtc/type_ptr.hpp>

#include "camera_math.h"
#include "mesh_buffers.h"
#include "offscreen_target.h"
#include "state_guard.h"
#include "textures.h"
#include "tissue/core/stopwatch.h"
#include "tissue/gl/program.h"

namespace tissue::render {
namespace {

// Tissue-like default base colour (sRGB) and a flat normal (0, 0, 1) as RGB.
constexpr std::uint8_t kDefaultBase[3] = {196, 112, 104};
constexpr std::uint8_t kFlatNormal[3] = {128, 128, 255};

// A GL_TIME_ELAPSED query around one pass; finishMs() waits for the GPU. A result longer than
// the wall-clock time since the begin is impossible and reported as -1: llvmpipe (Mesa 22.3)
// returns the time since boot for the first query on a newly created framebuffer.
class PassTimer {
 public:
  PassTimer(const gl::GlApi& gl, const gl::Query& query, bool enabled)
      : m_gl(gl), m_query(query), m_on(enabled) {
    if (m_on) m_gl.BeginQuery(GL_TIME_ELAPSED, m_query.id());
  }
  double finishMs() {
    if (!m_on) return -1.0;
    m_gl.EndQuery(GL_TIME_ELAPSED);
    m_on = false;
    GLuint64 ns = 0;
    m_gl.GetQueryObjectui64v(m_query.id(), GL_QUERY_RESULT, &ns);
    const double ms = static_cast<double>(ns) * 1e-6;
    return ms <= m_wall.elapsedMs() ? ms : -1.0;
  }
  ~PassTimer() {
    if (m_on) m_gl.EndQuery(GL_TIME_ELAPSED);
  }

 private:
  const gl::GlApi& m_gl;
  const gl::Query& m_query;
  bool m_on;
  Stopwatch m_wall;
};

// Uniform locations of one lit-program variant.
struct LitProgram {
  gl::Program program;
  GLint viewProjection = -1, cameraPosition = -1, lightPosition = -1, lightRadiance = -1, ambient = -1,
        specular = -1, shininess = -1, exposure = -1;
};

Result<LitProgram> buildLit(const gl::GlApi& gl, const gl::ShaderLibrary& library, bool normalMap) {
  const gl::ShaderDefine defines[] = {{"TISSUE_NORMAL_MAP", "1"}};
  auto program = gl::buildProgram(
      gl, library,
      {"lit.vert", "lit.frag", normalMap ? std::span(defines) : std::span<const gl::ShaderDefine>()});
  if (!program) return program.error();
  LitProgram lit;
  lit.program = std::move(*program);
  const GLuint id = lit.program.id();
  lit.viewProjection = gl.GetUniformLocation(id, "u_viewProjection");
  lit.cameraPosition = gl.GetUniformLocation(id, "u_cameraPosition");
  lit.lightPosition = gl.GetUniformLocation(id, "u_lightPosition");
  lit.lightRadiance = gl.GetUniformLocation(id, "u_lightRadiance");
  lit.ambient = gl.GetUniformLocation(id, "u_ambient");
  lit.specular = gl.GetUniformLocation(id, "u_specular");
  lit.shininess = gl.GetUniformLocation(id, "u_shininess");
  lit.exposure = gl.GetUniformLocation(id, "u_exposure");
  // Samplers never change: base colour on unit 0, normal map on unit 1.
  gl.UseProgram(id);
  gl.Uniform1i(gl.GetUniformLocation(id, "u_baseColor"), 0);
  gl.Uniform1i(gl.GetUniformLocation(id, "u_normalMap"), 1);
  return lit;
}

}  // namespace

struct Renderer::Impl {
  std::shared_ptr<const gl::GlApi> api;
  RendererSettings settings;
  LitProgram litFlat, litMapped;
  MeshBuffers mesh;
  gl::Texture baseColor, normalMap;
  bool normalMapping = false;
  OffscreenTarget offscreen;
  gl::Query drawQuery, resolveQuery;
  RenderTimings timings;

  const gl::GlApi& gl() const { return *api; }

  // The lit pass into whatever framebuffer and viewport are bound (state set, not restored).
  Result<void> drawLit(const Scene& scene, int width, int height, bool clear) {
    const gl::GlApi& g = gl();
    if (mesh.empty()) return Error{"renderer: no mesh; call setMesh first"};
    const LitProgram& lit = normalMapping ? litMapped : litFlat;
    g.Disable(GL_BLEND);
    g.Disable(GL_SCISSOR_TEST);
    g.Disable(GL_FRAMEBUFFER_SRGB);  // the shader encodes sRGB itself
    g.Enable(GL_DEPTH_TEST);
    g.DepthFunc(GL_LESS);
    g.DepthMask(GL_TRUE);
    g.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    g.Enable(GL_CULL_FACE);
    g.CullFace(GL_BACK);
    g.FrontFace(GL_CCW);
    if (settings.samples > 1) g.Enable(GL_MULTISAMPLE);
    if (clear) {
      g.ClearColor(scene.background.x, scene.background.y, scene.background.z, 1.0f);
      g.ClearDepth(1.0);
      g.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    }
    // Uniforms: camera, light and material.
    g.UseProgram(lit.program.id());
    const float aspect = static_cast<float>(width) / static_cast<float>(height);
    const glm::mat4 vp = viewProjection(scene.camera, aspect);
    g.UniformMatrix4fv(lit.viewProjection, 1, GL_FALSE, glm::value_ptr(vp));
    const Camera& c = scene.camera;
    const PointLight& l = scene.light;
    const Material& m = scene.material;
    g.Uniform3f(lit.cameraPosition, c.eye.x, c.eye.y, c.eye.z);
    g.Uniform3f(lit.lightPosition, l.positionMm.x, l.positionMm.y, l.positionMm.z);
    g.Uniform3f(lit.lightRadiance, l.color.x * l.intensity, l.color.y * l.intensity, l.color.z * l.intensity);
    g.Uniform3f(lit.ambient, m.ambient.x, m.ambient.y, m.ambient.z);
    g.Uniform1f(lit.specular, m.specular);
    g.Uniform1f(lit.shininess, m.shininess);
    g.Uniform1f(lit.exposure, m.exposure);
    g.ActiveTexture(GL_TEXTURE0);
    g.BindTexture(GL_TEXTURE_2D, baseColor.id());
    g.ActiveTexture(GL_TEXTURE1);
    g.BindTexture(GL_TEXTURE_2D, normalMap.id());
    // Draw.
    g.BindVertexArray(mesh.vertexArray());
    g.DrawElements(GL_TRIANGLES, mesh.indexCount(), GL_UNSIGNED_INT, nullptr);
    return gl::checkGlError(g, "renderer: lit pass");
  }
};

Renderer::Renderer(std::unique_ptr<Impl> impl) : m_impl(std::move(impl)) {}
Renderer::Renderer(Renderer&&) noexcept = default;
Renderer& Renderer::operator=(Renderer&&) noexcept = default;
Renderer::~Renderer() = default;

Result<Renderer> Renderer::create(const gl::GetProcAddressFn& getProcAddress,
                                  const RendererSettings& settings) {
  auto api = gl::loadGl(getProcAddress);
  if (!api) return Error{"renderer: " + api.error().message};
  auto impl = std::make_unique<Impl>();
  impl->api = std::move(*api);
  impl->settings = settings;
  const gl::GlApi& g = impl->gl();
  StateGuard guard(g);
  // Step 1: both shader variants (vertex normals; normal-mapped).
  const gl::ShaderLibrary library(settings.shaders);
  auto flat = buildLit(g, library, false);
  if (!flat) return flat.error();
  auto mapped = buildLit(g, library, true);
  if (!mapped) return mapped.error();
  impl->litFlat = std::move(*flat);
  impl->litMapped = std::move(*mapped);
  // Step 2: default textures and timer queries.
  g.ActiveTexture(GL_TEXTURE0);
  if (auto r = uploadSolidTexture(g, impl->baseColor, kDefaultBase[0], kDefaultBase[1], kDefaultBase[2]);
      !r) {
    return r.error();
  }
  if (auto r = uploadSolidTexture(g, impl->normalMap, kFlatNormal[0], kFlatNormal[1], kFlatNormal[2]); !r) {
    return r.error();
  }
  impl->drawQuery = gl::Query::create(g);
  impl->resolveQuery = gl::Query::create(g);
  if (auto r = gl::checkGlError(g, "renderer: create"); !r) return r.error();
  return Renderer(std::move(impl));
}

Result<void> Renderer::setMesh(const MeshArrays& mesh) {
  StateGuard guard(m_impl->gl());
  Stopwatch watch;
  auto r = m_impl->mesh.upload(m_impl->gl(), mesh);
  m_impl->timings.uploadCpuMs = watch.elapsedMs();
  return r;
}

Result<void> Renderer::updateMesh(std::span<const Float3> positions, std::span<const Float3> normals,
                                  std::span<const Float4> tangents) {
  StateGuard guard(m_impl->gl());
  Stopwatch watch;
  auto r = m_impl->mesh.update(m_impl->gl(), positions, normals, tangents);
  m_impl->timings.uploadCpuMs = watch.elapsedMs();
  return r;
}

Result<void> Renderer::setBaseColor(const Image8& image) {
  StateGuard guard(m_impl->gl());
  m_impl->gl().ActiveTexture(GL_TEXTURE0);
  return uploadTexture(m_impl->gl(), m_impl->baseColor, image);
}

Result<void> Renderer::setNormalMap(const Image8& image) {
  StateGuard guard(m_impl->gl());
  m_impl->gl().ActiveTexture(GL_TEXTURE0);
  auto r = uploadTexture(m_impl->gl(), m_impl->normalMap, image);
  if (r) m_impl->normalMapping = true;
  return r;
}

void Renderer::setNormalMapping(bool enabled) {
  m_impl->normalMapping = enabled;
}

Result<Image8> Renderer::renderImage(const Scene& scene, int width, int height) {
  Impl& s = *m_impl;
  const gl::GlApi& g = s.gl();
  StateGuard guard(g);
  Stopwatch total;
  if (auto r = s.offscreen.ensure(g, width, height, s.settings.samples); !r) return r.error();
  // Pass 1: lit.
  g.BindFramebuffer(GL_FRAMEBUFFER, s.offscreen.drawFramebuffer());
  g.Viewport(0, 0, width, height);
  Stopwatch draw;
  PassTimer drawTimer(g, s.drawQuery, s.settings.gpuTimers);
  if (auto r = s.drawLit(scene, width, height, true); !r) return r.error();
  s.timings.drawCpuMs = draw.elapsedMs();
  s.timings.drawGpuMs = drawTimer.finishMs();
  // Pass 2: resolve and read back.
  Stopwatch readback;
  PassTimer resolveTimer(g, s.resolveQuery, s.settings.gpuTimers);
  auto image = s.offscreen.read(g);
  s.timings.resolveGpuMs = resolveTimer.finishMs();
  s.timings.readbackCpuMs = readback.elapsedMs();
  s.timings.totalCpuMs = total.elapsedMs();
  return image;
}

Result<void> Renderer::renderTo(const Scene& scene, const HostFramebuffer& target) {
  Impl& s = *m_impl;
  const gl::GlApi& g = s.gl();
  if (target.width <= 0 || target.height <= 0) return Error{"renderer: host viewport has no area"};
  StateGuard guard(g);
  Stopwatch total;
  g.BindFramebuffer(GL_FRAMEBUFFER, target.framebuffer);
  if (g.CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    return Error{"renderer: host framebuffer " + std::to_string(target.framebuffer) + " is incomplete"};
  }
  g.Viewport(target.x, target.y, target.width, target.height);
  if (target.clear) {  // clear only the viewport, not the host's whole framebuffer
    g.Enable(GL_SCISSOR_TEST);
    g.Scissor(target.x, target.y, target.width, target.height);
  }
  Stopwatch draw;
  PassTimer drawTimer(g, s.drawQuery, s.settings.gpuTimers);
  if (target.clear) {
    g.ClearColor(scene.background.x, scene.background.y, scene.background.z, 1.0f);
    g.ClearDepth(1.0);
    g.DepthMask(GL_TRUE);
    g.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    g.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  }
  if (auto r = s.drawLit(scene, target.width, target.height, false); !r) return r.error();
  s.timings.drawCpuMs = draw.elapsedMs();
  s.timings.drawGpuMs = drawTimer.finishMs();
  s.timings.resolveGpuMs = -1.0;
  s.timings.readbackCpuMs = 0.0;
  s.timings.totalCpuMs = total.elapsedMs();
  return {};
}

const RenderTimings& Renderer::lastTimings() const {
  return m_impl->timings;
}

}  // namespace tissue::render
