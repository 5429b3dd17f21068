#pragma once
/// \file
/// The ray-march bench's measurements on a pipeline renderer (studies::RayMarchRender), after
/// François et al. 2006 Table 2: the settings of its table (10, 25, 50, 100 samples and
/// adaptive), their interleaved timing, the last frame's linear radiance where both the CPU ray
/// cast and the rasteriser cover a pixel, and the mean samples per pixel of the adaptive march.
/// GL: the renderer's context must be current.

#include <cstdint>
#include <span>
#include <vector>

#include "tissue/core/image.h"
#include "tissue/core/result.h"
#include "tissue/core/types.h"
#include "tissue/studies/raymarch_scene.h"

namespace tissue::studies {

/// The settings of the table: 10, 25, 50, 100 samples and adaptive (0).
inline constexpr int kRayMarchBenchSettings[] = {10, 25, 50, 100, 0};

/// Setting `n` of the table (0: adaptive) with the adaptive-quality fields of `adaptive`.
render::RayMarchSettings rayMarchBenchSetting(int n, const render::RayMarchSettings& adaptive);

/// The last frame's linear radiance divided by the method's scale, and the pixels both the CPU
/// ray cast and the GPU rasteriser cover (silhouette pixels only one of them covers would compare
/// tissue with background and swamp the figures).
struct GpuRadiance {
  std::vector<Float3> radiance;  ///< light units, rows top to bottom
  std::vector<std::uint8_t> mask;
};

/// Reads the renderer's last Radiance frame; `cpuCovered` is the CPU image's coverage.
Result<GpuRadiance> readRayMarchRadiance(render::Renderer& renderer,
                                         std::span<const std::uint8_t> cpuCovered);

/// Mean samples per covered pixel: the samples-shown frame writes samples / 100 as radiance,
/// also returned as a grey image (white = 100 samples; black where uncovered).
struct SampleCounts {
  double mean = 0.0;
  Image8 image;
};

/// Renders the samples-shown frame of the current settings and counts over `mask`.
Result<SampleCounts> meanSamples(RayMarchRender& gpu, int width, int height,
                                 std::span<const std::uint8_t> mask);

/// ms = median of the "ray-march" pass (CPU wall clock to completion, with
/// RendererSettings::finishPasses); gpuMs = median of its timer query where valid (-1 if never).
struct RayMarchTiming {
  double ms = 0.0, gpuMs = -1.0;
};

/// Times every setting of the table: one warm-up frame each (allocation, shader caches), then
/// `repeats` rounds of one frame per setting, interleaved so that a change in the machine's load
/// falls on every setting alike. One entry per setting, in table order.
Result<std::vector<RayMarchTiming>> timeRayMarchSettings(RayMarchRender& gpu,
                                                         const render::RayMarchSettings& adaptive, int width,
                                                         int height, int repeats);

}  // namespace tissue::studies
