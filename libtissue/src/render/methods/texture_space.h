#pragma once
// Texture-space diffusion as a shading method of the pipeline (d'Eon et al. 2007, with the
// culled, depth-sized and clipped irradiance maps of Jimenez and Gutierrez 2008). Per object:
//   texture-space:irradiance  the scene's lights (common/lights.glsl, shadows, transmission) into
//                             the object's UV space, with the stretch map (IrradianceMap);
//   texture-space:blur        one separable Gaussian per profile term, then their weighted sum
//                             as one map (TextureSpaceDiffusion);
//   texture-space:final       the camera pass into the geometry targets: diffused diffuse to the
//                             diffuse target with the object id, specular to the radiance target.
// The separable blur leaves non-separable ids as they are, so the blurred diffuse holds both
// methods' subsurface light; without separable objects post() copies the diffuse target there
// ("texture-space:copy"). Maps are allocated once per T_max and shared by the objects.
#include <map>

#include "frame_context.h"
#include "texture_space_passes.h"

namespace tissue::render {

class TextureSpaceMethod {
 public:
  static Result<TextureSpaceMethod> create(const gl::GlApi& gl, const gl::ShaderLibrary& library);
  /// Checks every object's settings and runs the three passes per object.
  Result<void> draw(const FrameContext& frame, std::span<const ObjectDraw> objects);
  /// After the separable blur (or instead of it): fills the blurred diffuse where nothing else
  /// did. `separableBlurred`: the separable passes ran and already carried these pixels over.
  Result<void> post(const FrameContext& frame, bool separableBlurred) const;

  /// The maps of the last object drawn, read back (Renderer::readTextureSpaceMaps).
  Result<TextureSpaceMaps> readMaps(const gl::GlApi& gl) const;

 private:
  Result<TextureSpaceDiffusion*> chain(const FrameContext& frame, int maxSize);
  gl::ShaderLibrary m_library;  // the maps' programs are built with their first size
  SurfacePrograms m_final;
  std::map<int, TextureSpaceDiffusion> m_chains;  // by T_max
  TextureSpaceDiffusion* m_last = nullptr;
  gl::Framebuffer m_copySource;  // reads the diffuse target for the copy
};

}  // namespace tissue::render
