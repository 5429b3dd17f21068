#include "frame_targets.h"

#include <algorithm>
#include <string>

namespace tissue::render {
namespace {

constexpr GLenum kGeometryBuffers[3] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2};

void makeTexture(const gl::GlApi& gl, gl::Texture& t, GLint format, int w, int h) {
  t = gl::Texture::create(gl);
  gl.BindTexture(GL_TEXTURE_2D, t.id());
  gl.TexImage2D(GL_TEXTURE_2D, 0, format, w, h, 0, GL_RGBA, GL_FLOAT, nullptr);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

// A multisampled texture (fixed sample locations, as mixing with renderbuffers would require).
void makeMultisampleTexture(const gl::GlApi& gl, gl::Texture& t, GLenum format, int w, int h, int samples) {
  t = gl::Texture::create(gl);
  gl.BindTexture(GL_TEXTURE_2D_MULTISAMPLE, t.id());
  gl.TexImage2DMultisample(GL_TEXTURE_2D_MULTISAMPLE, samples, format, w, h, GL_TRUE);
  gl.BindTexture(GL_TEXTURE_2D_MULTISAMPLE, 0);
}

void makeRenderbuffer(const gl::GlApi& gl, gl::Renderbuffer& rb, GLenum format, int w, int h, int samples) {
  rb = gl::Renderbuffer::create(gl);
  gl.BindRenderbuffer(GL_RENDERBUFFER, rb.id());
  gl.RenderbufferStorageMultisample(GL_RENDERBUFFER, samples, format, w, h);
}

Result<void> complete(const gl::GlApi& gl, const char* what) {
  const GLenum status = gl.CheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    return Error{std::string("renderer: the ") + what + " framebuffer is incomplete (status " +
                 std::to_string(status) + "); the driver lacks a float render target GL 3.3 requires"};
  }
  return {};
}

Result<void> singleTextureFramebuffer(const gl::GlApi& gl, gl::Framebuffer& fb, GLuint texture,
                                      const char* what) {
  fb = gl::Framebuffer::create(gl);
  gl.BindFramebuffer(GL_FRAMEBUFFER, fb.id());
  gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture, 0);
  return complete(gl, what);
}

}  // namespace

Result<void> FrameTargets::ensure(const gl::GlApi& gl, int width, int height, int samples) {
  GLint maxSize = 0, maxSamples = 0, maxColorSamples = 0, maxDepthSamples = 0;
  gl.GetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &maxSize);
  gl.GetIntegerv(GL_MAX_SAMPLES, &maxSamples);
  gl.GetIntegerv(GL_MAX_COLOR_TEXTURE_SAMPLES, &maxColorSamples);
  gl.GetIntegerv(GL_MAX_DEPTH_TEXTURE_SAMPLES, &maxDepthSamples);
  maxSamples = std::min({maxSamples, maxColorSamples, maxDepthSamples});
  if (width <= 0 || height <= 0 || width > maxSize || height > maxSize) {
    return Error{"renderer: image size " + std::to_string(width) + "x" + std::to_string(height) +
                 " is outside 1.." + std::to_string(maxSize) + " pixels"};
  }
  samples = samples > 1 ? std::min(samples, static_cast<int>(maxSamples)) : 0;
  if (width == m_width && height == m_height && samples == m_samples) return {};
  m_width = m_height = 0;
  // Step 1: the single-sample geometry textures and their framebuffer.
  makeTexture(gl, m_radiance, GL_RGBA16F, width, height);
  makeTexture(gl, m_diffuse, GL_RGBA16F, width, height);
  makeTexture(gl, m_position, GL_RGBA32F, width, height);
  m_depth = gl::Texture::create(gl);
  gl.BindTexture(GL_TEXTURE_2D, m_depth.id());
  gl.TexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, width, height, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT,
                nullptr);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);  // complete without mip-maps
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  m_resolved = gl::Framebuffer::create(gl);
  gl.BindFramebuffer(GL_FRAMEBUFFER, m_resolved.id());
  gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, m_radiance.id(), 0);
  gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, m_diffuse.id(), 0);
  gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT2, GL_TEXTURE_2D, m_position.id(), 0);
  gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, m_depth.id(), 0);
  gl.DrawBuffers(3, kGeometryBuffers);
  if (auto r = complete(gl, "geometry"); !r) return r;
  // Step 2: the multisampled geometry framebuffer, of textures (the separable resolve reads
  // the samples of diffuse and position with texelFetch).
  if (samples > 1) {
    makeMultisampleTexture(gl, m_msaaRadiance, GL_RGBA16F, width, height, samples);
    makeMultisampleTexture(gl, m_msaaDiffuse, GL_RGBA16F, width, height, samples);
    makeMultisampleTexture(gl, m_msaaPosition, GL_RGBA32F, width, height, samples);
    makeMultisampleTexture(gl, m_msaaDepth, GL_DEPTH_COMPONENT24, width, height, samples);
    m_msaa = gl::Framebuffer::create(gl);
    gl.BindFramebuffer(GL_FRAMEBUFFER, m_msaa.id());
    const GLenum ms = GL_TEXTURE_2D_MULTISAMPLE;
    gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, ms, m_msaaRadiance.id(), 0);
    gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, ms, m_msaaDiffuse.id(), 0);
    gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT2, ms, m_msaaPosition.id(), 0);
    gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, ms, m_msaaDepth.id(), 0);
    gl.DrawBuffers(3, kGeometryBuffers);
    if (auto r = complete(gl, "multisampled geometry"); !r) return r;
  } else {
    m_msaa.reset();
    for (gl::Texture* t : {&m_msaaRadiance, &m_msaaDiffuse, &m_msaaPosition, &m_msaaDepth})
      t->reset();
  }
  // Step 3: blur, composite and output targets.
  makeTexture(gl, m_blurTemp, GL_RGBA16F, width, height);
  makeTexture(gl, m_blurred, GL_RGBA16F, width, height);
  makeTexture(gl, m_composite, GL_RGBA16F, width, height);
  if (auto r = singleTextureFramebuffer(gl, m_blurTempFb, m_blurTemp.id(), "blur"); !r) return r;
  if (auto r = singleTextureFramebuffer(gl, m_blurredFb, m_blurred.id(), "blurred"); !r) return r;
  if (auto r = singleTextureFramebuffer(gl, m_compositeFb, m_composite.id(), "composite"); !r) return r;
  makeRenderbuffer(gl, m_output, GL_RGBA8, width, height, 0);
  m_outputFb = gl::Framebuffer::create(gl);
  gl.BindFramebuffer(GL_FRAMEBUFFER, m_outputFb.id());
  gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, m_output.id());
  if (auto r = complete(gl, "output"); !r) return r;
  m_width = width;
  m_height = height;
  m_samples = samples;
  return gl::checkGlError(gl, "renderer: frame targets");
}

void FrameTargets::resolve(const gl::GlApi& gl) const {
  if (m_samples <= 1) return;
  gl.BindFramebuffer(GL_READ_FRAMEBUFFER, m_msaa.id());
  gl.BindFramebuffer(GL_DRAW_FRAMEBUFFER, m_resolved.id());
  // One attachment at a time: a blit writes every draw buffer from the one read buffer.
  for (const GLenum attachment : kGeometryBuffers) {
    gl.ReadBuffer(attachment);
    gl.DrawBuffers(1, &attachment);
    gl.BlitFramebuffer(0, 0, m_width, m_height, 0, 0, m_width, m_height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  }
  gl.ReadBuffer(GL_COLOR_ATTACHMENT0);
  gl.DrawBuffers(3, kGeometryBuffers);
}

Result<Image8> FrameTargets::readOutput(const gl::GlApi& gl) const {
  Image8 image(m_width, m_height, 4);
  gl.BindFramebuffer(GL_READ_FRAMEBUFFER, m_outputFb.id());
  gl.ReadBuffer(GL_COLOR_ATTACHMENT0);
  gl.BindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  gl.PixelStorei(GL_PACK_ALIGNMENT, 4);  // RGBA8 rows are always 4-byte aligned
  gl.ReadPixels(0, 0, m_width, m_height, GL_RGBA, GL_UNSIGNED_BYTE, image.pixels.data());
  if (auto r = gl::checkGlError(gl, "renderer: readback"); !r) return r.error();
  flipVertically(image);  // GL rows run bottom-up
  return image;
}

Result<FloatImage> FrameTargets::readView(const gl::GlApi& gl, FrameView view) const {
  if (m_width == 0) return Error{"renderer: readFrame before any frame was rendered"};
  GLuint fb = m_resolved.id();
  GLenum attachment = GL_COLOR_ATTACHMENT0;
  switch (view) {
    case FrameView::Radiance:
      break;
    case FrameView::Diffuse:
      attachment = GL_COLOR_ATTACHMENT1;
      break;
    case FrameView::Position:
      attachment = GL_COLOR_ATTACHMENT2;
      break;
    case FrameView::BlurredDiffuse:
      fb = m_blurredFb.id();
      break;
  }
  FloatImage image{m_width, m_height, std::vector<Float4>(static_cast<std::size_t>(m_width) * m_height)};
  gl.BindFramebuffer(GL_READ_FRAMEBUFFER, fb);
  gl.ReadBuffer(attachment);
  gl.BindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  gl.PixelStorei(GL_PACK_ALIGNMENT, 4);
  gl.ReadPixels(0, 0, m_width, m_height, GL_RGBA, GL_FLOAT, image.pixels.data());
  gl.ReadBuffer(GL_COLOR_ATTACHMENT0);
  if (auto r = gl::checkGlError(gl, "renderer: readFrame"); !r) return r.error();
  // GL rows run bottom-up.
  for (int y = 0; y < m_height / 2; ++y) {
    std::swap_ranges(image.pixels.begin() + static_cast<std::ptrdiff_t>(y) * m_width,
                     image.pixels.begin() + static_cast<std::ptrdiff_t>(y + 1) * m_width,
                     image.pixels.begin() + static_cast<std::ptrdiff_t>(m_height - 1 - y) * m_width);
  }
  return image;
}

}  // namespace tissue::render
