#pragma once
/// \file
/// The scenes of Jimenez and Gutierrez 2008 Table 1 on our renderer: a row of up to 16 instances
/// of one organ, 1.1 organ widths apart (one mesh per instance: scene objects have no
/// transform), and the camera at a multiple of the organ's size from the middle n of them,
/// looking down and along -z with the light above right. GL: the renderer's context current.

#include <filesystem>
#include <string>
#include <vector>

#include "tissue/core/result.h"
#include "tissue/core/types.h"
#include "tissue/render/renderer.h"
#include "tissue/render/scene.h"
#include "tissue/studies/report.h"
#include "tissue/studies/texture_space_organ.h"
#include "tissue/studies/tsd_error.h"

namespace tissue::studies {

/// The table's organ counts and camera distances (x the organ's size).
inline constexpr int kTsdBenchObjects[] = {1, 2, 4, 8, 16};
inline constexpr float kTsdBenchDistances[] = {1.0f, 2.0f, 4.0f, 8.0f, 20.0f, 40.0f};

/// The camera `distance` mm from `target` (mm), looking down and along -z, the light above right;
/// near and far planes around an organ of `organSize` mm in a row `rowLength` mm long.
render::Scene tsdBenchScene(Float3 target, float distance, float organSize, float rowLength);

/// The row of organs uploaded to one renderer.
struct TsdOrganRow {
  static constexpr int kMaxObjects = 16;
  std::vector<render::MeshHandle> meshes;  ///< instance i centred at x_i = (i - 7.5) 1.1 width
  float widthMm = 0.0f;                    ///< mm, the organ's x extent
  float sizeMm = 0.0f;                     ///< mm, its bounding-box diagonal
  /// mm, the centre of instance `i`.
  float rowX(int i) const;
  /// The middle `n` organs with `method`, the camera `distance` mm from their centre.
  render::Scene sceneOf(int n, float distance, const render::TextureSpaceSettings& method) const;
};

/// Uploads kMaxObjects copies of `organ`, each centred on its place in the row.
Result<TsdOrganRow> uploadOrganRow(render::Renderer& renderer, const TsdOrgan& organ);

/// Jimenez and Gutierrez 2008, Table 1: the speed-up of the three optimisations by heads (rows:
/// 1, 2, 4, 8, 16) and camera distance (columns, the paper's units: kJimenezTable1Distances), on
/// a GeForce 8800 GTX at 1920 x 1200.
inline constexpr float kJimenezTable1Distances[] = {2.5f, 5.0f, 10.0f, 20.0f, 50.0f, 100.0f};
inline constexpr double kJimenezTable1Speedup[5][6] = {{1.17, 1.10, 1.39, 1.48, 1.53, 1.61},
                                                       {1.40, 1.10, 1.46, 1.63, 1.88, 1.88},
                                                       {1.66, 1.39, 1.58, 1.89, 2.10, 2.26},
                                                       {1.86, 1.67, 1.95, 2.01, 2.34, 2.59},
                                                       {2.01, 1.90, 2.28, 2.41, 2.50, 2.77}};

/// What `tissue-sim tsd-bench` asks of the bench.
struct TsdBenchConfig {
  int width = 320, height = 200;  ///< pixels
  int mapSize = 256;              ///< T_max, irradiance map texels (>= 16)
  int gaussians = 6;              ///< profile terms of the speed-up table: 2, 4 or 6
  int repeats = 3;                ///< timed frames per cell and path (median), after one warm-up
  bool accuracyOnly = false;      ///< only the accuracy rows (no speed-up table)
  bool chart = false;             ///< add the speed-up chart (tsd_bench_speedup.png)
  bool image = false;  ///< add the optimised frame of 16 organs, second distance (tsd_bench_16_organs.png)
  std::filesystem::path skinTable;  ///< d'Eon & Luebke's Gaussians (shared/reference/deon_skin_gaussians.tsv)
  std::string mesh;                 ///< the organ's file, for the report
  std::string glRenderer;           ///< GL_RENDERER of the caller's context, for the report
};

/// One accuracy row: one organ at the first distance, `gaussians` terms, optimised or not.
struct TsdAccuracyRow {
  int gaussians = 0;
  bool optimised = false;
  double ms = 0.0;  ///< median frame, ms
  int mapSize = 0;  ///< texels of the diffused map read back
  TexelError error;
};

/// The table (speed-up = unoptimised ms / optimised ms; [organ count][distance], empty with
/// accuracyOnly), the accuracy rows and the report: tsd_bench.json (objects, distances (mm),
/// distances_in_organ_sizes, speedup, unoptimised_ms, optimised_ms, accuracy {rows [setting,
/// optimised, ms, map_size, texel_rms, relative_rms, interior_relative_rms], reference_texels,
/// reference_ms}, organ_size_mm, mesh, atlas, triangles, width, height, map_size, gaussians,
/// repeats, renderer, gl_renderer, seconds, paper), tsd_bench.md (ours and Table 1),
/// tsd_bench_speedup.csv (one row per organ count and distance), tsd_bench_accuracy.csv, and
/// the chart and image when asked.
struct TsdBenchResult {
  std::vector<std::vector<double>> speedup, unoptimisedMs, optimisedMs;
  std::vector<TsdAccuracyRow> accuracy;
  std::size_t referenceTexels = 0;
  double referenceMs = 0.0;  ///< ms, the CPU reference convolutions together
  float organSizeMm = 0.0f;
  StudyOutput output;
};

/// Runs the table and the accuracy rows on `renderer` (its context current; no MSAA). The
/// accuracy reference convolves the unoptimised six-term frame's irradiance over the surface with
/// the six-term skin profile (d'Eon et al. 2007); each setting's diffused map is compared with it
/// at its texels' positions (diffusedMapError). The chart is only described: the caller draws it
/// with writeReport after releasing its GL context (VTK needs its own).
Result<TsdBenchResult> runTsdBench(render::Renderer& renderer, const TsdOrgan& organ,
                                   const TsdBenchConfig& config);

}  // namespace tissue::studies
