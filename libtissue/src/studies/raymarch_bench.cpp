// The ray-march bench's measurements (raymarch_bench.h).
#include "tissue/studies/raymarch_bench.h"

#include <algorithm>
#include <cmath>

#include "tissue/core/statistics.h"

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

}  // namespace tissue::studies
