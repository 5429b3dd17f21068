#include "separable_sss.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "tissue/gl/program.h"

namespace tissue::render {
namespace {

bool finite(const Float4& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && std::isfinite(v.w);
}

Result<void> checkSettings(const SeparableSettings& s, float objectId) {
  const std::string where = "renderer: separable object " + std::to_string(static_cast<int>(objectId) - 1);
  if (s.kernel.empty() || s.kernel.size() > static_cast<std::size_t>(kMaxKernelTaps)) {
    return Error{where + " has a kernel of " + std::to_string(s.kernel.size()) + " taps; give 1.." +
                 std::to_string(kMaxKernelTaps) + " {w_R, w_G, w_B, offset_mm} taps"};
  }
  if (s.transmittance.size() > static_cast<std::size_t>(kMaxTransmittanceRows)) {
    return Error{where + " has " + std::to_string(s.transmittance.size()) + " transmittance rows; at most " +
                 std::to_string(kMaxTransmittanceRows)};
  }
  for (const Float4& k : s.kernel)
    if (!finite(k)) return Error{where + " has a non-finite kernel tap"};
  for (const Float4& t : s.transmittance)
    if (!finite(t)) return Error{where + " has a non-finite transmittance row"};
  return {};
}

// The follow-surface length (mm) of eq. 4.12; 0 turns it off.
float followSurfaceMm(const SeparableSettings& s) {
  if (!s.followSurface) return 0.0f;
  if (s.followSurfaceMm > 0.0f) return s.followSurfaceMm;
  float widest = 0.0f;
  for (const Float4& k : s.kernel)
    widest = std::max(widest, std::abs(k.w));
  return std::max(widest, 1e-3f);
}

}  // namespace

Result<SeparableMethod> SeparableMethod::create(const gl::GlApi& gl, const gl::ShaderLibrary& library) {
  SeparableMethod m;
  auto geometry = buildSurfacePrograms(gl, library, "separable/geometry.frag");
  if (!geometry) return geometry.error();
  m.m_geometry = std::move(*geometry);
  auto blur = gl::buildProgram(gl, library, {"post/fullscreen.vert", "separable/blur.frag", {}});
  if (!blur) return blur.error();
  m.m_blur = std::move(*blur);
  const GLuint b = m.m_blur.id();
  gl.UseProgram(b);
  gl.Uniform1i(gl.GetUniformLocation(b, "u_input"), kUnitMethod0);
  gl.Uniform1i(gl.GetUniformLocation(b, "u_position"), kUnitMethod0 + 1);
  gl.Uniform1i(gl.GetUniformLocation(b, "u_kernels"), kUnitMethod0 + 2);
  m.m_kernels = gl::Texture::create(gl);
  gl.BindTexture(GL_TEXTURE_2D, m.m_kernels.id());
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  gl.BindTexture(GL_TEXTURE_2D, 0);
  return m;
}

Result<void> SeparableMethod::draw(const FrameContext& frame, std::span<const ObjectDraw> objects) const {
  for (const ObjectDraw& d : objects) {
    if (auto r = checkSettings(std::get<SeparableSettings>(d.object->method), d.objectId); !r) return r;
  }
  return frame.passes.run("separable:geometry", [&]() -> Result<void> {
    const gl::GlApi& g = frame.gl;
    beginGeometryPass(frame);
    for (const GLuint program : {m_geometry.flat.id(), m_geometry.mapped.id()}) {
      bool framed = false;
      for (const ObjectDraw& d : objects) {
        if (m_geometry.pick(d) != program) continue;
        if (!framed) setFrameUniforms(frame, program);
        framed = true;
        const auto& s = std::get<SeparableSettings>(d.object->method);
        g.Uniform1i(g.GetUniformLocation(program, "u_transmittanceRows"),
                    static_cast<GLint>(s.transmittance.size()));
        if (!s.transmittance.empty()) {
          g.Uniform4fv(g.GetUniformLocation(program, "u_transmittance"),
                       static_cast<GLsizei>(s.transmittance.size()), &s.transmittance[0].x);
        }
        g.Uniform1f(g.GetUniformLocation(program, "u_transmissionShrinkMm"), s.transmissionShrinkMm);
        drawSurface(frame, program, d);
      }
    }
    return gl::checkGlError(g, "renderer: separable geometry pass");
  });
}

Result<void> SeparableMethod::post(const FrameContext& frame, std::span<const ObjectDraw> objects) const {
  const gl::GlApi& g = frame.gl;
  // One kernel row per object id (row 0 and non-separable objects: 0 taps, left unblurred).
  const int width = kMaxKernelTaps + 1, rows = frame.objectCount + 1;
  std::vector<Float4> table(static_cast<std::size_t>(width) * rows);
  for (const ObjectDraw& d : objects) {
    const auto& s = std::get<SeparableSettings>(d.object->method);
    Float4* row = &table[static_cast<std::size_t>(d.objectId) * width];
    row[0] = {static_cast<float>(s.kernel.size()), followSurfaceMm(s), 0.0f, 0.0f};
    std::copy(s.kernel.begin(), s.kernel.end(), row + 1);
  }
  const Camera& c = frame.scene.camera;
  const float pixelsPerMm = 0.5f * static_cast<float>(frame.height) /
                            std::tan(0.5f * c.verticalFovDeg * 3.14159265f / 180.0f);  // eq. 4.11 x H/2
  auto blur = [&](GLuint input, GLuint target, float dx, float dy) -> Result<void> {
    g.BindFramebuffer(GL_FRAMEBUFFER, target);
    g.Viewport(0, 0, frame.width, frame.height);
    g.Disable(GL_DEPTH_TEST);
    g.Disable(GL_BLEND);
    g.Disable(GL_CULL_FACE);
    g.Disable(GL_SCISSOR_TEST);
    g.DepthMask(GL_FALSE);
    g.UseProgram(m_blur.id());
    g.Uniform2f(g.GetUniformLocation(m_blur.id(), "u_direction"), dx, dy);
    g.Uniform1f(g.GetUniformLocation(m_blur.id(), "u_pixelsPerMmAtUnitDepth"), pixelsPerMm);
    g.ActiveTexture(GL_TEXTURE0 + kUnitMethod0);
    g.BindTexture(GL_TEXTURE_2D, input);
    g.ActiveTexture(GL_TEXTURE0 + kUnitMethod0 + 1);
    g.BindTexture(GL_TEXTURE_2D, frame.targets.position());
    g.ActiveTexture(GL_TEXTURE0 + kUnitMethod0 + 2);
    g.BindTexture(GL_TEXTURE_2D, m_kernels.id());
    drawFullScreen(frame);
    return gl::checkGlError(g, "renderer: separable blur pass");
  };
  auto r = frame.passes.run("separable:blur-x", [&]() -> Result<void> {
    g.ActiveTexture(GL_TEXTURE0 + kUnitMethod0 + 2);
    g.BindTexture(GL_TEXTURE_2D, m_kernels.id());
    g.BindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    g.PixelStorei(GL_UNPACK_ALIGNMENT, 4);
    g.PixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    g.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, width, rows, 0, GL_RGBA, GL_FLOAT, table.data());
    return blur(frame.targets.diffuse(), frame.targets.blurTempFramebuffer(), 1.0f, 0.0f);
  });
  if (!r) return r;
  return frame.passes.run("separable:blur-y", [&] {
    return blur(frame.targets.blurTemp(), frame.targets.blurredFramebuffer(), 0.0f, 1.0f);
  });
}

}  // namespace tissue::render
