#include "post_passes.h"

#include "tissue/gl/program.h"

namespace tissue::render {
namespace {

// Full-screen passes write colour only, over everything.
void fullScreenState(const gl::GlApi& g) {
  g.Disable(GL_DEPTH_TEST);
  g.Disable(GL_BLEND);
  g.Disable(GL_CULL_FACE);
  g.Disable(GL_FRAMEBUFFER_SRGB);
  g.DepthMask(GL_FALSE);
  g.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

}  // namespace

Result<PostPasses> PostPasses::create(const gl::GlApi& gl, const gl::ShaderLibrary& library) {
  PostPasses p;
  auto composite = gl::buildProgram(gl, library, {"post/fullscreen.vert", "post/composite.frag", {}});
  if (!composite) return composite.error();
  auto tonemap = gl::buildProgram(gl, library, {"post/fullscreen.vert", "post/tonemap.frag", {}});
  if (!tonemap) return tonemap.error();
  p.m_composite = std::move(*composite);
  p.m_tonemap = std::move(*tonemap);
  for (int ms = 0; ms < 2; ++ms) {
    const gl::ShaderDefine single[] = {{"TISSUE_WRITE_DEPTH", "1"}};
    const gl::ShaderDefine multi[] = {{"TISSUE_WRITE_DEPTH", "1"}, {"TISSUE_DEPTH_MS", "1"}};
    auto program = gl::buildProgram(gl, library,
                                    {"post/fullscreen.vert", "post/tonemap.frag",
                                     ms ? std::span<const gl::ShaderDefine>(multi) : std::span(single)});
    if (!program) return program.error();
    const GLuint id = program->id();
    gl.UseProgram(id);
    gl.Uniform1i(gl.GetUniformLocation(id, "u_composite"), kUnitMethod0);
    gl.Uniform1i(gl.GetUniformLocation(id, "u_depth"), kUnitMethod0 + 1);
    p.m_tonemapDepth[ms] = std::move(*program);
  }
  gl.UseProgram(p.m_composite.id());
  gl.Uniform1i(gl.GetUniformLocation(p.m_composite.id(), "u_radiance"), kUnitMethod0);
  gl.Uniform1i(gl.GetUniformLocation(p.m_composite.id(), "u_blurredDiffuse"), kUnitMethod0 + 1);
  gl.UseProgram(p.m_tonemap.id());
  gl.Uniform1i(gl.GetUniformLocation(p.m_tonemap.id(), "u_composite"), kUnitMethod0);
  return p;
}

Result<void> PostPasses::composite(const FrameContext& frame) const {
  return frame.passes.run("composite", [&]() -> Result<void> {
    const gl::GlApi& g = frame.gl;
    g.BindFramebuffer(GL_FRAMEBUFFER, frame.targets.compositeFramebuffer());
    g.Viewport(0, 0, frame.width, frame.height);
    g.Disable(GL_SCISSOR_TEST);
    fullScreenState(g);
    g.UseProgram(m_composite.id());
    g.Uniform2i(g.GetUniformLocation(m_composite.id(), "u_origin"), 0, 0);
    g.ActiveTexture(GL_TEXTURE0 + kUnitMethod0);
    g.BindTexture(GL_TEXTURE_2D, frame.targets.radiance());
    g.ActiveTexture(GL_TEXTURE0 + kUnitMethod0 + 1);
    g.BindTexture(GL_TEXTURE_2D, frame.targets.blurred());
    drawFullScreen(frame);
    return gl::checkGlError(g, "renderer: composite pass");
  });
}

Result<void> PostPasses::tonemap(const FrameContext& frame, GLuint framebuffer, int x, int y,
                                 bool writeBackground, bool writeDepth) const {
  return frame.passes.run("tonemap", [&]() -> Result<void> {
    const gl::GlApi& g = frame.gl;
    g.BindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    g.Viewport(x, y, frame.width, frame.height);
    g.Disable(GL_SCISSOR_TEST);
    g.Disable(GL_MULTISAMPLE);
    fullScreenState(g);
    const bool multisampled = frame.targets.samples() > 1;
    const GLuint p = writeDepth ? m_tonemapDepth[multisampled ? 1 : 0].id() : m_tonemap.id();
    g.UseProgram(p);
    if (writeDepth) {
      // gl_FragDepth reaches the depth buffer only with the depth test on: GL_ALWAYS.
      writeBackground = false;
      g.Enable(GL_DEPTH_TEST);
      g.DepthFunc(GL_ALWAYS);
      g.DepthMask(GL_TRUE);
      g.Uniform1i(g.GetUniformLocation(p, "u_depthSamples"), frame.targets.samples());
      g.ActiveTexture(GL_TEXTURE0 + kUnitMethod0 + 1);
      if (multisampled) {
        g.BindTexture(GL_TEXTURE_2D_MULTISAMPLE, frame.targets.msaaDepth());
      } else {
        g.BindTexture(GL_TEXTURE_2D, frame.targets.depth());
      }
    }
    const Float3 bg = frame.scene.background;
    g.Uniform1f(g.GetUniformLocation(p, "u_exposure"), frame.scene.exposure);
    g.Uniform3f(g.GetUniformLocation(p, "u_background"), bg.x, bg.y, bg.z);
    g.Uniform1i(g.GetUniformLocation(p, "u_writeBackground"), writeBackground ? 1 : 0);
    g.Uniform2i(g.GetUniformLocation(p, "u_origin"), x, y);
    g.ActiveTexture(GL_TEXTURE0 + kUnitMethod0);
    g.BindTexture(GL_TEXTURE_2D, frame.targets.composite());
    drawFullScreen(frame);
    if (writeDepth) {
      g.Disable(GL_DEPTH_TEST);
      g.DepthMask(GL_FALSE);
    }
    return gl::checkGlError(g, "renderer: tonemap pass");
  });
}

}  // namespace tissue::render
