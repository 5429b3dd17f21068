#include "raymarch_scene.h"

#include <algorithm>

#include "gl_environment.h"
#include "organ_data.h"
#include "output.h"

namespace tissue::sim_app {
namespace {

// Renders `scene` with ray-marched single scattering (`march`: the march and adaptive-quality
// fields) on a new headless context into `png`; what it did (ms, context).
Result<nlohmann::json> renderRayMarchPng(const studies::RayMarchScene& scene,
                                         const render::RayMarchSettings& march, int width, int height,
                                         const std::filesystem::path& png) {
  context::ContextRequest request;
  request.width = request.height = 16;  // the renderer draws into its own framebuffer
  auto context = createAppContext(request);
  if (!context) return context.error();
  // finishPasses: the ray-march pass is timed to completion.
  auto gpu = studies::makeRayMarchRender(scene, (*context)->procAddressFunction(),
                                         {.shaders = shaderSettingsFromEnvironment(), .finishPasses = true});
  if (!gpu) return gpu.error();
  gpu->setMarch(march);
  double passMs = 0.0;
  auto image = gpu->render(width, height, &passMs);
  if (!image) return image.error();
  if (auto w = writePng(png, *image); !w) return w.error();
  nlohmann::json out{{"out", png.string()},
                     {"pass_ms", passMs},
                     {"gl_renderer", (*context)->info().renderer},
                     {"adaptive", march.adaptive}};
  out[march.adaptive ? "max_samples" : "samples"] = march.adaptive ? march.maxSamples : march.samples;
  return out;
}

}  // namespace

int runRayMarchRender(const std::string& meshFile, const std::string& png, int width, int height, int samples,
                      bool adaptive, const GlobalOptions& global) {
  auto scene = studies::loadRayMarchScene(organSourceFor(meshFile), float(width) / float(height), false);
  if (!scene) return fail("render", scene.error().message);
  render::RayMarchSettings settings;
  settings.samples = std::clamp(samples, 1, 256);
  settings.adaptive = adaptive;
  settings.radianceScale = studies::kRayMarchRadianceScale;
  auto done = renderRayMarchPng(*scene, settings, width, height, png);
  if (!done) return fail("render", done.error().message);
  (*done)["method"] = "raymarch";
  printResult(global, *done);
  return 0;
}

nlohmann::json renderPokedOrganRayMarch(const mesh::DeformableSurface& surface,
                                        const scene::OrganAssets& organ, const std::filesystem::path& outDir,
                                        int width, int height) {
  nlohmann::json report = nlohmann::json::array();
  for (bool closeUp : {false, true}) {
    auto scene = studies::rayMarchSceneFor(surface, organ, float(width) / float(height), closeUp);
    if (!scene) return {{"skipped", scene.error().message}};
    // Adaptive quality: a quarter of the 100-sample cost (docs/RESULTS.md), so the main job stays quick.
    render::RayMarchSettings settings;
    settings.adaptive = true;
    settings.radianceScale = studies::kRayMarchRadianceScale;
    const std::string name = std::string("frame_poked_raymarch") + (closeUp ? "_closeup" : "") + ".png";
    auto done = renderRayMarchPng(*scene, settings, width, height, outDir / name);
    if (!done) return {{"skipped", done.error().message}};
    report.push_back(*done);
  }
  return report;
}

}  // namespace tissue::sim_app
