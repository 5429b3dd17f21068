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
#include "tissue/core/statistics.h"
#include "tissue/core/stopwatch.h"
#include "tissue/inspect/chart.h"

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

double median(const std::vector<double>& v) {
  return v.empty() ? -1.0 : summarizeSamples(v).median;
}

// The last frame's linear radiance divided by the method's scale, and the pixels both the CPU
// ray cast and the GPU rasteriser cover (silhouette pixels only one of them covers would compare
// tissue with background and swamp the figures).
struct GpuRadiance {
  std::vector<Float3> radiance;  // light units, rows top to bottom
  std::vector<std::uint8_t> mask;
};

Result<GpuRadiance> readRadiance(render::Renderer& renderer, std::span<const std::uint8_t> cpuCovered) {
  auto frame = renderer.readFrame(render::FrameView::Radiance);
  if (!frame) return frame.error();
  GpuRadiance out{{}, std::vector<std::uint8_t>(cpuCovered.begin(), cpuCovered.end())};
  for (std::size_t i = 0; i < frame->pixels.size(); ++i) {
    const Float4& p = frame->pixels[i];
    out.radiance.push_back(
        {p.x / kRayMarchRadianceScale, p.y / kRayMarchRadianceScale, p.z / kRayMarchRadianceScale});
    if (p.w <= 0.0f) out.mask[i] = 0;
  }
  return out;
}

// Mean samples per covered pixel: the samples-shown frame writes samples / 100 as radiance,
// also returned as a grey image (white = 100 samples; black where uncovered).
struct SampleCounts {
  double mean = 0.0;
  Image8 image;
};

Result<SampleCounts> meanSamples(RayMarchRender& gpu, int width, int height,
                                 std::span<const std::uint8_t> mask) {
  gpu.settings().showSamples = true;
  auto shown = gpu.render(width, height);
  gpu.settings().showSamples = false;
  if (!shown) return shown.error();
  auto frame = gpu.renderer.readFrame(render::FrameView::Radiance);
  if (!frame) return frame.error();
  SampleCounts out{0.0, Image8(width, height, 4)};
  std::size_t n = 0;
  for (std::size_t i = 0; i < mask.size(); ++i) {
    const double samples = std::round(double(frame->pixels[i].x) * 100.0);
    if (mask[i]) out.mean += samples, ++n;
    const auto grey = std::uint8_t(std::lround(std::clamp(samples / 100.0, 0.0, 1.0) * 255.0));
    std::uint8_t* px = out.image.at(int(i) % width, int(i) / width);
    px[0] = px[1] = px[2] = grey;
    px[3] = 255;
  }
  out.mean = n ? out.mean / double(n) : 0.0;
  return out;
}

// The settings of the table: 10, 25, 50, 100 samples and adaptive (0).
constexpr int kSettings[] = {10, 25, 50, 100, 0};

render::RayMarchSettings settingFor(int n, const render::RayMarchSettings& adaptive) {
  render::RayMarchSettings s = adaptive;
  s.samples = n;
  s.adaptive = n == 0;
  s.radianceScale = kRayMarchRadianceScale;
  return s;
}

// Times every setting: one warm-up frame each (allocation, shader caches), then `repeats`
// rounds of one frame per setting, interleaved so that a change in the machine's load falls on
// every setting alike. ms = median of the "ray-march" pass (CPU wall clock to completion,
// glFinish); gpu_ms = median of its timer query where valid (-1 if never).
struct Timing {
  double ms = 0.0, gpuMs = -1.0;
};

Result<std::vector<Timing>> timeSettings(RayMarchRender& gpu, const BenchOptions& o) {
  const std::size_t count = std::size(kSettings);
  std::vector<std::vector<double>> ms(count), gpuMs(count);
  for (int r = 0; r < o.repeats + 1; ++r) {
    for (std::size_t k = 0; k < count; ++k) {
      gpu.setMarch(settingFor(kSettings[k], o.adaptive));
      double pass = 0.0;
      if (auto frame = gpu.render(o.width, o.height, &pass); !frame) return frame.error();
      if (r == 0) continue;
      ms[k].push_back(pass);
      const render::PassTiming* t = gpu.renderer.lastTimings().find("ray-march");
      if (t && t->gpuMs >= 0.0) gpuMs[k].push_back(t->gpuMs);
    }
  }
  std::vector<Timing> out;
  for (std::size_t k = 0; k < count; ++k)
    out.push_back({median(ms[k]), median(gpuMs[k])});
  return out;
}

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
  auto timings = timeSettings(*gpu, o);
  if (!timings) return fail(cmd, timings.error().message);
  for (std::size_t k = 0; k < std::size(kSettings); ++k) {
    const int n = kSettings[k];
    gpu->setMarch(settingFor(n, o.adaptive));
    auto image = gpu->render(o.width, o.height);
    if (!image) return fail(cmd, image.error().message);
    auto radiance = readRadiance(gpu->renderer, reference.covered);
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
      auto samples = meanSamples(*gpu, o.width, o.height, mask);
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
  auto radiance50 = readRadiance(gpu->renderer, reference.covered);
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
