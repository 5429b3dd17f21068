// The demo's method renders of its poked organ through the scene module (demo_render.h).
#include "demo_render.h"

#include "pass_timings_json.h"
#include "tissue/core/image.h"
#include "tissue/studies/raymarch_scene.h"
#include "tissue/studies/sss_bench.h"

namespace tissue::sim_app {
namespace {

nlohmann::json skipped(const std::string& why) {
  return {{"skipped", why}};
}

/// Organ 0 in `method` for one frame into `png`, then lit again.
Result<Image8> renderIn(scene::Scene& s, render::ShadingMethod method, int width, int height) {
  if (auto m = s.setMethod(0, method); !m) return m.error();
  auto image = s.renderImage(width, height);
  (void)s.setMethod(0, render::ShadingMethod::Lit);
  return image;
}

nlohmann::json timings(const render::RenderTimings& t) {
  return {{"passes", passTimingsJson(t)}, {"total_cpu_ms", t.totalCpuMs}};
}

}  // namespace

nlohmann::json renderSubsurface(scene::Scene& s, const std::filesystem::path& png, int width, int height,
                                bool textureSpace) {
  using render::ShadingMethod;
  const scene::MethodChoices choices;  // the scene's: the main job's
  // Step 1: separable, lit by a shadow-casting lamp (shadows and transmission); its pre-blur
  // diffuse and position are the reference's input for both methods.
  s.setShadows(true);
  auto image = renderIn(s, ShadingMethod::Separable, width, height);
  auto diffuse = s.renderer().readFrame(render::FrameView::Diffuse);
  auto position = s.renderer().readFrame(render::FrameView::Position);
  // Step 2: the same object switched to texture-space diffusion at run time.
  if (image && textureSpace) image = renderIn(s, ShadingMethod::TextureSpace, width, height);
  s.setShadows(false);
  if (!image) return skipped(image.error().message);
  if (auto w = writePng(png, *image); !w) return skipped(w.error().message);
  const auto& t = s.renderer().lastTimings();
  nlohmann::json j = timings(t);
  j.update({{"image", png.filename().string()}, {"material", s.assets(0).material.name}});
  if (textureSpace)
    j["gaussians"] = choices.gaussians;
  else
    j["kernel"] = choices.kernel + "-" + std::to_string(choices.taps);
  // Step 3: the subsurface diffuse against the exact convolution of the separable frame's
  // pre-blur diffuse (texture-space pixels hold their diffused radiance in the Diffuse view).
  auto truth = scene::separableTruth(s.assets(0), choices);
  if (diffuse && position && truth)
    if (auto e = studies::lastFrameReferenceError(s.renderer(), *diffuse, *position, *truth)) {
      j["reference_ms"] = e->referenceMs;
      j["image_rms"] = e->imageRms;
      j["relative_rms"] = e->relativeRms;
    }
  return j;
}

nlohmann::json renderParallax(scene::Scene& s, const std::filesystem::path& png, int width, int height) {
  auto image = renderIn(s, render::ShadingMethod::Parallax, width, height);
  if (!image) return skipped(image.error().message);
  if (auto w = writePng(png, *image); !w) return skipped(w.error().message);
  const scene::MethodChoices choices;
  nlohmann::json j = timings(s.renderer().lastTimings());
  j.update({{"image", png.filename().string()},
            {"layer_depth_mm", choices.parallaxDepthMm},
            {"refractive_index", choices.refractiveIndex.value_or(s.assets(0).material.ior)}});
  return j;
}

Result<void> frameForRayMarch(scene::Scene& s, const mesh::DeformableSurface& surface, float aspect,
                              bool closeUp) {
  auto framing = studies::rayMarchSceneFor(surface, s.assets(0), aspect, closeUp);
  if (!framing) return framing.error();
  s.setCamera(framing->camera);
  s.renderScene().lights = studies::pipelineLights(*framing);
  return {};
}

nlohmann::json renderRayMarch(scene::Scene& s, const mesh::DeformableSurface& surface,
                              const std::filesystem::path& outDir, int width, int height) {
  nlohmann::json report = nlohmann::json::array();
  for (bool closeUp : {false, true}) {
    if (auto framed = frameForRayMarch(s, surface, float(width) / float(height), closeUp); !framed)
      return skipped(framed.error().message);
    auto image = renderIn(s, render::ShadingMethod::RayMarch, width, height);
    s.frameOrgans();
    if (!image) return skipped(image.error().message);
    const auto png = outDir / (std::string("frame_poked_raymarch") + (closeUp ? "_closeup" : "") + ".png");
    if (auto w = writePng(png, *image); !w) return skipped(w.error().message);
    nlohmann::json entry{
        {"out", png.string()}, {"adaptive", true}, {"max_samples", render::RayMarchSettings{}.maxSamples}};
    for (const auto& p : s.renderer().lastTimings().passes)
      if (p.name == "ray-march") entry["pass_ms"] = p.cpuMs;
    report.push_back(entry);
  }
  return report;
}

}  // namespace tissue::sim_app
