#pragma once
// The renderer's intermediate targets for one image size:
//   geometry: radiance (RGBA16F, linear HDR; a = coverage), diffuse (RGBA16F, the separable
//     objects' diffuse before the blur; a = object id), position (RGBA32F, world mm + view depth
//     mm) and depth (a texture: the tone map reads it for HostDepth::TestAndWrite); multisampled textures
//     when MSAA is on (sampled by the separable method's resolve), resolved into textures;
//   blurTemp, blurred (RGBA16F): the separable blur's two passes;
//   composite (RGBA16F): radiance + blurred diffuse, the tone map's input;
//   output (RGBA8): the tone-mapped sRGB image read back by renderImage.
#include "tissue/core/image.h"
#include "tissue/core/result.h"
#include "tissue/gl/objects.h"
#include "tissue/render/renderer.h"

namespace tissue::render {

class FrameTargets {
 public:
  /// (Re)allocates for `width` x `height` pixels and `samples` (0/1: none, clamped to GL_MAX_SAMPLES).
  Result<void> ensure(const gl::GlApi& gl, int width, int height, int samples);
  int width() const { return m_width; }
  int height() const { return m_height; }
  int samples() const { return m_samples; }
  /// Where the geometry passes draw (3 colour attachments and depth).
  GLuint geometryFramebuffer() const { return m_samples > 1 ? m_msaa.id() : m_resolved.id(); }
  /// Copies the multisampled geometry attachments into the textures (no-op without MSAA).
  void resolve(const gl::GlApi& gl) const;
  GLuint radiance() const { return m_radiance.id(); }
  GLuint diffuse() const { return m_diffuse.id(); }
  GLuint position() const { return m_position.id(); }
  /// The single-sample depth texture (GL_DEPTH_COMPONENT24) of the geometry passes without MSAA.
  GLuint depth() const { return m_depth.id(); }
  /// The multisampled depth texture of the geometry passes with MSAA (0 without).
  GLuint msaaDepth() const { return m_msaaDepth.id(); }
  /// The single-sample geometry framebuffer (radiance, diffuse, position: attachments 0..2).
  GLuint resolvedFramebuffer() const { return m_resolved.id(); }
  /// The multisampled diffuse and position (GL_TEXTURE_2D_MULTISAMPLE; 0 without MSAA).
  GLuint msaaDiffuse() const { return m_msaaDiffuse.id(); }
  GLuint msaaPosition() const { return m_msaaPosition.id(); }
  GLuint blurTempFramebuffer() const { return m_blurTempFb.id(); }
  GLuint blurTemp() const { return m_blurTemp.id(); }
  GLuint blurredFramebuffer() const { return m_blurredFb.id(); }
  GLuint blurred() const { return m_blurred.id(); }
  GLuint compositeFramebuffer() const { return m_compositeFb.id(); }
  GLuint composite() const { return m_composite.id(); }
  GLuint outputFramebuffer() const { return m_outputFb.id(); }
  /// Reads the tone-mapped output, rows top to bottom.
  Result<Image8> readOutput(const gl::GlApi& gl) const;
  /// Reads an intermediate target as float RGBA, rows top to bottom.
  Result<FloatImage> readView(const gl::GlApi& gl, FrameView view) const;

 private:
  int m_width = 0, m_height = 0, m_samples = -1;
  gl::Texture m_radiance, m_diffuse, m_position, m_depth, m_blurTemp, m_blurred, m_composite;
  gl::Texture m_msaaRadiance, m_msaaDiffuse, m_msaaPosition, m_msaaDepth;  // multisampled
  gl::Renderbuffer m_output;
  gl::Framebuffer m_resolved, m_msaa, m_blurTempFb, m_blurredFb, m_compositeFb, m_outputFb;
};

}  // namespace tissue::render
