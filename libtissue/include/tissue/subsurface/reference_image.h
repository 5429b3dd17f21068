#pragma once
/// \file
/// Images of ray-marched single scattering computed on the CPU: camera rays meet the mesh
/// through a BVH, the surface attributes are interpolated at the hit (as the rasteriser does,
/// perspective-correct), and every pixel is marched with marchSingleScattering. In plane mode
/// the image is what the GPU shader computes; in mesh mode with many samples it is the
/// accuracy reference (the light's entry point on the actual deformed mesh). Lengths in mm.

#include <cstdint>
#include <span>
#include <vector>

#include "tissue/core/image.h"
#include "tissue/core/types.h"
#include "tissue/subsurface/layer_stack.h"
#include "tissue/subsurface/single_scattering.h"

namespace tissue::subsurface {

/// A mesh's render-vertex arrays, all #V long (as the renderer receives them).
struct MeshView {
  std::span<const Float3> positions;    ///< mm
  std::span<const Float3> normals;      ///< unit vertex normals
  std::span<const Float4> tangents;     ///< unit T with handedness w; B = w cross(N, T)
  std::span<const Float4> planes;       ///< fitted planes (N_S, d in mm), eq. 14
  std::span<const Float2> uvs;          ///< texture coordinates
  std::span<const Triangle> triangles;  ///< #F
  float uvPerMm = 1.0f / 80.0f;         ///< texture units per mm (see uvPerMmOf)
};

/// A perspective look-at camera (the renderer's Camera without the clip planes).
struct PinholeCamera {
  Float3 eye{0.0f, 0.0f, 200.0f};   ///< mm
  Float3 target{0.0f, 0.0f, 0.0f};  ///< mm
  Float3 up{0.0f, 1.0f, 0.0f};      ///< unitless
  float verticalFovDeg = 40.0f;     ///< degrees
};

/// How the light's entry point is found (see single_scattering.h).
enum class EntryMode { Planes, Mesh };

/// What to compute.
struct CpuImageSettings {
  int width = 160;      ///< pixels
  int height = 120;     ///< pixels
  MarchSettings march;  ///< sample count, Depth_max, threshold
  EntryMode entry = EntryMode::Mesh;
  bool jitter = true;     ///< noisy sampling from pixelJitter (else the midpoint rule)
  unsigned seed = 0;      ///< frame seed of the jitter
  bool adaptive = false;  ///< per-pixel sample count from adaptiveSampleCount
  AdaptiveSettings adaptiveSettings;
  int threads = 2;  ///< worker threads (rows are split between them)
};

/// Linear radiance per pixel, rows top to bottom.
struct RadianceImage {
  int width = 0;
  int height = 0;
  std::vector<Float3> radiance;       ///< light units
  std::vector<std::uint8_t> covered;  ///< 1 where a camera ray met the mesh
  std::vector<int> samples;           ///< samples marched per pixel (0 where uncovered)
  std::vector<float> viewCos;         ///< N_P . omega_out per pixel (grazing near 0; 0 where uncovered)
};

/// Renders single scattering of `mesh` seen by `camera`.
RadianceImage renderSingleScatteringCpu(const MeshView& mesh, const LayerStack& stack,
                                        std::span<const Light> lights, const PinholeCamera& camera,
                                        const CpuImageSettings& settings);

/// Texture units per mm of a mesh, sqrt(total UV area / total surface area).
float uvPerMmOf(std::span<const Float3> positions, std::span<const Float2> uvs,
                std::span<const Triangle> triangles);

/// The display transform of the GPU methods (shaders/common/tonemap.glsl): exposure, Reinhard
/// x / (1 + x), sRGB encoding; uncovered pixels get `background` (sRGB 0..1). RGBA8.
Image8 toDisplay(const RadianceImage& image, float exposure, Float3 background);

/// Root-mean-square difference of two RGBA8 images over the RGB values of the pixels where
/// `mask` is non-zero (all pixels if empty), in units of full scale (0..1).
double displayRms(const Image8& a, const Image8& b, std::span<const std::uint8_t> mask = {});

/// Relative root-mean-square difference of linear radiance `a` against `reference` (#pixels
/// each, rows top to bottom, e.g. a GPU frame divided by its radiance scale) over the pixels
/// where `mask` is non-zero (all if empty): sqrt(sum |a - r|^2 / sum |r|^2) over RGB. -1 when
/// the sizes differ or the reference is black there.
double relativeRadianceRms(std::span<const Float3> a, std::span<const Float3> reference,
                           std::span<const std::uint8_t> mask = {});

}  // namespace tissue::subsurface
