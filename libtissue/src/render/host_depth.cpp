#include "host_depth.h"

#include <string>

#include "tissue/gl/program.h"

namespace tissue::render {
namespace {

// A sized depth format with its upload format and type, and the attachment point.
struct DepthFormat {
  GLenum internal = 0, format = 0, type = 0, attachment = 0;
};

// The single-sample texture format a depth blit from the host's attachment needs: glBlitFramebuffer
// of GL_DEPTH_BUFFER_BIT wants the same depth and stencil formats on both sides.
Result<DepthFormat> hostDepthFormat(const gl::GlApi& g, GLuint framebuffer) {
  // The default framebuffer names its buffers GL_DEPTH and GL_STENCIL; a framebuffer object
  // names attachment points. Bound to GL_READ_FRAMEBUFFER by the caller.
  const GLenum depth = framebuffer == 0 ? GLenum(GL_DEPTH) : GLenum(GL_DEPTH_ATTACHMENT);
  const GLenum stencil = framebuffer == 0 ? GLenum(GL_STENCIL) : GLenum(GL_STENCIL_ATTACHMENT);
  GLint type = GL_NONE, depthBits = 0, componentType = 0, stencilType = GL_NONE, stencilBits = 0;
  g.GetFramebufferAttachmentParameteriv(GL_READ_FRAMEBUFFER, depth, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE,
                                        &type);
  if (type == GL_NONE) {
    return Error{"renderer: HostDepth::TestAndWrite, but host framebuffer " + std::to_string(framebuffer) +
                 " has no depth buffer"};
  }
  g.GetFramebufferAttachmentParameteriv(GL_READ_FRAMEBUFFER, depth, GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE,
                                        &depthBits);
  g.GetFramebufferAttachmentParameteriv(GL_READ_FRAMEBUFFER, depth, GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE,
                                        &componentType);
  g.GetFramebufferAttachmentParameteriv(GL_READ_FRAMEBUFFER, stencil, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE,
                                        &stencilType);
  if (stencilType != GL_NONE) {
    g.GetFramebufferAttachmentParameteriv(GL_READ_FRAMEBUFFER, stencil,
                                          GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE, &stencilBits);
  }
  if (auto r = gl::checkGlError(g, "renderer: querying the host's depth format"); !r) return r.error();
  const bool withStencil = stencilBits > 0;
  const GLenum at = withStencil ? GLenum(GL_DEPTH_STENCIL_ATTACHMENT) : GLenum(GL_DEPTH_ATTACHMENT);
  if (componentType == GL_FLOAT && depthBits == 32) {
    return withStencil
               ? DepthFormat{GL_DEPTH32F_STENCIL8, GL_DEPTH_STENCIL, GL_FLOAT_32_UNSIGNED_INT_24_8_REV, at}
               : DepthFormat{GL_DEPTH_COMPONENT32F, GL_DEPTH_COMPONENT, GL_FLOAT, at};
  }
  if (componentType != GL_FLOAT && depthBits == 24) {
    return withStencil ? DepthFormat{GL_DEPTH24_STENCIL8, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, at}
                       : DepthFormat{GL_DEPTH_COMPONENT24, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, at};
  }
  if (componentType != GL_FLOAT && !withStencil && (depthBits == 16 || depthBits == 32)) {
    return DepthFormat{depthBits == 16 ? GLenum(GL_DEPTH_COMPONENT16) : GLenum(GL_DEPTH_COMPONENT32),
                       GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, at};
  }
  return Error{"renderer: HostDepth::TestAndWrite: the host's depth buffer has " + std::to_string(depthBits) +
               (componentType == GL_FLOAT ? " float" : " normalised") + " depth bits and " +
               std::to_string(stencilBits) +
               " stencil bits; supported: 16, 24 or 32 normalised (24 also with 8 stencil), 32 float "
               "(with or without 8 stencil)"};
}

}  // namespace

Result<HostDepthPass> HostDepthPass::create(const gl::GlApi& gl, const gl::ShaderLibrary& library) {
  auto fill = gl::buildProgram(gl, library, {"post/fullscreen.vert", "post/host_depth.frag", {}});
  if (!fill) return fill.error();
  HostDepthPass p;
  p.m_fill = std::move(*fill);
  gl.UseProgram(p.m_fill.id());
  gl.Uniform1i(gl.GetUniformLocation(p.m_fill.id(), "u_hostDepth"), kUnitMethod0);
  return p;
}

Result<void> HostDepthPass::load(const FrameContext& frame, GLuint hostFramebuffer, int x, int y) {
  return frame.passes.run("host-depth", [&]() -> Result<void> {
    const gl::GlApi& g = frame.gl;
    // Step 1: a copy target of the host's format, as large as the viewport's far corner (a blit
    // from a multisampled framebuffer must keep its rectangle, so the copy keeps the host's
    // pixel coordinates).
    g.BindFramebuffer(GL_READ_FRAMEBUFFER, hostFramebuffer);
    auto format = hostDepthFormat(g, hostFramebuffer);
    if (!format) return format.error();
    const int w = x + frame.width, h = y + frame.height;
    if (!m_copy || format->internal != m_format || w != m_width || h != m_height) {
      m_format = 0;
      m_copy = gl::Texture::create(g);
      g.ActiveTexture(GL_TEXTURE0 + kUnitMethod0);
      g.BindTexture(GL_TEXTURE_2D, m_copy.id());
      g.BindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
      g.TexImage2D(GL_TEXTURE_2D, 0, GLint(format->internal), w, h, 0, format->format, format->type, nullptr);
      g.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);  // complete without mip-maps
      g.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
      g.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_NONE);
      // Bound to both targets: glDrawBuffer and glReadBuffer must reach this framebuffer, not
      // the host's.
      m_copyFramebuffer = gl::Framebuffer::create(g);
      g.BindFramebuffer(GL_FRAMEBUFFER, m_copyFramebuffer.id());
      g.FramebufferTexture2D(GL_FRAMEBUFFER, format->attachment, GL_TEXTURE_2D, m_copy.id(), 0);
      g.DrawBuffer(GL_NONE);  // depth only (GL 3.3 wants no draw buffer without a colour attachment)
      g.ReadBuffer(GL_NONE);
      if (g.CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        return Error{"renderer: the host-depth copy framebuffer is incomplete"};
      m_format = format->internal, m_width = w, m_height = h;
      g.BindFramebuffer(GL_READ_FRAMEBUFFER, hostFramebuffer);
    }
    // Step 2: the blit (scissor off: it would clip the blit; the depth mask does not apply to
    // blits but is set anyway for drivers that disagree).
    g.BindFramebuffer(GL_DRAW_FRAMEBUFFER, m_copyFramebuffer.id());
    g.Disable(GL_SCISSOR_TEST);
    g.DepthMask(GL_TRUE);
    g.BlitFramebuffer(x, y, w, h, x, y, w, h, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
    if (auto r = gl::checkGlError(g, "renderer: blit of the host's depth"); !r) return r;
    // Step 3: the copy into the geometry depth: depth only, every pixel (GL_ALWAYS).
    g.BindFramebuffer(GL_FRAMEBUFFER, frame.targets.geometryFramebuffer());
    g.Viewport(0, 0, frame.width, frame.height);
    g.Disable(GL_BLEND);
    g.Disable(GL_CULL_FACE);
    g.Enable(GL_DEPTH_TEST);
    g.DepthFunc(GL_ALWAYS);
    g.ColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    g.UseProgram(m_fill.id());
    g.Uniform2i(g.GetUniformLocation(m_fill.id(), "u_origin"), x, y);
    g.ActiveTexture(GL_TEXTURE0 + kUnitMethod0);
    g.BindTexture(GL_TEXTURE_2D, m_copy.id());
    drawFullScreen(frame);
    g.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    g.DepthFunc(GL_LESS);
    return gl::checkGlError(g, "renderer: host-depth pass");
  });
}

}  // namespace tissue::render
