// tissue-sim tsd-bench: Jimenez and Gutierrez 2008 Table 1 on our renderer. 1, 2, 4, 8 and 16
// organ instances in a row by six camera distances; each cell the speed-up of texture-space
// diffusion with the three irradiance-map optimisations over without, measured in one run, on
// the render pipeline (one scene object per organ).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>

#include "command.h"
#include "gl_environment.h"
#include "output.h"
#include "texture_space_setup.h"
#include "tissue/context/headless_context.h"
#include "tissue/core/statistics.h"
#include "tissue/core/stopwatch.h"
#include "tissue/inspect/chart.h"
#include "tissue/studies/tsd_bench.h"
#include "tissue/studies/tsd_error.h"

namespace tissue::sim_app {
namespace {

struct BenchOptions {
  std::string mesh;
  float scale = 1.0f;  // mm per file unit
  int width = 320;     // pixels
  int height = 200;    // pixels
  int mapSize = 256;   // T_max, texels
  int gaussians = 6;
  int repeats = 3;
  std::string chart;          // PNG of the speed-ups, optional
  std::string image;          // PNG of one optimised frame (16 organs, second distance), optional
  bool accuracyOnly = false;  // skip the speed-up table
};

constexpr auto& kObjects = studies::kTsdBenchObjects;
constexpr auto& kDistances = studies::kTsdBenchDistances;

double median(const std::vector<double>& v) {
  return summarizeSamples(v).median;
}

int run(const BenchOptions& o, const GlobalOptions& global) {
  const char* cmd = "tsd-bench";
  if (o.width <= 0 || o.height <= 0 || o.mapSize < 16 || o.repeats < 1)
    return fail(cmd, "--width, --height, --repeats must be positive and --map-size at least 16");
  const auto meshPath = o.mesh.empty() ? dataDir() / "meshes" / "liver.obj" : std::filesystem::path(o.mesh);
  auto organ = loadTsdOrgan(meshPath, o.scale);
  if (!organ) return fail(cmd, organ.error().message);
  auto gaussians = skinGaussians(o.gaussians);
  if (!gaussians) return fail(cmd, gaussians.error().message);
  // The GL context lives in this scope only: VTK's chart needs its own (GLX) context afterwards.
  std::optional<nlohmann::json> glInfo;
  nlohmann::json speedup = nlohmann::json::array(), plainMs = nlohmann::json::array(),
                 optimisedMs = nlohmann::json::array();
  std::vector<inspect::ChartSeries> series;
  nlohmann::json accuracy{{"rows", nlohmann::json::array()}};
  float size = 0.0f;
  Stopwatch total;
  {
    auto context = createAppContext({}, false);
    if (!context) return fail(cmd, context.error().message);
    auto renderer = render::Renderer::create(
        (*context)->procAddressFunction(),
        {.shaders = shaderSettingsFromEnvironment(), .samples = 0, .gpuTimers = false});
    if (!renderer) return fail(cmd, renderer.error().message);
    // The row of organs (studies::uploadOrganRow), 1.1 organ widths apart.
    auto row = studies::uploadOrganRow(*renderer, *organ);
    if (!row) return fail(cmd, row.error().message);
    size = row->sizeMm;
    render::TextureSpaceSettings plain, optimised;
    plain.gaussians = optimised.gaussians = *gaussians;
    plain.mapSize = optimised.mapSize = o.mapSize;
    plain.cull = plain.clip = plain.depthSize = false;
    // The middle `n` organs with `method`; the camera's target is their centre.
    auto sceneOf = [&](int n, float distance, const render::TextureSpaceSettings& method) {
      return row->sceneOf(n, distance, method);
    };
    for (int objects : kObjects) {
      if (o.accuracyOnly) break;
      nlohmann::json rowS = nlohmann::json::array(), rowP = nlohmann::json::array(),
                     rowO = nlohmann::json::array();
      inspect::ChartSeries line{
          std::to_string(objects) + (objects == 1 ? " organ" : " organs"), {}, {}, true};
      for (float k : kDistances) {
        std::vector<double> tp, to;
        for (int rep = 0; rep <= o.repeats; ++rep) {  // repeat 0 warms up (allocations, shaders)
          for (const auto* s : {&plain, &optimised}) {
            const render::Scene scene = sceneOf(objects, k * size, *s);
            Stopwatch watch;
            auto image = renderer->renderImage(scene, o.width, o.height);
            if (!image) return fail(cmd, image.error().message);
            if (rep > 0) (s == &plain ? tp : to).push_back(watch.elapsedMs());
            if (!o.image.empty() && s == &optimised && objects == 16 && k == kDistances[1] && rep == 0)
              if (auto w = writePng(o.image, *image); !w) return fail(cmd, w.error().message);
          }
        }
        const double p = median(tp), q = median(to);
        rowS.push_back(p / q), rowP.push_back(p), rowO.push_back(q);
        line.x.push_back(double(k)), line.y.push_back(p / q);
      }
      speedup.push_back(rowS), plainMs.push_back(rowP), optimisedMs.push_back(rowO);
      series.push_back(line);
    }
    // Accuracy: one organ at the first distance. The reference convolves the unoptimised
    // frame's irradiance (read back) over the surface with the six-term skin profile (the
    // material's own); each setting's diffused map is compared with it at its texels' positions.
    {
      render::TextureSpaceSettings six = plain;
      six.gaussians = *skinGaussians(6);
      if (auto r = renderer->renderImage(sceneOf(1, kDistances[0] * size, six), o.width, o.height); !r)
        return fail(cmd, r.error().message);
      auto full = renderer->readTextureSpaceMaps();
      if (!full) return fail(cmd, full.error().message);
      const render::SurfaceSamples samples = studies::surfaceSamplesOf(*full);
      float cutoff = 0.0f;
      const auto table = skinProfileTable(six.gaussians, cutoff);
      accuracy["reference_texels"] = samples.positionMm.size();
      double referenceMs = 0.0;
      for (int n : {2, 4, 6}) {
        auto g = skinGaussians(n);
        if (!g) return fail(cmd, g.error().message);
        for (bool on : {false, true}) {
          render::TextureSpaceSettings s = on ? optimised : plain;
          s.gaussians = *g;
          const render::Scene scene = sceneOf(1, kDistances[0] * size, s);
          std::vector<double> ms;
          for (int rep = 0; rep <= o.repeats; ++rep) {
            Stopwatch watch;
            if (auto image = renderer->renderImage(scene, o.width, o.height); !image)
              return fail(cmd, image.error().message);
            if (rep > 0) ms.push_back(watch.elapsedMs());
          }
          auto maps = renderer->readTextureSpaceMaps();
          if (!maps) return fail(cmd, maps.error().message);
          const Stopwatch referenceWatch;
          const studies::TexelError error = studies::diffusedMapError(*maps, samples, table, cutoff);
          referenceMs += referenceWatch.elapsedMs();
          accuracy["rows"].push_back({{"setting", std::to_string(n) + "-gaussians"},
                                      {"optimised", on},
                                      {"ms", median(ms)},
                                      {"map_size", maps->size},
                                      {"texel_rms", error.rms},
                                      {"relative_rms", error.relative},
                                      {"interior_relative_rms", error.interiorRelative}});
        }
      }
      accuracy["reference_ms"] = referenceMs;
    }
    glInfo = nlohmann::json{{"gl_renderer", (*context)->info().renderer}};
  }
  if (!o.chart.empty() && !series.empty()) {
    const inspect::ChartSettings cs{"Texture-space diffusion: speed-up of the three optimisations (llvmpipe)",
                                    "camera distance to the middle organ (organ diagonals)",
                                    "speed-up (unoptimised ms / optimised ms)",
                                    true,
                                    false,
                                    900,
                                    600};
    if (auto r = inspect::writeLineChart(o.chart, cs, series); !r) return fail(cmd, r.error().message);
  }
  nlohmann::json out;
  out["objects"] = kObjects;
  nlohmann::json distances = nlohmann::json::array();
  for (float k : kDistances)
    distances.push_back(k * size);
  out["distances"] = distances;
  out["distances_in_organ_sizes"] = kDistances;
  out["speedup"] = speedup;
  out["unoptimised_ms"] = plainMs;
  out["optimised_ms"] = optimisedMs;
  out["accuracy"] = accuracy;
  out["organ_size_mm"] = size;
  out["mesh"] = meshPath.string();
  out["atlas"] = organ->atlas;
  out["triangles"] = organ->mesh.triangles.size();
  out["width"] = o.width;
  out["height"] = o.height;
  out["map_size"] = o.mapSize;
  out["gaussians"] = o.gaussians;
  out["repeats"] = o.repeats;
  out["renderer"] =
      "the render pipeline (texture-space method), whole frames with composite, tone map and readback";
  out["gl_renderer"] = (*glInfo)["gl_renderer"];
  out["seconds"] = total.elapsedMs() * 1e-3;
  printResult(global, out);
  return 0;
}

}  // namespace

void registerTsdBenchCommand(CLI::App& app, const GlobalOptions& global, int& exitCode) {
  auto opts = std::make_shared<BenchOptions>();
  auto* cmd = app.add_subcommand("tsd-bench",
                                 "Jimenez et al. 2008 Table 1: speed-up of the optimised texture-space "
                                 "diffusion by organ count and distance");
  cmd->add_option("--mesh", opts->mesh,
                  "organ mesh (default data/meshes/liver.obj); no UVs: automatic atlas");
  cmd->add_option("--scale", opts->scale, "mm per file unit (default 1)");
  cmd->add_option("--width", opts->width, "image width, pixels (default 320)");
  cmd->add_option("--height", opts->height, "image height, pixels (default 200)");
  cmd->add_option("--map-size", opts->mapSize, "T_max, irradiance map texels (default 256)");
  cmd->add_option("--gaussians", opts->gaussians, "profile terms: 2, 4 or 6 (default 6)");
  cmd->add_option("--repeats", opts->repeats, "timed frames per cell and path (default 3; median)");
  cmd->add_option("--chart", opts->chart, "write the speed-ups as a line chart PNG");
  cmd->add_flag("--accuracy-only", opts->accuracyOnly, "only the accuracy rows (no speed-up table)");
  cmd->add_option("--image", opts->image, "write the optimised frame of 16 organs at the second distance");
  cmd->callback([opts, &global, &exitCode] { exitCode = run(*opts, global); });
}

}  // namespace tissue::sim_app
