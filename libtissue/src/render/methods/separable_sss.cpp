#include "separable_sss.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <variant>

#include "tissue/gl/program.h"

namespace tissue::render {
namespace {

bool finite(const Float4& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && std::isfinite(v.w);
}

Result<void> checkSettings(const SeparableSettings& s, float objectId) {
  const std::string where = "renderer: separable object " + std::to_string(static_cast<int>(objectId) - 1);
  if (s.components.empty() || s.components.size() > static_cast<std::size_t>(kMaxKernelComponents)) {
    return Error{where + " has a kernel of " + std::to_string(s.components.size()) + " components; give 1.." +
                 std::to_string(kMaxKernelComponents) + " (the rank, Freude eq. 5.10)"};
  }
  for (std::size_t r = 0; r < s.components.size(); ++r) {
    const SeparableComponent& c = s.components[r];
    const std::string component = where + "'s kernel component " + std::to_string(r);
    if (c.taps.empty() || c.taps.size() > static_cast<std::size_t>(kMaxKernelTaps)) {
      return Error{component + " has " + std::to_string(c.taps.size()) + " taps; give 1.." +
                   std::to_string(kMaxKernelTaps) + " {w_R, w_G, w_B, offset_mm} taps"};
    }
    if (!finite({c.sign.x, c.sign.y, c.sign.z, 0.0f})) return Error{component + " has a non-finite sign"};
    for (const Float4& k : c.taps)
      if (!finite(k)) return Error{component + " has a non-finite tap"};
  }
  if (s.transmittance.size() > static_cast<std::size_t>(kMaxTransmittanceRows)) {
    return Error{where + " has " + std::to_string(s.transmittance.size()) + " transmittance rows; at most " +
                 std::to_string(kMaxTransmittanceRows)};
  }
  for (const Float4& t : s.transmittance)
    if (!finite(t)) return Error{where + " has a non-finite transmittance row"};
  return {};
}

// The follow-surface length (mm) of eq. 4.12; 0 turns it off.
float followSurfaceMm(const SeparableSettings& s) {
  if (!s.followSurface) return 0.0f;
  if (s.followSurfaceMm > 0.0f) return s.followSurfaceMm;
  float widest = 0.0f;
  for (const SeparableComponent& c : s.components)
    for (const Float4& k : c.taps)
      widest = std::max(widest, std::abs(k.w));
  return std::max(widest, 1e-3f);
}

// The kernel table (RGBA32F, kMaxKernelTaps + 1 texels wide). Row `id` (0..objectCount) is the
// object's header (components, followSurfaceMm, first component row, 0), 0 components for id 0
// and non-separable objects; after them one row per component: (sign RGB, taps), then the taps.
struct KernelTable {
  std::vector<Float4> texels;
  int rows = 0;
  int maxComponents = 0;  // the frame's highest rank: the number of blur pass pairs
};

KernelTable kernelTable(const FrameContext& frame, std::span<const ObjectDraw> objects) {
  constexpr int width = kMaxKernelTaps + 1;
  KernelTable t;
  t.rows = frame.objectCount + 1;
  for (const ObjectDraw& d : objects)
    t.rows += static_cast<int>(std::get<SeparableSettings>(d.object->method).components.size());
  t.texels.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(t.rows));
  int next = frame.objectCount + 1;
  for (const ObjectDraw& d : objects) {
    const auto& s = std::get<SeparableSettings>(d.object->method);
    const int count = static_cast<int>(s.components.size());
    t.texels[static_cast<std::size_t>(d.objectId) * width] = {static_cast<float>(count), followSurfaceMm(s),
                                                              static_cast<float>(next), 0.0f};
    for (const SeparableComponent& c : s.components) {
      Float4* row = &t.texels[static_cast<std::size_t>(next++) * width];
      row[0] = {c.sign.x, c.sign.y, c.sign.z, static_cast<float>(c.taps.size())};
      std::copy(c.taps.begin(), c.taps.end(), row + 1);
    }
    t.maxComponents = std::max(t.maxComponents, count);
  }
  return t;
}

// Full-screen pass state: the whole viewport, no depth, blending, culling or scissor.
void setFullScreenState(const FrameContext& frame) {
  const gl::GlApi& g = frame.gl;
  g.Viewport(0, 0, frame.width, frame.height);
  g.Disable(GL_DEPTH_TEST);
  g.Disable(GL_BLEND);
  g.Disable(GL_CULL_FACE);
  g.Disable(GL_SCISSOR_TEST);
  g.DepthMask(GL_FALSE);
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
  gl.Uniform1i(gl.GetUniformLocation(b, "u_coverage"), kUnitMethod0 + 3);
  auto resolve = gl::buildProgram(gl, library, {"post/fullscreen.vert", "separable/resolve.frag", {}});
  if (!resolve) return resolve.error();
  m.m_resolve = std::move(*resolve);
  gl.UseProgram(m.m_resolve.id());
  gl.Uniform1i(gl.GetUniformLocation(m.m_resolve.id(), "u_diffuse"), kUnitMethod0);
  gl.Uniform1i(gl.GetUniformLocation(m.m_resolve.id(), "u_position"), kUnitMethod0 + 1);
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
        frame.passes.issued(d.index());  // PassTiming::issued
      }
    }
    return gl::checkGlError(g, "renderer: separable geometry pass");
  });
}

Result<void> SeparableMethod::resolve(const FrameContext& frame) const {
  return frame.passes.run("separable:resolve", [&]() -> Result<void> {
    const gl::GlApi& g = frame.gl;
    constexpr GLenum buffers[3] = {GL_NONE, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2};
    g.BindFramebuffer(GL_FRAMEBUFFER, frame.targets.resolvedFramebuffer());
    g.DrawBuffers(3, buffers);
    setFullScreenState(frame);
    g.UseProgram(m_resolve.id());
    g.Uniform1i(g.GetUniformLocation(m_resolve.id(), "u_samples"), frame.targets.samples());
    g.ActiveTexture(GL_TEXTURE0 + kUnitMethod0);
    g.BindTexture(GL_TEXTURE_2D_MULTISAMPLE, frame.targets.msaaDiffuse());
    g.ActiveTexture(GL_TEXTURE0 + kUnitMethod0 + 1);
    g.BindTexture(GL_TEXTURE_2D_MULTISAMPLE, frame.targets.msaaPosition());
    drawFullScreen(frame);
    g.BindTexture(GL_TEXTURE_2D_MULTISAMPLE, 0);
    g.ActiveTexture(GL_TEXTURE0 + kUnitMethod0);
    g.BindTexture(GL_TEXTURE_2D_MULTISAMPLE, 0);
    constexpr GLenum all[3] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2};
    g.DrawBuffers(3, all);
    return gl::checkGlError(g, "renderer: separable resolve pass");
  });
}

Result<void> SeparableMethod::post(const FrameContext& frame, std::span<const ObjectDraw> objects) const {
  const gl::GlApi& g = frame.gl;
  const KernelTable table = kernelTable(frame, objects);
  GLint maxSize = 0;
  g.GetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
  if (table.rows > maxSize) {
    return Error{"renderer: the frame's separable kernels need " + std::to_string(table.rows) +
                 " table rows (objects + components), more than this GL's " + std::to_string(maxSize) +
                 "; use fewer objects or lower ranks"};
  }
  const bool multisampled = frame.targets.samples() > 1;
  if (multisampled) {
    if (auto r = resolve(frame); !r) return r;
  }
  const Camera& c = frame.scene.camera;
  const float pixelsPerMm = 0.5f * static_cast<float>(frame.height) /
                            std::tan(0.5f * c.verticalFovDeg * 3.14159265f / 180.0f);  // eq. 4.11 x H/2
  // One 1D pass of component r; the vertical passes of r >= 1 add to the blurred target (RGB
  // only: its alpha keeps the object id), with negative signs in the float target (eq. 5.10).
  auto blur = [&](GLuint input, GLuint target, int component, bool vertical) -> Result<void> {
    g.BindFramebuffer(GL_FRAMEBUFFER, target);
    setFullScreenState(frame);
    if (vertical && component > 0) {
      g.Enable(GL_BLEND);
      g.BlendEquation(GL_FUNC_ADD);
      g.BlendFuncSeparate(GL_ONE, GL_ONE, GL_ZERO, GL_ONE);
    }
    const GLuint b = m_blur.id();
    g.UseProgram(b);
    g.Uniform2f(g.GetUniformLocation(b, "u_direction"), vertical ? 0.0f : 1.0f, vertical ? 1.0f : 0.0f);
    g.Uniform1f(g.GetUniformLocation(b, "u_pixelsPerMmAtUnitDepth"), pixelsPerMm);
    g.Uniform1i(g.GetUniformLocation(b, "u_component"), component);
    g.Uniform1i(g.GetUniformLocation(b, "u_vertical"), vertical ? 1 : 0);
    g.Uniform1i(g.GetUniformLocation(b, "u_coverageWeighted"), multisampled ? 1 : 0);
    g.ActiveTexture(GL_TEXTURE0 + kUnitMethod0);
    g.BindTexture(GL_TEXTURE_2D, input);
    g.ActiveTexture(GL_TEXTURE0 + kUnitMethod0 + 1);
    g.BindTexture(GL_TEXTURE_2D, frame.targets.position());
    g.ActiveTexture(GL_TEXTURE0 + kUnitMethod0 + 2);
    g.BindTexture(GL_TEXTURE_2D, m_kernels.id());
    g.ActiveTexture(GL_TEXTURE0 + kUnitMethod0 + 3);
    g.BindTexture(GL_TEXTURE_2D, frame.targets.radiance());
    drawFullScreen(frame);
    g.Disable(GL_BLEND);
    g.BlendFunc(GL_ONE, GL_ZERO);  // GL's default, for the passes after
    return gl::checkGlError(g, "renderer: separable blur pass");
  };
  // Per component r: "separable:blur-x" then "separable:blur-y" (r = 0), "separable:blur-x:r"
  // and "separable:blur-y:r" after.
  for (int r = 0; r < table.maxComponents; ++r) {
    std::string suffix;
    if (r > 0) suffix = std::to_string(r).insert(0, 1, ':');
    auto x = frame.passes.run("separable:blur-x" + suffix, [&]() -> Result<void> {
      if (r == 0) {
        g.ActiveTexture(GL_TEXTURE0 + kUnitMethod0 + 2);
        g.BindTexture(GL_TEXTURE_2D, m_kernels.id());
        g.BindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
        g.PixelStorei(GL_UNPACK_ALIGNMENT, 4);
        g.PixelStorei(GL_UNPACK_ROW_LENGTH, 0);
        g.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, kMaxKernelTaps + 1, table.rows, 0, GL_RGBA, GL_FLOAT,
                     table.texels.data());
      }
      return blur(frame.targets.diffuse(), frame.targets.blurTempFramebuffer(), r, false);
    });
    if (!x) return x;
    auto y = frame.passes.run("separable:blur-y" + suffix, [&] {
      return blur(frame.targets.blurTemp(), frame.targets.blurredFramebuffer(), r, true);
    });
    if (!y) return y;
  }
  return {};
}

}  // namespace tissue::render
