#pragma once
/// \file
/// Texture-space diffusion (d'Eon, Luebke and Enderton 2007) with the culled, depth-sized and
/// clipped irradiance maps of Jimenez and Gutierrez 2008, as a renderer of its own: it draws one
/// mesh (as several instances, for the paper's Table 1) into an offscreen image. Each instance
/// gets its irradiance map rendered in UV space with a per-frame stretch map, blurred by one
/// separable Gaussian per profile term, and summed in the final pass. Lengths are mm.
/// Like Renderer, it uses whatever GL context is current and restores the GL state it touches.

#include <memory>
#include <span>
#include <vector>

#include "tissue/core/image.h"
#include "tissue/core/result.h"
#include "tissue/render/renderer.h"
#include "tissue/render/scene.h"
#include "tissue/render/texture_space_math.h"

namespace tissue::render {

/// Per-frame settings of the standalone texture-space renderer. Superseded by the pipeline's
/// texture-space method (TextureSpaceSettings in shading.h); kept only for the demo's frame
/// until the demo draws through the pipeline, then this header goes.
struct TsdSettings {
  std::vector<ProfileGaussian> gaussians;  ///< the profile, increasing variances (1..8 terms)
  bool cull = true;                        ///< culled irradiance map (Jimenez §3, 105 degrees)
  bool clip = true;                        ///< clipped irradiance map (§5, eq. 5-6)
  bool depthSize = true;                   ///< depth-based map size (§4, eq. 3-4)
  float clipD = 1.0f;                      ///< D of eq. 5 (1: the exact frustum)
  /// d_ref of eq. 3, mm. 0: derived from the viewport, the distance at which one texel of the
  /// full map covers one pixel: d_ref = H / (2 tan(fov / 2) * texelsPerMm).
  float referenceDistanceMm = 0.0f;
  int blurHalfTaps = 3;  ///< 2 h + 1 taps per 1D Gaussian pass (d'Eon: 7)
};

/// Creation settings.
struct TextureSpaceRendererSettings {
  gl::ShaderLibrarySettings shaders;  ///< where GLSL comes from
  int maxMapSize = 1024;              ///< T_max, texels (allocated once, §4)
};

/// Texture-space diffusion of one mesh, drawn as instances. Movable, not copyable.
class TextureSpaceRenderer {
 public:
  static Result<TextureSpaceRenderer> create(const gl::GetProcAddressFn& getProcAddress,
                                             const TextureSpaceRendererSettings& settings = {});
  TextureSpaceRenderer(TextureSpaceRenderer&&) noexcept;
  TextureSpaceRenderer& operator=(TextureSpaceRenderer&&) noexcept;
  ~TextureSpaceRenderer();

  /// Uploads the mesh; its UVs must be usable (unique, no overlaps: see mesh::computeUvAtlas).
  /// `texelsPerMm` is the UV map's density at T_max (for d_ref), texels per mm.
  Result<void> setMesh(const MeshArrays& mesh, float texelsPerMm);
  /// Re-uploads positions, normals and tangents of a deforming mesh.
  Result<void> updateMesh(std::span<const Float3> positions, std::span<const Float3> normals,
                          std::span<const Float4> tangents);
  /// The albedo texture (sRGB).
  Result<void> setBaseColor(const Image8& image);

  /// Renders the instances (one per offset, mm; empty = one at the origin) into an RGBA8 image,
  /// rows top to bottom. Each instance runs the whole texture-space chain.
  Result<Image8> renderImage(const Scene& scene, int width, int height, const TsdSettings& settings,
                             std::span<const Float3> instanceOffsetsMm = {});

 private:
  struct Impl;
  explicit TextureSpaceRenderer(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> m_impl;
};

}  // namespace tissue::render
