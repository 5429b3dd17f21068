#pragma once
// HostDepth::TestAndWrite, the reading half: the host's depth buffer into the renderer's depth
// buffer before the geometry passes, so that the tissue is depth-tested against what the host
// drew. The default framebuffer's depth can only be read by glBlitFramebuffer, and a blit of
// depth needs matching formats: the host's depth and stencil sizes are queried
// (glGetFramebufferAttachmentParameteriv) and a single-sample depth texture of that format
// receives the blit. A multisampled geometry target cannot be blitted into from a single-sample
// one, so a full-screen pass writes gl_FragDepth from that texture into the geometry depth,
// which works with MSAA on and off (post/host_depth.frag). No read-back, no glFinish.
// The writing half is the tone map's (PostPasses::tonemap with writeDepth).
#include "methods/frame_context.h"

namespace tissue::render {

class HostDepthPass {
 public:
  static Result<HostDepthPass> create(const gl::GlApi& gl, const gl::ShaderLibrary& library);
  /// The "host-depth" pass: copies the depth of `hostFramebuffer` in the viewport at (x, y) of
  /// the frame's size and writes it into the frame's geometry depth. Errors: no depth
  /// attachment, or a depth format without a matching texture format.
  Result<void> load(const FrameContext& frame, GLuint hostFramebuffer, int x, int y);

 private:
  gl::Program m_fill;
  gl::Texture m_copy;  // single-sample, the host's depth format, (x + width) x (y + height)
  gl::Framebuffer m_copyFramebuffer;
  GLenum m_format = 0;
  int m_width = 0, m_height = 0;
};

}  // namespace tissue::render
