#pragma once
// The texture-space method (texture-space diffusion, d'Eon et al. 2007): not in this build. It arrives with
// branch `tsd`; until then drawing an object with it is an Error, never a silent fallback to another method.
#include "frame_context.h"

namespace tissue::render {

class TextureSpaceMethod {
 public:
  static Result<TextureSpaceMethod> create(const gl::GlApi& gl, const gl::ShaderLibrary& library);
  /// Its passes over `objects`; for now always an Error naming the missing method.
  Result<void> draw(const FrameContext& frame, std::span<const ObjectDraw> objects) const;
};

}  // namespace tissue::render
