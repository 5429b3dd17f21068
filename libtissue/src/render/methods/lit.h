#pragma once
// The Lit method: Blinn-Phong through the normal map, shadows from every light, straight into
// the HDR radiance target (shaders/lit/lit.frag). No subsurface scattering.
#include "frame_context.h"

namespace tissue::render {

class LitMethod {
 public:
  static Result<LitMethod> create(const gl::GlApi& gl, const gl::ShaderLibrary& library);
  /// The "lit" geometry pass over `objects`.
  Result<void> draw(const FrameContext& frame, std::span<const ObjectDraw> objects) const;

 private:
  SurfacePrograms m_programs;
};

}  // namespace tissue::render
