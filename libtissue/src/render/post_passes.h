#pragma once
// The frame's last passes: HDR composite (radiance + blurred separable diffuse, RGBA16F) and
// the tone map (exposure, Reinhard, sRGB8) into the output or a host framebuffer.
#include "methods/frame_context.h"

namespace tissue::render {

class PostPasses {
 public:
  static Result<PostPasses> create(const gl::GlApi& gl, const gl::ShaderLibrary& library);
  /// The "composite" pass into the composite target.
  Result<void> composite(const FrameContext& frame) const;
  /// The "tonemap" pass into `framebuffer` at viewport (x, y, width, height) = the frame's size;
  /// `writeBackground` false leaves uncovered pixels alone. `writeDepth` (HostDepth::TestAndWrite)
  /// also writes the frame's depth (the nearest sample with MSAA) into `framebuffer`'s depth
  /// buffer where covered, and implies writeBackground false.
  Result<void> tonemap(const FrameContext& frame, GLuint framebuffer, int x, int y, bool writeBackground,
                       bool writeDepth = false) const;

 private:
  gl::Program m_composite, m_tonemap;
  gl::Program m_tonemapDepth[2];  // TISSUE_WRITE_DEPTH: single-sample, multisampled depth
};

}  // namespace tissue::render
