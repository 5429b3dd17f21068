#pragma once
// Screen-space separable subsurface scattering (Jimenez et al. 2015; Freude 2014, ch. 4):
//   separable:geometry  diffuse (+ transmission) to the diffuse target with the object id,
//                       specular to the radiance target (shaders/separable/geometry.frag);
//   separable:resolve   MSAA only: the diffuse and position targets resolved to the nearest
//                       covered sample (shaders/separable/resolve.frag), not averaged;
//   separable:blur-x,   two 1D passes with each object's own kernel, per-pixel kernel scale
//   separable:blur-y    (eq. 4.11) and follow-surface (eq. 4.12) (shaders/separable/blur.frag);
//   ...:blur-x:r, :blur-y:r  the same for component r >= 1 of rank-R kernels, added with the
//                       component's sign into the blurred target (Freude eq. 5.10).
// The composite pass then adds the blurred diffuse to the radiance (specular after the blur).
// Kernels arrive as plain arrays (SeparableSettings::components); this file knows no optics.
#include "frame_context.h"

namespace tissue::render {

class SeparableMethod {
 public:
  static Result<SeparableMethod> create(const gl::GlApi& gl, const gl::ShaderLibrary& library);
  /// Checks every object's kernel and draws the "separable:geometry" pass.
  Result<void> draw(const FrameContext& frame, std::span<const ObjectDraw> objects) const;
  /// The blur passes (two per component of the frame's highest rank), after every geometry
  /// pass and the MSAA resolve.
  Result<void> post(const FrameContext& frame, std::span<const ObjectDraw> objects) const;

 private:
  Result<void> resolve(const FrameContext& frame) const;

  SurfacePrograms m_geometry;
  gl::Program m_blur;
  gl::Program m_resolve;  // the MSAA resolve of diffuse and position
  gl::Texture m_kernels;  // RGBA32F, (kMaxKernelTaps + 1) x (objects + 1 + components), per frame
};

}  // namespace tissue::render
