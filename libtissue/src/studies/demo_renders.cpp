// The main job's method renders of its poked organ, and the scene a host embeds (demo_renders.h).
#include "demo_renders.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "json_text.h"
#include "loop_detail.h"
#include "tissue/core/image.h"
#include "tissue/core/statistics.h"
#include "tissue/core/stopwatch.h"
#include "tissue/studies/demo_run.h"
#include "tissue/studies/raymarch_scene.h"
#include "tissue/studies/sss_bench.h"

namespace tissue::studies::detail {

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
  return {{"passes", passTimings(t)}, {"total_cpu_ms", t.totalCpuMs}};
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
    if (auto e = lastFrameReferenceError(s.renderer(), *diffuse, *position, *truth)) {
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

namespace {

// The host's one setting (issue 16): a frame budget, 60 Hz and a loose 1 s, each for 45 frames of
// its loop (simulate, render) while the controller chooses each organ's method and learns the pass
// times; then the frame as the trainee sees it and what was chosen.
Result<nlohmann::json> renderUnderBudgets(scene::Scene& s, const std::filesystem::path& outDir, int width,
                                          int height) {
  nlohmann::json out = nlohmann::json::array();
  for (double budgetMs : {1000.0 / 60.0, 1000.0}) {
    if (auto b = s.setBudgetMs(budgetMs); !b) return b.error();
    std::vector<double> frameMs;
    for (int frame = 0; frame < 45; ++frame) {
      if (auto step = s.step(1.0 / 60.0); !step) return step.error();
      Stopwatch watch;
      if (auto image = s.renderImage(width, height); !image) return image.error();
      frameMs.push_back(watch.elapsedMs());
    }
    const std::string name = "frame_embedded_budget_" + std::to_string(int(std::lround(budgetMs))) + "ms.png";
    if (auto r = s.renderPng(outDir / name, width, height); !r) return r.error();
    nlohmann::json choices = nlohmann::json::array();
    for (const scene::BudgetChoice& c : s.budgetChoices())
      choices.push_back(detail::budgetChoiceJson(c));
    const auto t = summarizeSamples(frameMs);
    out.push_back({{"budget_ms", budgetMs},
                   {"image", name},
                   {"frame_ms", {{"median", t.median}, {"p99", t.p99}, {"max", t.max}}},
                   {"choices", std::move(choices)}});
  }
  if (auto off = s.setBudgetMs(0.0); !off) return off.error();
  return out;
}

}  // namespace

nlohmann::json renderEmbeddedScene(const scene::SceneSettings& settings, const std::filesystem::path& dataDir,
                                   const std::filesystem::path& outDir, int width, int height) {
  auto fail = [](const std::string& why) { return nlohmann::json{{"skipped", why}}; };
  // The scene on its own headless context, with the caller's settings (the app reads the environment).
  auto made = scene::Scene::create({}, settings);
  if (!made) return fail(made.error().message);
  scene::Scene& s = *made;
  // Organ 1: the liver as its scenario moves it, separable SSS.
  scene::OrganDesc simulated;
  simulated.scenario = dataDir / "scenarios" / "liver_poke_grasp.json";
  simulated.material = dataDir / "materials" / "liver.json";
  simulated.method = render::ShadingMethod::Separable;
  auto liver = s.addOrgan(simulated);
  if (!liver) return fail(liver.error().message);
  // Organ 2: a static copy, a quarter turn about z, scaled 0.6, 170 mm to the side, texture space.
  scene::OrganDesc copy;
  copy.mesh = dataDir / "meshes" / "liver.obj";
  copy.material = simulated.material;
  copy.method = render::ShadingMethod::TextureSpace;
  const float c = 0.0f, sn = 0.6f;  // 0.6 x (cos 90°, sin 90°)
  copy.model = {c, sn, 0, 0, -sn, c, 0, 0, 0, 0, 0.6f, 0, 170.0f, 0, -10.0f, 1};
  auto aside = s.addOrgan(copy);
  if (!aside) return fail(aside.error().message);
  // A host's frames: 1 s to settle, then the instrument comes down 10 mm into the top.
  std::vector<double> stepMs;
  for (int frame = 0; frame < 160; ++frame) {
    if (frame >= 60) {
      const float down = std::min(1.0f, float(frame - 60) / 80.0f);
      if (auto p = s.setInstrumentPose({.tipMm = {31.82f, 0.0f, 75.0f - 25.7f * down}, .radiusMm = 8.0f}); !p)
        return fail(p.error().message);
    }
    Stopwatch watch;
    auto step = s.step(1.0 / 60.0);
    if (!step) return fail(step.error().message);
    stepMs.push_back(watch.elapsedMs());
  }
  const auto png = outDir / "frame_embedded_scene.png";
  if (auto r = s.renderPng(png, width, height); !r) return fail(r.error().message);
  const Float3 f = s.instrumentForceN();
  const auto t = summarizeSamples(stepMs);
  // A failure under a budget is reported in its own entry: the scene's figures above stand.
  auto budgets = renderUnderBudgets(s, outDir, width, height);
  return {
      {"image", png.filename().string()},
      {"budgets", budgets ? std::move(*budgets) : fail(budgets.error().message)},
      {"organs",
       {{{"method", "separable"}, {"simulated", true}},
        {{"method", "texture-space"}, {"simulated", false}, {"model", "quarter turn about z, scale 0.6"}}}},
      {"force_at_10mm_N", {f.x, f.y, f.z}},
      {"step_ms", {{"median", t.median}, {"p99", t.p99}, {"max", t.max}}}};
}

}  // namespace tissue::studies::detail

namespace tissue::studies {

Result<void> frameForRayMarch(scene::Scene& s, const mesh::DeformableSurface& surface, float aspect,
                              bool closeUp) {
  auto framing = rayMarchSceneFor(surface, s.assets(0), aspect, closeUp);
  if (!framing) return framing.error();
  s.setCamera(framing->camera);
  s.renderScene().lights = pipelineLights(*framing);
  return {};
}

}  // namespace tissue::studies
