// tissue-sim raymarch-bench: the render pipeline's ray-march method at 10, 25, 50 and 100
// samples and adaptive, each timed (its "ray-march" pass) and compared with the CPU reference
// (mesh mode, many samples), after François et al. 2006 Table 2. Also the error of the plane
// approximation and the agreement of the method with its CPU twin in linear radiance.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "command.h"
#include "gl_environment.h"
#include "output.h"
#include "raymarch_scene.h"
#include "tissue/context/headless_context.h"
#include "tissue/core/stopwatch.h"
#include "tissue/inspect/chart.h"
#include "tissue/studies/raymarch_bench.h"

namespace tissue::sim_app {
namespace {

struct BenchOptions {
  std::string mesh;
  int width = 240;             // pixels
  int height = 180;            // pixels
  int referenceSamples = 200;  // CPU reference samples per pixel
  int repeats = 7;             // frames timed per setting (median)
  float pokeDepthMm = 8.0f;    // mm; 0 = undeformed
  bool closeUp = true;
  std::string images;                 // folder for the images, empty = none
  std::string chart;                  // PNG of error against frame time, empty = none
  render::RayMarchSettings adaptive;  // its adaptive-quality fields
};

int run(BenchOptions o, const GlobalOptions& global) {
  const char* cmd = "raymarch-bench";
  if (o.mesh.empty()) o.mesh = (dataDir() / "meshes" / "liver.obj").string();
  if (o.width <= 0 || o.height <= 0 || o.referenceSamples < 1 || o.repeats < 1)
    return fail(cmd, "--width, --height, --reference-samples and --repeats must be positive");
  auto loaded = loadRayMarchScene(o.mesh, float(o.width) / float(o.height), o.closeUp);
  if (!loaded) return fail(cmd, loaded.error().message);
  RayMarchScene& scene = *loaded;
  if (o.pokeDepthMm > 0.0f) {
    if (auto poked = pokeScene(scene, 0.02, o.pokeDepthMm); !poked) return fail(cmd, poked.error().message);
  }
  // Step 1: the CPU reference: light entry on the actual mesh, midpoint rule, no early stop.
  subsurface::CpuImageSettings ref;
  ref.width = o.width;
  ref.height = o.height;
  ref.entry = subsurface::EntryMode::Mesh;
  ref.jitter = false;
  ref.march.samples = o.referenceSamples;
  ref.march.attenuationThreshold = 0.0f;
  Stopwatch refClock;
  const auto reference = subsurface::renderSingleScatteringCpu(meshView(scene), scene.material.stack,
                                                               scene.lights, pinholeOf(scene.camera), ref);
  const double referenceMs = refClock.elapsedMs();
  const Image8 referenceImage = subsurface::toDisplay(reference, kRayMarchRadianceScale, kRayMarchBackground);
  // Step 2: the same with the fitted planes: what the plane approximation costs in accuracy.
  ref.entry = subsurface::EntryMode::Planes;
  const auto planesOnly = subsurface::renderSingleScatteringCpu(meshView(scene), scene.material.stack,
                                                                scene.lights, pinholeOf(scene.camera), ref);
  const Image8 planesImage = subsurface::toDisplay(planesOnly, kRayMarchRadianceScale, kRayMarchBackground);
  // Step 3: the pipeline's ray-march method at each setting.
  auto context = createAppContext({}, false);
  if (!context) return fail(cmd, context.error().message);
  render::RendererSettings rendererSettings;
  rendererSettings.shaders = shaderSettingsFromEnvironment();
  rendererSettings.finishPasses = true;  // the ray-march pass is timed to completion
  auto gpu = makeRayMarchRender(scene, (*context)->procAddressFunction(), rendererSettings);
  if (!gpu) return fail(cmd, gpu.error().message);
  nlohmann::json results = nlohmann::json::array();
  Image8 hundredImage;
  std::vector<Float3> hundred;
  double hundredMs = 0.0;
  std::vector<std::uint8_t> mask;
  auto timings = studies::timeRayMarchSettings(*gpu, o.adaptive, o.width, o.height, o.repeats);
  if (!timings) return fail(cmd, timings.error().message);
  for (std::size_t k = 0; k < std::size(studies::kRayMarchBenchSettings); ++k) {
    const int n = studies::kRayMarchBenchSettings[k];
    gpu->setMarch(studies::rayMarchBenchSetting(n, o.adaptive));
    auto image = gpu->render(o.width, o.height);
    if (!image) return fail(cmd, image.error().message);
    auto radiance = studies::readRayMarchRadiance(gpu->renderer, reference.covered);
    if (!radiance) return fail(cmd, radiance.error().message);
    if (mask.empty()) mask = radiance->mask;  // one mask for every row: the first frame's coverage
    nlohmann::json row;
    row["setting"] = n == 0 ? "adaptive" : std::to_string(n);
    row["ms"] = (*timings)[k].ms;
    row["gpu_ms"] = (*timings)[k].gpuMs;
    row["image_rms"] = subsurface::displayRms(*image, referenceImage, mask);
    row["radiance_rel_rms"] = subsurface::relativeRadianceRms(radiance->radiance, reference.radiance, mask);
    if (n == 100) hundredImage = *image, hundred = radiance->radiance, hundredMs = (*timings)[k].ms;
    if (n == 0) {
      auto samples = studies::meanSamples(*gpu, o.width, o.height, mask);
      if (!samples) return fail(cmd, samples.error().message);
      row["samples"] = samples->mean;
      if (!o.images.empty())
        (void)writePng(std::filesystem::path(o.images) / "raymarch_samples.png", samples->image);
      row["rms_vs_100"] = subsurface::displayRms(*image, hundredImage, mask);
      row["radiance_rel_rms_vs_100"] = subsurface::relativeRadianceRms(radiance->radiance, hundred, mask);
      row["ms_ratio_vs_100"] = hundredMs > 0.0 ? (*timings)[k].ms / hundredMs : -1.0;
    } else {
      row["samples"] = n;
    }
    if (!o.images.empty())
      (void)writePng(
          std::filesystem::path(o.images) / ("raymarch_" + row["setting"].get<std::string>() + ".png"),
          *image);
    results.push_back(row);
  }
  // Step 4: the method against its CPU twin (plane mode, same jitter and sample count), in
  // linear radiance.
  subsurface::CpuImageSettings twin = ref;
  twin.jitter = true;
  twin.march = {};
  twin.march.samples = 50;
  const auto cpu50 = subsurface::renderSingleScatteringCpu(meshView(scene), scene.material.stack,
                                                           scene.lights, pinholeOf(scene.camera), twin);
  render::RayMarchSettings s50;
  s50.radianceScale = kRayMarchRadianceScale;
  gpu->setMarch(s50);
  auto gpu50 = gpu->render(o.width, o.height);
  if (!gpu50) return fail(cmd, gpu50.error().message);
  auto radiance50 = studies::readRayMarchRadiance(gpu->renderer, reference.covered);
  if (!radiance50) return fail(cmd, radiance50.error().message);
  if (!o.images.empty()) {
    const std::filesystem::path dir = o.images;
    (void)writePng(dir / "raymarch_reference.png", referenceImage);
    (void)writePng(dir / "raymarch_planes_reference.png", planesImage);
    (void)writePng(dir / "raymarch_cpu_model_50.png",
                   subsurface::toDisplay(cpu50, kRayMarchRadianceScale, kRayMarchBackground));
    (void)writePng(dir / "raymarch_gpu_50.png", *gpu50);
  }
  const std::string glRenderer = (*context)->info().renderer;
  // Release GL before charting: VTK draws through GLX, which refuses to share the process's
  // current EGL context (X error BadAccess on glXMakeCurrent, Mesa 22.3).
  gpu = Error{"released"};
  context->reset();
  nlohmann::json out;
  out["mesh"] = o.mesh;
  out["width"] = o.width;
  out["height"] = o.height;
  out["poke_depth_mm"] = o.pokeDepthMm;
  out["repeats"] = o.repeats;
  out["gl_renderer"] = glRenderer;
  out["reference"] = {{"samples", o.referenceSamples}, {"entry", "mesh"}, {"cpu_ms", referenceMs}};
  out["results"] = results;
  out["plane_approximation_rms"] = subsurface::displayRms(planesImage, referenceImage, mask);
  out["plane_approximation_radiance_rel_rms"] =
      subsurface::relativeRadianceRms(planesOnly.radiance, reference.radiance, mask);
  out["gpu_vs_cpu_model_radiance_rel_rms_50"] =
      subsurface::relativeRadianceRms(radiance50->radiance, cpu50.radiance, radiance50->mask);
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
        "ray-march pass time (ms)",
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
    std::printf("%-10s %8s %10s %10s %12s\n", "setting", "samples", "ms", "image_rms", "radiance_rel");
    for (const auto& r : results)
      std::printf("%-10s %8.1f %10.2f %10.4f %12.4f\n", r["setting"].get<std::string>().c_str(),
                  r["samples"].get<double>(), r["ms"].get<double>(), r["image_rms"].get<double>(),
                  r["radiance_rel_rms"].get<double>());
    const auto& a = results.back();
    std::printf("adaptive: %.3f of the 100-sample time, rms %.4f (radiance %.4f) from the 100-sample image\n",
                a["ms_ratio_vs_100"].get<double>(), a["rms_vs_100"].get<double>(),
                a["radiance_rel_rms_vs_100"].get<double>());
    std::printf(
        "plane approximation rms %.4f; GPU vs CPU model (50 samples) radiance rms %.4f; reference %.0f ms\n",
        out["plane_approximation_rms"].get<double>(),
        out["gpu_vs_cpu_model_radiance_rel_rms_50"].get<double>(), referenceMs);
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
  cmd->add_option("--repeats", o->repeats, "timed frames per setting, median (default 7)");
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
