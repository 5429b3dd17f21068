// The SSS bench (sss_bench.h): timing and the reference comparison of every method setting.
#include "tissue/studies/sss_bench.h"

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <utility>

#include "tissue/core/statistics.h"
#include "tissue/core/stopwatch.h"
#include "tissue/core/vec_math.h"
#include "tissue/materials/method_materials.h"
#include "tissue/scene/material_file.h"
#include "tissue/studies/coverage.h"
#include "tissue/studies/texture_space_organ.h"

namespace tissue::studies {
namespace {

double median(const std::vector<double>& v) {
  return summarizeSamples(v).median;
}

}  // namespace

Result<void> setUpSssBench(SssBenchContext& ctx, const scene::OrganAssets& organ) {
  ctx.material = scene::opticalMaterial(organ.material);
  auto truth = materials::makeSeparableMaterial(ctx.material, "preintegrated", 17);
  if (!truth) return truth.error();
  ctx.profiles = {reference::RadialProfile{}, truth->truth};
  if (!organ.mesh.hasUvs()) return Error{"the SSS bench needs an organ with UVs"};
  const TsdOrgan o = tsdOrganOf(organ.mesh);
  auto handle = ctx.renderer->createMesh(o.arrays());
  if (!handle) return handle.error();
  render::SceneObject object;
  object.mesh = *handle;
  for (auto [image, slot] :
       {std::pair{&organ.baseColor, &object.baseColor}, std::pair{&organ.normalMap, &object.normalMap}}) {
    if (!image->has_value()) continue;
    auto texture = ctx.renderer->createTexture(**image);
    if (!texture) return texture.error();
    *slot = *texture;
  }
  ctx.scene.lights[0].castsShadows = true;
  ctx.scene.objects = {object};
  ctx.scene.camera = render::frameBoundingBox(o.lo, o.hi, float(ctx.width) / float(ctx.height));
  const Float3 c{(o.lo.x + o.hi.x) / 2, (o.lo.y + o.hi.y) / 2, (o.lo.z + o.hi.z) / 2};
  ctx.scene.lights[0].positionMm = {c.x + 150.0f, c.y + 200.0f, o.hi.z + 300.0f};
  return {};
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
  // With MSAA, silhouette pixels hold one real surface sample (the separable resolve), so the
  // reference convolves them too.
  ctx.diffuse = std::move(diffuse->pixels);
  ctx.position = std::move(position->pixels);
  auto convolved =
      reference::convolveScreen({ctx.width, ctx.height, ctx.diffuse, ctx.position}, ctx.profiles);
  if (!convolved) return convolved.error();
  ctx.reference = std::move(*convolved);
  return {};
}

Result<reference::ImageError> compareLastFrame(SssBenchContext& ctx) {
  auto blurred = ctx.renderer->readFrame(render::FrameView::BlurredDiffuse);
  if (!blurred) return blurred.error();
  auto radiance = ctx.renderer->readFrame(render::FrameView::Radiance);
  if (!radiance) return radiance.error();
  studies::removeCoverageWeight(blurred->pixels, *radiance);
  return reference::compareWithReference({ctx.width, ctx.height, ctx.diffuse, ctx.position}, blurred->pixels,
                                         ctx.reference, ctx.profiles);
}

Result<ReferenceError> lastFrameReferenceError(render::Renderer& renderer, const render::FloatImage& diffuse,
                                               const render::FloatImage& position,
                                               const reference::RadialProfile& truth) {
  auto blurred = renderer.readFrame(render::FrameView::BlurredDiffuse);
  if (!blurred) return blurred.error();
  auto radiance = renderer.readFrame(render::FrameView::Radiance);
  if (!radiance) return radiance.error();
  std::vector<Float4> pre = diffuse.pixels;
  dropPartialCoverage(pre, *radiance);  // MSAA silhouettes are not surface points
  const reference::ScreenBuffers frame{diffuse.width, diffuse.height, pre, position.pixels};
  const std::vector<reference::RadialProfile> profiles{{}, truth};
  Stopwatch watch;
  auto exact = reference::convolveScreen(frame, profiles);
  if (!exact) return exact.error();
  ReferenceError out;
  out.referenceMs = watch.elapsedMs();
  const auto e = reference::compareWithReference(frame, blurred->pixels, *exact, profiles);
  out.imageRms = e.rms;
  out.relativeRms = e.relativeRms;
  return out;
}

namespace {

// One separable row: kernel `model` with `taps` taps and `rank` components, timed and compared.
Result<void> separableRow(SssBenchContext& ctx, const char* model, int taps, int rank,
                          std::vector<SssBenchRow>& rows, std::vector<SssBenchSkip>& skipped) {
  auto material = materials::makeSeparableMaterial(ctx.material, model, taps, rank);
  if (!material) {
    skipped.push_back(
        {"separable",
         std::string(model) + (rank > 1 ? std::to_string(rank) : "") + "-" + std::to_string(taps),
         material.error().message});
    return {};
  }
  ctx.scene.objects.at(0).method = material->settings;
  auto ms = timeFrames(ctx, "separable:");
  if (!ms) return ms.error();
  if (auto r = ensureReference(ctx); !r) return r.error();
  auto error = compareLastFrame(ctx);
  if (!error) return error.error();
  rows.push_back({"separable", material->kernelName, ms->first, ms->second, error->rms, error->relativeRms});
  return {};
}

}  // namespace

Result<std::vector<SssBenchRow>> separableBenchRows(SssBenchContext& ctx,
                                                    std::vector<SssBenchSkip>& skipped) {
  std::vector<SssBenchRow> rows;
  for (const char* model : {"svd", "preintegrated", "guided", "manual", "deon", "jimenez"}) {
    for (const int taps : {7, 11, 17, 25}) {
      if (auto r = separableRow(ctx, model, taps, 1, rows, skipped); !r) return r.error();
    }
  }
  // Rank-R kernels (Freude eq. 5.10): SVD ranks 2 and 3, d'Eon's sum of 2 and 4 Gaussians, each
  // component two more 1D passes.
  for (const auto& [model, rank] :
       {std::pair{"svd", 2}, std::pair{"svd", 3}, std::pair{"deon", 2}, std::pair{"deon", 4}}) {
    for (const int taps : {11, 17}) {
      if (auto r = separableRow(ctx, model, taps, rank, rows, skipped); !r) return r.error();
    }
  }
  return rows;
}

Result<std::vector<SssBenchRow>> textureSpaceBenchRows(SssBenchContext& ctx,
                                                       std::vector<SssBenchSkip>& skipped) {
  // The reference convolves a pre-blur (undiffused) frame: the separable rows' first frame.
  if (ctx.reference.empty())
    return Error{"texture-space rows need the reference of the separable rows; run those first"};
  std::vector<SssBenchRow> rows;
  for (const int n : {2, 4, 6}) {
    const std::string setting = std::to_string(n) + "-gaussians";
    auto settings = materials::makeTextureSpaceSettings(ctx.material, n);
    if (!settings) {
      skipped.push_back({"texture-space", setting, settings.error().message});
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

Result<SssBenchResult> runSssBench(render::Renderer& renderer, const scene::OrganSource& source,
                                   const SssBenchConfig& config) {
  const std::string mesh = source.mesh.string();
  if (config.width <= 0 || config.height <= 0 || config.frames <= 0)
    return Error{"the SSS bench needs a positive width, height and frame count"};
  scene::OrganSource own = source;
  own.uvAtlasFallback = false;  // the base colour and normal map belong to the file's UVs
  auto organ = scene::loadOrganAssets(own);
  if (!organ) {
    if (!std::filesystem::is_regular_file(own.material))
      return Error{"material for " + mesh + ": " + organ.error().message};
    return Error{mesh + ": " + organ.error().message};
  }
  SssBenchContext ctx;
  ctx.renderer = &renderer;
  ctx.width = config.width;
  ctx.height = config.height;
  ctx.frames = config.frames;
  if (auto r = setUpSssBench(ctx, *organ); !r) return Error{mesh + ": " + r.error().message};
  SssBenchResult out;
  for (const SssBenchMethod& method : kSssBenchMethods) {
    auto rows = method.rows(ctx, out.skipped);
    if (!rows) return Error{std::string(method.name) + ": " + rows.error().message};
    out.rows.insert(out.rows.end(), rows->begin(), rows->end());
  }
  nlohmann::json results = nlohmann::json::array(), skipped = nlohmann::json::array();
  Table table{{"method", "setting", "ms", "method ms", "image RMS", "relative RMS"}, {}};
  for (const SssBenchRow& r : out.rows) {
    results.push_back({{"method", r.method},
                       {"setting", r.setting},
                       {"ms", r.ms},
                       {"method_ms", r.methodMs},
                       {"image_rms", r.imageRms},
                       {"relative_rms", r.relativeRms}});
    table.rows.push_back({r.method, r.setting, fixed(r.ms, 2), fixed(r.methodMs, 2), general(r.imageRms, 4),
                          fixed(r.relativeRms, 4)});
  }
  for (const SssBenchSkip& skip : out.skipped)
    skipped.push_back({{"method", skip.method}, {"setting", skip.setting}, {"reason", skip.reason}});
  const char* referenceText =
      "exact screen-space convolution with the normalised dipole profile (tissue::reference)";
  const nlohmann::json json{{"mesh", mesh},
                            {"material", ctx.material.name},
                            {"width", config.width},
                            {"height", config.height},
                            {"frames", config.frames},
                            {"samples", config.samples},
                            {"gl_renderer", config.glRenderer},
                            {"reference", referenceText},
                            {"results", results},
                            {"skipped", skipped}};
  out.output.json = json.dump(2);
  out.output.summary = markdownTable(table);
  std::string md = "# SSS bench: " + mesh + " (" + ctx.material.name + ")\n\n" +
                   std::to_string(config.width) + " x " + std::to_string(config.height) + " pixels, " +
                   std::to_string(config.frames) + " frames per setting (median), MSAA " +
                   std::to_string(config.samples) + ", " + config.glRenderer +
                   ". Reference: " + referenceText + ".\n\n" + out.output.summary;
  if (!out.skipped.empty()) {
    Table skips{{"method", "setting", "skipped because"}, {}};
    for (const SssBenchSkip& skip : out.skipped)
      skips.rows.push_back({skip.method, skip.setting, skip.reason});
    md += "\n" + markdownTable(skips);
  }
  out.output.report.add("sss_bench.md", std::move(md));
  out.output.report.add("sss_bench.csv", csvTable(table));
  out.output.report.add("sss_bench.json", out.output.json + "\n");
  return out;
}

}  // namespace tissue::studies
