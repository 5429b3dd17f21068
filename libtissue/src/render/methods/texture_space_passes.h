#pragma once
// Texture-space diffusion's GL passes for one object (d'Eon et al. 2007, Jimenez et al. 2008):
// the irradiance map (IrradianceMap), one separable Gaussian per profile term, each blurring the
// previous result by the variance it adds (G(v1) * G(v2) = G(v1 + v2)), and the combine pass that
// sums the blurred maps with the profile's weights into one map. Objects are processed one after another and
// share the maps. State is set, not restored.
#include <memory>
#include <vector>

#include "irradiance_map.h"
#include "tissue/render/shading.h"

namespace tissue::render {

/// Everything texture-space diffusion needs besides the scene.
struct TextureSpaceDiffusionSettings {
  std::vector<ProfileGaussian> gaussians;  ///< increasing variances, at most kMaxTsdGaussians
  IrradianceMapSettings irradiance;        ///< the three optimisations
  int blurHalfTaps = 3;                    ///< 2 h + 1 taps per 1D pass (d'Eon: 7)
};

/// The maps and programs, created once for a maximum map size and reused by every object.
class TextureSpaceDiffusion {
 public:
  static Result<TextureSpaceDiffusion> create(const gl::GlApi& gl, const gl::ShaderLibrary& library,
                                              int maxSize);

  /// Irradiance pass and the Gaussian chain for one object.
  Result<void> diffuse(GLuint vertexArray, GLsizei indexCount, const IrradianceFrame& frame,
                       const TextureSpaceDiffusionSettings& settings, bool writePositions = false);
  /// The Gaussian chain on the irradiance map as last rendered (irradianceMap().render(...)).
  Result<void> convolve(const TextureSpaceDiffusionSettings& settings);
  /// The weighted sum of the chain's maps, sum_i w_i map_i, as one map (premultiplied by
  /// coverage, the used T x T square); returns its texture, valid until the next convolve.
  Result<GLuint> combine(const TextureSpaceDiffusionSettings& settings);

  const IrradianceMap& irradianceMap() const { return m_irradiance; }
  IrradianceMap& irradianceMap() { return m_irradiance; }
  /// The framebuffer holding combine()'s map (for readback).
  GLuint combinedFramebuffer() const { return m_tempFramebuffer.id(); }

  /// Empty (create() makes a usable one).
  TextureSpaceDiffusion() = default;

 private:
  Result<void> blur(GLuint source, GLuint target, float sigmaMm, bool horizontal,
                    const TextureSpaceDiffusionSettings& settings);
  // Binds `target` with the used T x T viewport; with `skipCulled` (and the map's visibility in
  // depth) clears it and sets the depth test that rejects culled and empty texels.
  void bindTexels(GLuint target, bool skipCulled) const;
  const gl::GlApi* m_gl = nullptr;
  IrradianceMap m_irradiance;
  gl::Program m_blur, m_combine;
  gl::Texture m_temp;
  gl::Framebuffer m_tempFramebuffer;
  std::vector<gl::Texture> m_maps;
  std::vector<gl::Framebuffer> m_mapFramebuffers;
  gl::VertexArray m_emptyVertexArray;  // the full-screen triangle needs no attributes
};

}  // namespace tissue::render
