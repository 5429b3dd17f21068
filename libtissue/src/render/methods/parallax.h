#pragma once
// Layered parallax multi-texturing (Oat 2006, as in Norberg 2010 §2.2 and §3.2), per object:
//   parallax:lightmap       the texture-space irradiance pass (IrradianceMap: culled §3, clipped
//                           §5 of Jimenez and Gutierrez 2008), once per light, box-filtered into
//                           the reduced-resolution lightmap (shaders/parallax/gather.frag);
//   parallax:lightmap-blur  Poisson-disc passes with a radius in mm on the surface (blur.frag);
//   parallax:geometry       outer layer + inner layers at the eq. 15-18 offset, lit by the
//                           blurred lightmap, eq. 19 blend, into the radiance target
//                           (geometry.frag).
// The lightmap is one set of textures per (size, reduction), reused by the parallax objects in turn.
#include <map>
#include <memory>
#include <utility>

#include "frame_context.h"
#include "irradiance_map.h"

namespace tissue::render {

class ParallaxMethod {
 public:
  static Result<ParallaxMethod> create(const gl::GlApi& gl, const gl::ShaderLibrary& library);
  /// Checks every object's settings, then the three passes per object.
  Result<void> draw(const FrameContext& frame, std::span<const ObjectDraw> objects) const;

 private:
  // The lightmap's GL objects, created on the first parallax frame that needs their sizes, so
  // that renderers without parallax objects do not hold them; one per (size, reduction) in use.
  struct Lightmap {
    IrradianceMap irradiance;
    gl::Texture maps[2];  // ping-pong, reduced resolution, premultiplied by the visible fraction
    gl::Framebuffer framebuffers[2];
    int size = 0, reduction = 0;
  };
  Result<Lightmap*> ensureLightmap(const gl::GlApi& gl, const ParallaxLightmapSettings& s) const;
  /// Draws the lightmap and blurs it; returns which of `l.maps` holds the result.
  Result<int> lightmap(const FrameContext& frame, const ObjectDraw& object, Lightmap& l) const;
  Result<void> geometry(const FrameContext& frame, const ObjectDraw& object, GLuint lightmapTexture) const;

  gl::ShaderLibrary m_library;
  SurfacePrograms m_geometry;
  gl::Program m_gather, m_blur;
  std::vector<Float2> m_disc;                                                    // unit Poisson disc
  mutable std::map<std::pair<int, int>, std::unique_ptr<Lightmap>> m_lightmaps;  // a cache (see above)
};

}  // namespace tissue::render
