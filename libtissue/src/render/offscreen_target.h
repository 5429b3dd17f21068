#pragma once
// The renderer's own framebuffer: RGBA8 colour and 24-bit depth renderbuffers, optionally
// multisampled and then resolved (blitted) into a single-sample framebuffer for readback.
#include "tissue/core/image.h"
#include "tissue/core/result.h"
#include "tissue/gl/objects.h"

namespace tissue::render {

class OffscreenTarget {
 public:
  /// (Re)allocates for `width` x `height` pixels and `samples` (0/1: none, clamped to GL_MAX_SAMPLES).
  Result<void> ensure(const gl::GlApi& gl, int width, int height, int samples);
  /// The framebuffer to draw into.
  GLuint drawFramebuffer() const { return m_samples > 1 ? m_msaaFramebuffer.id() : m_framebuffer.id(); }
  /// Resolves MSAA (if any) and reads the colour back, rows top to bottom.
  Result<Image8> read(const gl::GlApi& gl) const;

 private:
  int m_width = 0, m_height = 0, m_samples = -1;
  gl::Framebuffer m_framebuffer, m_msaaFramebuffer;
  gl::Renderbuffer m_color, m_depth, m_msaaColor, m_msaaDepth;
};

}  // namespace tissue::render
