// The ray-march bench's measurements (raymarch_bench.h).
#include "tissue/studies/raymarch_bench.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "tissue/core/statistics.h"
#include "tissue/core/stopwatch.h"

namespace tissue::studies {
namespace {

double median(const std::vector<double>& v) {
  return v.empty() ? -1.0 : summarizeSamples(v).median;
}

}  // namespace

Result<GpuRadiance> readRayMarchRadiance(render::Renderer& renderer,
                                         std::span<const std::uint8_t> cpuCovered) {
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

render::RayMarchSettings rayMarchBenchSetting(int n, const render::RayMarchSettings& adaptive) {
  render::RayMarchSettings s = adaptive;
  s.samples = n;
  s.adaptive = n == 0;
  s.radianceScale = kRayMarchRadianceScale;
  return s;
}

Result<std::vector<RayMarchTiming>> timeRayMarchSettings(RayMarchRender& gpu,
                                                         const render::RayMarchSettings& adaptive, int width,
                                                         int height, int repeats) {
  const std::size_t count = std::size(kRayMarchBenchSettings);
  std::vector<std::vector<double>> ms(count), gpuMs(count);
  for (int r = 0; r < repeats + 1; ++r) {
    for (std::size_t k = 0; k < count; ++k) {
      gpu.setMarch(rayMarchBenchSetting(kRayMarchBenchSettings[k], adaptive));
      double pass = 0.0;
      if (auto frame = gpu.render(width, height, &pass); !frame) return frame.error();
      if (r == 0) continue;
      ms[k].push_back(pass);
      const render::PassTiming* t = gpu.renderer.lastTimings().find("ray-march");
      if (t && t->gpuMs >= 0.0) gpuMs[k].push_back(t->gpuMs);
    }
  }
  std::vector<RayMarchTiming> out;
  for (std::size_t k = 0; k < count; ++k)
    out.push_back({median(ms[k]), median(gpuMs[k])});
  return out;
}

namespace {

// The CPU model's image of `scene` with `settings`.
subsurface::RadianceImage cpuImage(const RayMarchScene& scene, const subsurface::CpuImageSettings& settings) {
  return subsurface::renderSingleScatteringCpu(meshView(scene), scene.material.stack, scene.lights,
                                               pinholeOf(scene.camera), settings);
}

Image8 display(const subsurface::RadianceImage& image) {
  return subsurface::toDisplay(image, kRayMarchRadianceScale, kRayMarchBackground);
}

StudyOutput rayMarchBenchOutput(const RayMarchBenchResult& r, const std::string& mesh,
                                const RayMarchBenchConfig& c) {
  nlohmann::json results = nlohmann::json::array();
  Table table{{"setting", "samples (mean)", "ms (ray-march pass)", "gpu_ms", "image_rms", "radiance_rel_rms"},
              {}};
  for (const RayMarchBenchRow& row : r.rows) {
    nlohmann::json j{{"setting", row.setting},    {"samples", row.samples},
                     {"ms", row.timing.ms},       {"gpu_ms", row.timing.gpuMs},
                     {"image_rms", row.imageRms}, {"radiance_rel_rms", row.radianceRelRms}};
    if (row.setting == "adaptive") {
      j["rms_vs_100"] = r.adaptiveRmsVs100;
      j["radiance_rel_rms_vs_100"] = r.adaptiveRadianceRelRmsVs100;
      j["ms_ratio_vs_100"] = r.adaptiveMsRatioVs100;
    }
    results.push_back(j);
    table.rows.push_back({row.setting, fixed(row.samples, 1), fixed(row.timing.ms, 1),
                          fixed(row.timing.gpuMs, 1), fixed(row.imageRms, 4), fixed(row.radianceRelRms, 3)});
  }
  Table paper{{"samples", "fish fps", "fish ms", "gecko fps", "gecko ms"}, {}};
  nlohmann::json paperJson{{"source", "François et al. 2006, Table 2 (800 x 600 pixels)"},
                           {"samples", kFrancoisTable2Samples},
                           {"fish_fps", kFrancoisTable2FishFps},
                           {"gecko_fps", kFrancoisTable2GeckoFps}};
  for (std::size_t i = 0; i < std::size(kFrancoisTable2Samples); ++i)
    paper.rows.push_back({std::to_string(kFrancoisTable2Samples[i]), fixed(kFrancoisTable2FishFps[i], 0),
                          fixed(1000.0 / kFrancoisTable2FishFps[i], 1), fixed(kFrancoisTable2GeckoFps[i], 0),
                          fixed(1000.0 / kFrancoisTable2GeckoFps[i], 1)});
  const nlohmann::json json{
      {"mesh", mesh},
      {"width", c.width},
      {"height", c.height},
      {"poke_depth_mm", c.pokeDepthMm},
      {"repeats", c.repeats},
      {"gl_renderer", c.glRenderer},
      {"reference", {{"samples", c.referenceSamples}, {"entry", "mesh"}, {"cpu_ms", r.referenceMs}}},
      {"results", results},
      {"plane_approximation_rms", r.planeRms},
      {"plane_approximation_radiance_rel_rms", r.planeRadianceRelRms},
      {"gpu_vs_cpu_model_radiance_rel_rms_50", r.gpuVsCpuModel50},
      {"paper", paperJson}};
  StudyOutput out;
  out.json = json.dump(2);
  char lines[400];
  std::snprintf(
      lines, sizeof lines,
      "adaptive: %.3f of the 100-sample time, rms %.4f (radiance %.4f) from the 100-sample image\n"
      "plane approximation rms %.4f; GPU vs CPU model (50 samples) radiance rms %.4f; reference %.0f ms\n",
      r.adaptiveMsRatioVs100, r.adaptiveRmsVs100, r.adaptiveRadianceRelRmsVs100, r.planeRms,
      r.gpuVsCpuModel50, r.referenceMs);
  out.summary = markdownTable(table) + lines;
  out.report.add(
      "raymarch_bench.md",
      "# Ray-marched single scattering: time and error by samples (after François et al. 2006 "
      "Table 2)\n\n" +
          mesh + ", " + std::to_string(c.width) + " x " + std::to_string(c.height) + " pixels, poked " +
          fixed(c.pokeDepthMm, 1) + " mm, median of " + std::to_string(c.repeats) + " frames, " +
          c.glRenderer + "; reference: the CPU march with the light entering through the mesh, " +
          std::to_string(c.referenceSamples) + " samples.\n\n" + out.summary +
          "\nFrançois et al. 2006, Table 2 (their renderer, 800 x 600 pixels):\n\n" + markdownTable(paper));
  out.report.add("raymarch_bench.csv", csvTable(table));
  out.report.add("raymarch_bench.json", out.json + "\n");
  if (c.chart) {
    // Error against cost (François Table 2 as a curve): fixed counts as a line, adaptive a point.
    ReportChart chart{
        "raymarch_error_vs_time.png",
        {"Ray-marched single scattering: error against time (" + c.glRenderer + ")",
         "ray-march pass time (ms)", "RMS difference to the CPU reference (0..1)", true, true, 900, 600},
        {{"10, 25, 50, 100 samples", {}, {}, true}, {"adaptive", {}, {}, false}}};
    for (const RayMarchBenchRow& row : r.rows) {
      auto& series = chart.series[row.setting == "adaptive" ? 1 : 0];
      series.x.push_back(row.timing.ms), series.y.push_back(row.imageRms);
    }
    out.report.charts.push_back(std::move(chart));
  }
  return out;
}

}  // namespace

Result<RayMarchBenchResult> runRayMarchBench(const gl::GetProcAddressFn& getProcAddress,
                                             render::RendererSettings settings,
                                             const scene::OrganSource& source, const RayMarchBenchConfig& c) {
  if (c.width <= 0 || c.height <= 0 || c.referenceSamples < 1 || c.repeats < 1)
    return Error{"the width, height, reference samples and repeats must be positive"};
  auto loaded = loadRayMarchScene(source, float(c.width) / float(c.height), c.closeUp);
  if (!loaded) return loaded.error();
  RayMarchScene& scene = *loaded;
  if (c.pokeDepthMm > 0.0f)
    if (auto poked = pokeScene(scene, 0.02, c.pokeDepthMm); !poked) return poked.error();
  RayMarchBenchResult out;
  std::vector<ReportImage> images;
  // Step 1: the CPU reference: light entry on the actual mesh, midpoint rule, no early stop.
  subsurface::CpuImageSettings ref;
  ref.width = c.width;
  ref.height = c.height;
  ref.entry = subsurface::EntryMode::Mesh;
  ref.jitter = false;
  ref.march.samples = c.referenceSamples;
  ref.march.attenuationThreshold = 0.0f;
  const Stopwatch refClock;
  const auto reference = cpuImage(scene, ref);
  out.referenceMs = refClock.elapsedMs();
  const Image8 referenceImage = display(reference);
  // Step 2: the same with the fitted planes: what the plane approximation costs in accuracy.
  ref.entry = subsurface::EntryMode::Planes;
  const auto planesOnly = cpuImage(scene, ref);
  const Image8 planesImage = display(planesOnly);
  // Step 3: the pipeline's ray-march method at each setting.
  settings.finishPasses = true;  // the ray-march pass is timed to completion
  auto gpu = makeRayMarchRender(scene, getProcAddress, settings);
  if (!gpu) return gpu.error();
  auto timings = timeRayMarchSettings(*gpu, c.adaptive, c.width, c.height, c.repeats);
  if (!timings) return timings.error();
  Image8 hundredImage;
  double hundredMs = 0.0;
  std::vector<Float3> hundred;
  std::vector<std::uint8_t> mask;  // one mask for every row: the first frame's coverage
  for (std::size_t k = 0; k < std::size(kRayMarchBenchSettings); ++k) {
    const int n = kRayMarchBenchSettings[k];
    gpu->setMarch(rayMarchBenchSetting(n, c.adaptive));
    auto image = gpu->render(c.width, c.height);
    if (!image) return image.error();
    auto radiance = readRayMarchRadiance(gpu->renderer, reference.covered);
    if (!radiance) return radiance.error();
    if (mask.empty()) mask = radiance->mask;
    RayMarchBenchRow row{n == 0 ? "adaptive" : std::to_string(n), double(n), (*timings)[k],
                         subsurface::displayRms(*image, referenceImage, mask),
                         subsurface::relativeRadianceRms(radiance->radiance, reference.radiance, mask)};
    if (n == 100) hundredImage = *image, hundred = radiance->radiance, hundredMs = row.timing.ms;
    if (n == 0) {
      auto samples = meanSamples(*gpu, c.width, c.height, mask);
      if (!samples) return samples.error();
      row.samples = samples->mean;
      if (c.images) images.push_back({"raymarch_samples.png", std::move(samples->image)});
      out.adaptiveRmsVs100 = subsurface::displayRms(*image, hundredImage, mask);
      out.adaptiveRadianceRelRmsVs100 = subsurface::relativeRadianceRms(radiance->radiance, hundred, mask);
      out.adaptiveMsRatioVs100 = hundredMs > 0.0 ? row.timing.ms / hundredMs : -1.0;
    }
    if (c.images) images.push_back({"raymarch_" + row.setting + ".png", std::move(*image)});
    out.rows.push_back(std::move(row));
  }
  // Step 4: the method against its CPU twin (plane mode, same jitter and sample count), in
  // linear radiance.
  subsurface::CpuImageSettings twin = ref;
  twin.jitter = true;
  twin.march = {};
  twin.march.samples = 50;
  const auto cpu50 = cpuImage(scene, twin);
  render::RayMarchSettings s50;
  s50.radianceScale = kRayMarchRadianceScale;
  gpu->setMarch(s50);
  auto gpu50 = gpu->render(c.width, c.height);
  if (!gpu50) return gpu50.error();
  auto radiance50 = readRayMarchRadiance(gpu->renderer, reference.covered);
  if (!radiance50) return radiance50.error();
  out.planeRms = subsurface::displayRms(planesImage, referenceImage, mask);
  out.planeRadianceRelRms = subsurface::relativeRadianceRms(planesOnly.radiance, reference.radiance, mask);
  out.gpuVsCpuModel50 =
      subsurface::relativeRadianceRms(radiance50->radiance, cpu50.radiance, radiance50->mask);
  out.output = rayMarchBenchOutput(out, source.mesh.string(), c);
  if (c.images) {
    images.push_back({"raymarch_reference.png", referenceImage});
    images.push_back({"raymarch_planes_reference.png", planesImage});
    images.push_back({"raymarch_cpu_model_50.png", display(cpu50)});
    images.push_back({"raymarch_gpu_50.png", std::move(*gpu50)});
    for (auto& i : images)
      out.output.report.images.push_back(std::move(i));
  }
  return out;
}

}  // namespace tissue::studies
