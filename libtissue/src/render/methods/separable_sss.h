#pragma once
// The separable method (screen-space separable SSS, Jimenez et al. 2015): not in this build. It arrives with
// branch `sss`; until then drawing an object with it is an Error, never a silent fallback to another method.
#include "frame_context.h"

namespace tissue::render {

class SeparableMethod {
 public:
  static Result<SeparableMethod> create(const gl::GlApi& gl, const gl::ShaderLibrary& library);
  /// Its passes over `objects`; for now always an Error naming the missing method.
  Result<void> draw(const FrameContext& frame, std::span<const ObjectDraw> objects) const;
  /// Its screen-space passes, after every geometry pass.
  Result<void> post(const FrameContext& frame, std::span<const ObjectDraw> objects) const;
};

}  // namespace tissue::render
