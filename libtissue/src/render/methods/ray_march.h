#pragma once
// The ray-march method: ray-marched subsurface texture mapping (François et al. 2006,
// Algorithms 1-2; Norberg 2010 §2.1, §3.1) as one geometry pass, "ray-march", straight into the
// HDR radiance target (shaders/raymarch/). The mesh's per-vertex fitted planes (attribute 4)
// give the light's entry; the layer stack comes from the object's RayMarchSettings and its
// subsurface maps. The same model runs on the CPU in tissue::subsurface (plane mode).
#include "frame_context.h"

namespace tissue::render {

class RayMarchMethod {
 public:
  /// Builds the fixed-count and adaptive programs, each also in the samples-shown variant.
  static Result<RayMarchMethod> create(const gl::GlApi& gl, const gl::ShaderLibrary& library);
  /// The "ray-march" pass over `objects` (their subsurface maps resolved by the frame into
  /// ObjectDraw::methodTextures). Errors name the object and what to fix (layer and map counts,
  /// a missing map, a mesh without planes).
  Result<void> draw(const FrameContext& frame, std::span<const ObjectDraw> objects) const;

 private:
  // [adaptive][showSamples]
  gl::Program m_programs[2][2];
};

}  // namespace tissue::render
