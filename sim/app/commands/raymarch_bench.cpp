// tissue-sim raymarch-bench: ray-marched single scattering on the GPU at 10, 25, 50 and 100
// samples and adaptive, each timed and compared with the CPU reference (mesh mode, many
// samples), after François et al. 2006 Table 2. Also the error of the plane approximation
// and the agreement of the shader with its CPU twin.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "command.h"
#include "output.h"
#include "raymarch_scene.h"
#include "tissue/context/headless_context.h"
#include "tissue/core/stopwatch.h"
#include "tissue/inspect/chart.h"

namespace tissue::sim_app {
namespace {

struct BenchOptions {
  std::string mesh;
  int width = 240;             // pixels
  int height = 180;            // pixels
  int referenceSamples = 200;  // CPU reference samples per pixel
  int repeats = 3;             // GPU frames timed per setting (median)
  float pokeDepthMm = 8.0f;    // mm; 0 = undeformed
  bool closeUp = true;
  std::string images;                       // folder for the images, empty = none
  std::string chart;                        // PNG of error against frame time, empty = none
  render::RayMarchRenderSettings adaptive;  // its adaptive-quality fields
};

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

// Mean of the samples-per-pixel image (grey = samples / 100) over covered pixels.
double meanSamples(const Image8& shown, std::span<const std::uint8_t> covered) {
  double sum = 0.0;
  std::size_t n = 0;
  for (int y = 0; y < shown.height; ++y)
    for (int x = 0; x < shown.width; ++x)
      if (covered[std::size_t(y) * shown.width + x]) sum += shown.at(x, y)[0] * 100.0 / 255.0, ++n;
  return n ? sum / double(n) : 0.0;
}

// Pixels both the CPU ray cast and the GPU rasteriser cover: silhouette pixels that only one
// of them covers would compare tissue with background and swamp the figures.
std::vector<std::uint8_t> commonCoverage(std::span<const std::uint8_t> cpu, const Image8& gpu,
                                         Float3 background) {
  std::vector<std::uint8_t> mask(cpu.begin(), cpu.end());
  const int bg[3] = {int(std::lround(background.x * 255.0f)), int(std::lround(background.y * 255.0f)),
                     int(std::lround(background.z * 255.0f))};
  for (int y = 0; y < gpu.height; ++y)
    for (int x = 0; x < gpu.width; ++x) {
      const std::uint8_t* p = gpu.at(x, y);
      if (p[0] == bg[0] && p[1] == bg[1] && p[2] == bg[2]) mask[std::size_t(y) * gpu.width + x] = 0;
    }
  return mask;
}

int run(BenchOptions o, const GlobalOptions& global) {
  const char* cmd = "raymarch-bench";
  if (o.mesh.empty()) o.mesh = (dataDir() / "meshes" / "liver.obj").string();
  if (o.width <= 0 || o.height <= 0 || o.referenceSamples < 1 || o.repeats < 1)
    return fail(cmd, "--width, --height, --reference-samples and --repeats must be positive");
  auto loaded = loadRayMarchScene(o.mesh, float(o.width) / float(o.height), o.closeUp);
  if (!loaded) return fail(cmd, loaded.error().message);
  RayMarchScene& scene = *loaded;
  if (o.pokeDepthMm > 0.0f) pokeScene(scene, 0.02, o.pokeDepthMm);
  // Step 1: the CPU reference: light entry on the actual mesh, midpoint rule, no early stop.
  subsurface::CpuImageSettings ref;
  ref.width = o.width;
  ref.height = o.height;
  ref.entry = subsurface::EntryMode::Mesh;
  ref.jitter = false;
  ref.march.samples = o.referenceSamples;
  ref.march.attenuationThreshold = 0.0f;
  Stopwatch refClock;
  const auto reference = subsurface::renderSingleScatteringCpu(meshView(scene), scene.stack, scene.lights,
                                                               pinholeOf(scene.camera), ref);
  const double referenceMs = refClock.elapsedMs();
  const render::RayMarchRenderSettings base;
  const Image8 referenceImage = subsurface::toDisplay(reference, base.exposure, base.background);
  // Step 2: the same with the fitted planes: what the plane approximation costs in accuracy.
  ref.entry = subsurface::EntryMode::Planes;
  const auto planesOnly = subsurface::renderSingleScatteringCpu(meshView(scene), scene.stack, scene.lights,
                                                                pinholeOf(scene.camera), ref);
  const Image8 planesImage = subsurface::toDisplay(planesOnly, base.exposure, base.background);
  // Step 3: the GPU at each setting.
  auto context = context::createHeadlessContext({}, {.backend = "", .log = false});
  if (!context) return fail(cmd, context.error().message);
  auto renderer = makeRayMarchRenderer(scene, (*context)->procAddressFunction());
  if (!renderer) return fail(cmd, renderer.error().message);
  const auto lights = gpuLights(scene);
  nlohmann::json results = nlohmann::json::array();
  Image8 hundred;
  const int fixed[] = {10, 25, 50, 100, 0};
  for (int n : fixed) {
    render::RayMarchRenderSettings s = o.adaptive;
    s.samples = n;
    s.adaptive = n == 0;
    std::vector<double> ms;
    Image8 image;
    for (int r = 0; r < o.repeats + 1; ++r) {  // the first frame warms up (shader compile, allocation)
      auto frame = renderer->renderImage(scene.camera, lights, s, o.width, o.height);
      if (!frame) return fail(cmd, frame.error().message);
      if (r > 0) ms.push_back(renderer->lastDrawMs());
      image = std::move(*frame);
    }
    nlohmann::json row;
    row["setting"] = n == 0 ? "adaptive" : std::to_string(n);
    row["ms"] = median(ms);
    const auto mask = commonCoverage(reference.covered, image, s.background);
    row["image_rms"] = subsurface::displayRms(image, referenceImage, mask);
    if (n == 100) hundred = image;
    if (n == 0) {
      s.showSamples = true;
      auto shown = renderer->renderImage(scene.camera, lights, s, o.width, o.height);
      if (!shown) return fail(cmd, shown.error().message);
      row["samples"] = meanSamples(*shown, mask);
      row["rms_vs_100"] = subsurface::displayRms(image, hundred, mask);
      if (!o.images.empty()) (void)writePng(std::filesystem::path(o.images) / "raymarch_samples.png", *shown);
    } else {
      row["samples"] = n;
    }
    if (!o.images.empty())
      (void)writePng(
          std::filesystem::path(o.images) / ("raymarch_" + row["setting"].get<std::string>() + ".png"),
          image);
    results.push_back(row);
  }
  // Step 4: the shader against its CPU twin (plane mode, same jitter and sample count).
  subsurface::CpuImageSettings twin = ref;
  twin.jitter = true;
  twin.march = {};
  twin.march.samples = 50;
  const auto cpu50 = subsurface::renderSingleScatteringCpu(meshView(scene), scene.stack, scene.lights,
                                                           pinholeOf(scene.camera), twin);
  render::RayMarchRenderSettings s50;
  auto gpu50 = renderer->renderImage(scene.camera, lights, s50, o.width, o.height);
  if (!gpu50) return fail(cmd, gpu50.error().message);
  if (!o.images.empty()) {
    (void)writePng(std::filesystem::path(o.images) / "raymarch_reference.png", referenceImage);
    (void)writePng(std::filesystem::path(o.images) / "raymarch_planes_reference.png", planesImage);
    (void)writePng(std::filesystem::path(o.images) / "raymarch_cpu_model_50.png",
                   subsurface::toDisplay(cpu50, s50.exposure, s50.background));
    (void)writePng(std::filesystem::path(o.images) / "raymarch_gpu_50.png", *gpu50);
  }
  const std::string glRenderer = (*context)->info().renderer;
  // Release GL before charting: VTK draws through GLX, which refuses to share the process's
  // current EGL context (X error BadAccess on glXMakeCurrent, Mesa 22.3).
  renderer = Error{"released"};
  context->reset();
  nlohmann::json out;
  out["mesh"] = o.mesh;
  out["width"] = o.width;
  out["height"] = o.height;
  out["poke_depth_mm"] = o.pokeDepthMm;
  out["gl_renderer"] = glRenderer;
  out["reference"] = {{"samples", o.referenceSamples}, {"entry", "mesh"}, {"cpu_ms", referenceMs}};
  out["results"] = results;
  const auto mask = commonCoverage(reference.covered, *gpu50, s50.background);
  out["plane_approximation_rms"] = subsurface::displayRms(planesImage, referenceImage, mask);
  out["gpu_vs_cpu_model_rms_50"] =
      subsurface::displayRms(*gpu50, subsurface::toDisplay(cpu50, s50.exposure, s50.background), mask);
  if (!o.chart.empty()) {
    // Error against cost (François Table 2 as a curve): fixed counts as a line, adaptive a point.
    inspect::ChartSeries fixedSeries{"10, 25, 50, 100 samples", {}, {}, true};
    inspect::ChartSeries adaptiveSeries{"adaptive", {}, {}, false};
    for (const auto& r : results) {
      auto& series = r["setting"] == "adaptive" ? adaptiveSeries : fixedSeries;
      series.x.push_back(r["ms"].get<double>());
      series.y.push_back(r["image_rms"].get<double>());
    }
    const inspect::ChartSeries both[] = {fixedSeries, adaptiveSeries};
    const inspect::ChartSettings settings{
        "Ray-marched single scattering: error against time (" + glRenderer + ")",
        "frame time (ms)",
        "RMS difference to the CPU reference (0..1)",
        true,
        true,
        900,
        600};
    if (auto r = inspect::writeLineChart(o.chart, settings, both); !r) return fail(cmd, r.error().message);
  }
  if (global.json) {
    printResult(global, out);
  } else {
    std::printf("%-10s %8s %10s %10s\n", "setting", "samples", "ms", "image_rms");
    for (const auto& r : results)
      std::printf("%-10s %8.1f %10.2f %10.4f\n", r["setting"].get<std::string>().c_str(),
                  r["samples"].get<double>(), r["ms"].get<double>(), r["image_rms"].get<double>());
    std::printf("plane approximation rms %.4f; GPU vs CPU model (50 samples) rms %.4f; reference %.0f ms\n",
                out["plane_approximation_rms"].get<double>(), out["gpu_vs_cpu_model_rms_50"].get<double>(),
                referenceMs);
  }
  return 0;
}

}  // namespace

void registerRayMarchBenchCommand(CLI::App& app, const GlobalOptions& global, int& exitCode) {
  auto o = std::make_shared<BenchOptions>();
  auto* cmd = app.add_subcommand("raymarch-bench",
                                 "time ray-marched subsurface scattering per sample count and adaptive, "
                                 "with the error against the CPU reference");
  cmd->add_option("--mesh", o->mesh, "a data/ mesh with a material file (default data/meshes/liver.obj)");
  cmd->add_option("--width", o->width, "image width, pixels (default 240)");
  cmd->add_option("--height", o->height, "image height, pixels (default 180)");
  cmd->add_option("--reference-samples", o->referenceSamples, "CPU reference samples (default 200)");
  cmd->add_option("--repeats", o->repeats, "timed GPU frames per setting, median (default 3)");
  cmd->add_option("--poke-depth", o->pokeDepthMm, "poke depth, mm (default 8; 0 = rest shape)");
  cmd->add_flag("!--whole", o->closeUp, "frame the whole organ instead of a close-up of the poke site");
  cmd->add_option("--depth-resolution", o->adaptive.depthResolutionMm,
                  "adaptive: wanted depth step, mm (default 0.06)");
  cmd->add_option("--texels-per-step", o->adaptive.texelsPerStep,
                  "adaptive: wanted sideways step, texels or pixels (default 1.5)");
  cmd->add_option("--cutoff", o->adaptive.cutoff,
                  "adaptive: round-trip transmittance where the march stops (default 0.03)");
  cmd->add_option("--min-samples", o->adaptive.minSamples, "adaptive: fewest samples (default 4)");
  cmd->add_option("--chart", o->chart, "PNG chart of error against frame time");
  cmd->add_option("--images", o->images, "folder to write the images into (must exist)");
  cmd->callback([o, &global, &exitCode] { exitCode = run(*o, global); });
}

}  // namespace tissue::sim_app
