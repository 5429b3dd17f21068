#pragma once
/// \file
/// The ray-march bench's measurements on a pipeline renderer (studies::RayMarchRender), after
/// François et al. 2006 Table 2: the settings of its table (10, 25, 50, 100 samples and
/// adaptive), their interleaved timing, the last frame's linear radiance where both the CPU ray
/// cast and the rasteriser cover a pixel, and the mean samples per pixel of the adaptive march.
/// GL: the renderer's context must be current.

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "tissue/core/image.h"
#include "tissue/core/result.h"
#include "tissue/core/types.h"
#include "tissue/studies/raymarch_scene.h"
#include "tissue/studies/report.h"

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

/// François et al. 2006, Table 2: frames per second of their renderer at 800 x 600 pixels by
/// samples along the view ray (10, 50, 100), for the fish and the gecko model.
inline constexpr int kFrancoisTable2Samples[] = {10, 50, 100};
inline constexpr double kFrancoisTable2FishFps[] = {126.0, 51.0, 20.0};
inline constexpr double kFrancoisTable2GeckoFps[] = {120.0, 33.0, 16.0};

/// What `tissue-sim raymarch-bench` asks of the bench.
struct RayMarchBenchConfig {
  int width = 240, height = 180;      ///< pixels
  int referenceSamples = 200;         ///< samples per pixel of the CPU reference (mesh entry, midpoint rule)
  int repeats = 7;                    ///< timed frames per setting (median)
  float pokeDepthMm = 8.0f;           ///< mm, the poke before the bench; 0 = rest shape
  bool closeUp = true;                ///< frame the poke site (false: the whole organ)
  render::RayMarchSettings adaptive;  ///< its adaptive-quality fields
  bool images =
      false;  ///< add the images (raymarch_<setting>.png, raymarch_samples.png, raymarch_reference.png, ...)
  bool chart = false;      ///< add the chart of error against time (raymarch_error_vs_time.png)
  std::string glRenderer;  ///< GL_RENDERER of the caller's context, for the report
};

/// One setting of the table.
struct RayMarchBenchRow {
  std::string setting;          ///< "10", "25", "50", "100", "adaptive"
  double samples = 0.0;         ///< per pixel (the adaptive march: mean over covered pixels)
  RayMarchTiming timing;        ///< ms
  double imageRms = 0.0;        ///< display RMS against the CPU reference (0..1)
  double radianceRelRms = 0.0;  ///< relative RMS in linear radiance against it
};

/// The bench's figures and report: raymarch_bench.json (mesh, width, height, poke_depth_mm,
/// repeats, gl_renderer, reference {samples, entry, cpu_ms}, results [setting, samples, ms,
/// gpu_ms, image_rms, radiance_rel_rms; adaptive also rms_vs_100, radiance_rel_rms_vs_100,
/// ms_ratio_vs_100], plane_approximation_rms, plane_approximation_radiance_rel_rms,
/// gpu_vs_cpu_model_radiance_rel_rms_50, paper), raymarch_bench.md (ours and Table 2),
/// raymarch_bench.csv (one row per setting), and the images and chart when asked.
struct RayMarchBenchResult {
  std::vector<RayMarchBenchRow> rows;  ///< in kRayMarchBenchSettings' order
  double referenceMs = 0.0;            ///< ms, the CPU reference
  /// The adaptive march against the 100-sample one: display RMS, relative radiance RMS, time ratio.
  double adaptiveRmsVs100 = 0.0, adaptiveRadianceRelRmsVs100 = 0.0, adaptiveMsRatioVs100 = -1.0;
  /// The CPU march with the fitted planes' entry against the mesh entry (François eq. 9-10, 14-15).
  double planeRms = 0.0, planeRadianceRelRms = 0.0;
  /// The pipeline at 50 samples against the CPU model with the same jitter, relative radiance RMS.
  double gpuVsCpuModel50 = 0.0;
  StudyOutput output;
};

/// The bench: loads `source` (a mesh with its material file and subsurface map), pokes it, renders
/// the CPU reference (mesh entry, many samples, no early stop) and the plane-entry image, then on
/// a pipeline renderer made on the caller's current context (`settings`, finishPasses forced on)
/// times and measures every setting of the table, the adaptive march's samples, and the method
/// against its CPU twin. The renderer is released before returning; the chart is only described
/// (the caller draws it with writeReport after releasing its GL context).
Result<RayMarchBenchResult> runRayMarchBench(const gl::GetProcAddressFn& getProcAddress,
                                             render::RendererSettings settings,
                                             const scene::OrganSource& source,
                                             const RayMarchBenchConfig& config);

}  // namespace tissue::studies
