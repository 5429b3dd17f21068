#pragma once
/// \file
/// Ray-marched subsurface texture mapping on the GPU (François et al. 2006, Algorithms 1-2;
/// Norberg 2010 §2.1, §3.1): single scattering through a layer stack described by RGBA
/// subsurface maps, with the light's entry through the per-vertex fitted planes interpolated
/// across each triangle (eq. 9-10, 14-15). Shaders in shaders/raymarch/. The same model runs
/// on the CPU in tissue::subsurface (plane mode), which the tests compare against.
///
/// A self-contained renderer (own buffers, programs and offscreen target) so that it does not
/// depend on the shading-method pipeline being rebuilt on another branch; see the report.
/// Lengths in mm, coefficients in mm^-1.

#include <memory>
#include <span>
#include <vector>

#include "tissue/core/image.h"
#include "tissue/core/result.h"
#include "tissue/core/types.h"
#include "tissue/gl/proc_address.h"
#include "tissue/gl/shader_library.h"
#include "tissue/render/renderer.h"
#include "tissue/render/scene.h"

namespace tissue::render {

/// One layer of the stack, as the shader takes it.
struct RayMarchLayer {
  Float3 sigma_s;         ///< scattering, mm^-1 per RGB channel
  Float3 sigma_t;         ///< extinction, mm^-1 per RGB channel
  float schlickK = 0.0f;  ///< Schlick phase parameter (optics::schlickKFromG(g))
};

/// The layered material: 4N + 1 layers and N RGBA maps (N = 1 or 2) of boundary depths.
struct RayMarchMaterial {
  std::vector<RayMarchLayer> layers;   ///< top first
  std::vector<Image8> subsurfaceMaps;  ///< RGBA, rows top (v = 1) first
  float depthScaleMm = 3.0f;           ///< mm per unit of the maps
  float uvPerMm = 1.0f / 80.0f;        ///< texture units per mm along T and B
};

/// A point light without falloff.
struct RayMarchLight {
  Float3 positionMm;  ///< mm
  Float3 radiance;    ///< linear RGB
};

/// Per-frame settings (the CPU model's MarchSettings and AdaptiveSettings, plus display).
struct RayMarchRenderSettings {
  int samples = 50;                    ///< fixed sample count (1..256)
  float depthMaxMm = 3.0f;             ///< Depth_max of eq. 15, mm
  float attenuationThreshold = 1e-3f;  ///< stop once exp(-tau_PM) falls below it (0: never)
  float minCosView = 0.1f;             ///< clamp of N_S . omega_out in eq. 15
  bool jitter = true;                  ///< noisy sampling from a per-pixel hash (Norberg §3.1.2)
  unsigned seed = 0;                   ///< frame seed of the hash
  bool adaptive = false;               ///< per-pixel count from view angle, depth and footprint
  int minSamples = 4;                  ///< adaptive floor
  int maxSamples = 100;                ///< adaptive ceiling
  float depthResolutionMm = 0.06f;     ///< adaptive: wanted depth step, mm
  float cutoff = 0.03f;                ///< adaptive: round-trip transmittance where the march stops
  float texelsPerStep = 1.5f;          ///< adaptive: wanted sideways step, texels or pixels
  bool showSamples = false;            ///< write samples / 100 as grey instead of radiance
  float exposure =
      8.0f;  ///< multiplies radiance before the Reinhard tone map (single scattering alone is dim)
  Float3 background{0.05f, 0.05f, 0.06f};  ///< sRGB clear colour
};

/// Draws a mesh with ray-marched single scattering. Needs its context current for every call.
class RayMarchRenderer {
 public:
  /// Loads GL and builds the fixed-count and adaptive program variants.
  static Result<RayMarchRenderer> create(const gl::GetProcAddressFn& getProcAddress,
                                         const gl::ShaderLibrarySettings& shaders = {});
  RayMarchRenderer(RayMarchRenderer&&) noexcept;
  RayMarchRenderer& operator=(RayMarchRenderer&&) noexcept;
  ~RayMarchRenderer();

  /// Uploads the mesh and its per-vertex fitted planes (N_S, d in mm), #V each.
  Result<void> setMesh(const MeshArrays& mesh, std::span<const Float4> planes);
  /// Re-uploads the deforming attributes, planes included (sizes as in setMesh).
  Result<void> updateMesh(std::span<const Float3> positions, std::span<const Float3> normals,
                          std::span<const Float4> tangents, std::span<const Float4> planes);
  /// Sets the layer stack; errors when the layer and map counts do not fit 4N + 1.
  Result<void> setMaterial(const RayMarchMaterial& material);

  /// Renders `width` x `height` pixels and reads them back (RGBA8, rows top first).
  Result<Image8> renderImage(const Camera& camera, std::span<const RayMarchLight> lights,
                             const RayMarchRenderSettings& settings, int width, int height);

  /// ms of the last renderImage: the draw including glFinish (CPU wall clock).
  double lastDrawMs() const;

 private:
  struct Impl;
  explicit RayMarchRenderer(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> m_impl;
};

}  // namespace tissue::render
