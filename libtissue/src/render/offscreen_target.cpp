#include "offscreen_target.h"

#include <algorithm>
#include <string>

namespace tissue::render {
namespace {

Result<void> attach(const gl::GlApi& gl, gl::Framebuffer& fb, gl::Renderbuffer& color,
                    gl::Renderbuffer& depth, int width, int height, int samples) {
  fb = gl::Framebuffer::create(gl);
  color = gl::Renderbuffer::create(gl);
  depth = gl::Renderbuffer::create(gl);
  gl.BindRenderbuffer(GL_RENDERBUFFER, color.id());
  gl.RenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_RGBA8, width, height);
  gl.BindRenderbuffer(GL_RENDERBUFFER, depth.id());
  gl.RenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_DEPTH_COMPONENT24, width, height);
  gl.BindFramebuffer(GL_FRAMEBUFFER, fb.id());
  gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color.id());
  gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth.id());
  const GLenum status = gl.CheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    return Error{"renderer: offscreen framebuffer " + std::to_string(width) + "x" + std::to_string(height) +
                 " (" + std::to_string(samples) + " samples) is incomplete, status " +
                 std::to_string(status)};
  }
  return gl::checkGlError(gl, "renderer: offscreen framebuffer");
}

}  // namespace

Result<void> OffscreenTarget::ensure(const gl::GlApi& gl, int width, int height, int samples) {
  GLint maxSize = 0, maxSamples = 0;
  gl.GetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &maxSize);
  gl.GetIntegerv(GL_MAX_SAMPLES, &maxSamples);
  if (width <= 0 || height <= 0 || width > maxSize || height > maxSize) {
    return Error{"renderer: image size " + std::to_string(width) + "x" + std::to_string(height) +
                 " is outside 1.." + std::to_string(maxSize) + " pixels"};
  }
  samples = samples > 1 ? std::min(samples, static_cast<int>(maxSamples)) : 0;
  if (width == m_width && height == m_height && samples == m_samples) return {};
  m_width = m_height = 0;
  if (auto r = attach(gl, m_framebuffer, m_color, m_depth, width, height, 0); !r) return r;
  if (samples > 1) {
    if (auto r = attach(gl, m_msaaFramebuffer, m_msaaColor, m_msaaDepth, width, height, samples); !r)
      return r;
  } else {
    m_msaaFramebuffer.reset();
    m_msaaColor.reset();
    m_msaaDepth.reset();
  }
  m_width = width;
  m_height = height;
  m_samples = samples;
  return {};
}

Result<Image8> OffscreenTarget::read(const gl::GlApi& gl) const {
  if (m_samples > 1) {
    gl.BindFramebuffer(GL_READ_FRAMEBUFFER, m_msaaFramebuffer.id());
    gl.BindFramebuffer(GL_DRAW_FRAMEBUFFER, m_framebuffer.id());
    gl.BlitFramebuffer(0, 0, m_width, m_height, 0, 0, m_width, m_height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  }
  Image8 image(m_width, m_height, 4);
  gl.BindFramebuffer(GL_READ_FRAMEBUFFER, m_framebuffer.id());
  gl.BindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  gl.PixelStorei(GL_PACK_ALIGNMENT, 4);  // RGBA8 rows are always 4-byte aligned
  gl.ReadPixels(0, 0, m_width, m_height, GL_RGBA, GL_UNSIGNED_BYTE, image.pixels.data());
  if (auto r = gl::checkGlError(gl, "renderer: readback"); !r) return r.error();
  flipVertically(image);  // GL rows run bottom-up
  return image;
}

}  // namespace tissue::render
