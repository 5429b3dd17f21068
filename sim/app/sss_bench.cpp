#include "sss_bench.h"

#include <algorithm>

#include "sss_material.h"
#include "tissue/core/stopwatch.h"

namespace tissue::sim_app {
namespace {

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

}  // namespace

void dropPartialCoverage(std::vector<Float4>& diffuse, const render::FloatImage& radiance) {
  for (std::size_t i = 0; i < diffuse.size() && i < radiance.pixels.size(); ++i)
    if (radiance.pixels[i].w < 0.999f) diffuse[i].w = 0.0f;
}

Result<std::pair<double, double>> timeFrames(SssBenchContext& ctx, const std::string& passPrefix) {
  std::vector<double> frame, method;
  for (int i = 0; i <= ctx.frames; ++i) {
    Stopwatch watch;
    auto image = ctx.renderer->renderImage(ctx.scene, ctx.width, ctx.height);
    if (!image) return image.error();
    if (i == 0) continue;  // warm-up: allocations and shader caches
    frame.push_back(watch.elapsedMs());
    double sum = 0.0;
    for (const auto& p : ctx.renderer->lastTimings().passes)
      if (p.name.rfind(passPrefix, 0) == 0) sum += p.cpuMs;
    method.push_back(sum);
  }
  return std::pair{median(frame), median(method)};
}

Result<void> ensureReference(SssBenchContext& ctx) {
  if (!ctx.reference.empty()) return {};
  auto diffuse = ctx.renderer->readFrame(render::FrameView::Diffuse);
  if (!diffuse) return diffuse.error();
  auto position = ctx.renderer->readFrame(render::FrameView::Position);
  if (!position) return position.error();
  auto radiance = ctx.renderer->readFrame(render::FrameView::Radiance);
  if (!radiance) return radiance.error();
  ctx.diffuse = std::move(diffuse->pixels);
  ctx.position = std::move(position->pixels);
  dropPartialCoverage(ctx.diffuse, *radiance);
  auto convolved =
      reference::convolveScreen({ctx.width, ctx.height, ctx.diffuse, ctx.position}, ctx.profiles);
  if (!convolved) return convolved.error();
  ctx.reference = std::move(*convolved);
  return {};
}

Result<reference::ImageError> compareLastFrame(SssBenchContext& ctx) {
  auto blurred = ctx.renderer->readFrame(render::FrameView::BlurredDiffuse);
  if (!blurred) return blurred.error();
  return reference::compareWithReference({ctx.width, ctx.height, ctx.diffuse, ctx.position}, blurred->pixels,
                                         ctx.reference, ctx.profiles);
}

Result<std::vector<SssBenchRow>> separableBenchRows(SssBenchContext& ctx, nlohmann::json& skipped) {
  std::vector<SssBenchRow> rows;
  for (const char* model : {"svd", "preintegrated", "guided", "manual", "deon", "jimenez"}) {
    for (const int taps : {7, 11, 17, 25}) {
      auto material = makeSeparableMaterial(ctx.material, model, taps);
      if (!material) {
        skipped.push_back({{"method", "separable"},
                           {"setting", std::string(model) + "-" + std::to_string(taps)},
                           {"reason", material.error().message}});
        continue;
      }
      ctx.scene.objects.at(0).method = material->settings;
      auto ms = timeFrames(ctx, "separable:");
      if (!ms) return ms.error();
      if (auto r = ensureReference(ctx); !r) return r.error();
      auto error = compareLastFrame(ctx);
      if (!error) return error.error();
      rows.push_back(
          {"separable", material->kernelName, ms->first, ms->second, error->rms, error->relativeRms});
    }
  }
  return rows;
}

Result<std::vector<SssBenchRow>> textureSpaceBenchRows(SssBenchContext& ctx, nlohmann::json& skipped) {
  // The reference convolves a pre-blur (undiffused) frame: the separable rows' first frame.
  if (ctx.reference.empty())
    return Error{"texture-space rows need the reference of the separable rows; run those first"};
  std::vector<SssBenchRow> rows;
  for (const int n : {2, 4, 6}) {
    const std::string setting = std::to_string(n) + "-gaussians";
    auto settings = makeTextureSpaceSettings(ctx.material, n);
    if (!settings) {
      skipped.push_back(
          {{"method", "texture-space"}, {"setting", setting}, {"reason", settings.error().message}});
      continue;
    }
    ctx.scene.objects.at(0).method = *settings;
    auto ms = timeFrames(ctx, "texture-space:");
    if (!ms) return ms.error();
    auto error = compareLastFrame(ctx);
    if (!error) return error.error();
    rows.push_back({"texture-space", setting, ms->first, ms->second, error->rms, error->relativeRms});
  }
  return rows;
}

}  // namespace tissue::sim_app
