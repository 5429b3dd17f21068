#pragma once
// The parallax method (layered parallax mapping): not in this build. It arrives with branch `raymarch`; until
// then drawing an object with it is an Error, never a silent fallback to another method.
#include "frame_context.h"

namespace tissue::render {

class ParallaxMethod {
 public:
  static Result<ParallaxMethod> create(const gl::GlApi& gl, const gl::ShaderLibrary& library);
  /// Its passes over `objects`; for now always an Error naming the missing method.
  Result<void> draw(const FrameContext& frame, std::span<const ObjectDraw> objects) const;
};

}  // namespace tissue::render
