// The main job's scene as a host embeds it (demo_embedded.h).
#include "demo_embedded.h"

#include <cmath>
#include <vector>

#include "organ_data.h"
#include "output.h"
#include "tissue/core/statistics.h"
#include "tissue/core/stopwatch.h"
#include "tissue/scene/scene.h"

namespace tissue::sim_app {

nlohmann::json renderEmbeddedScene(const std::filesystem::path& outDir, int width, int height) {
  auto fail = [](const std::string& why) { return nlohmann::json{{"skipped", why}}; };
  // The scene on its own headless context, with the apps' settings (env vars read by the app).
  auto made = scene::Scene::create({}, dataSceneSettings());
  if (!made) return fail(made.error().message);
  scene::Scene& s = *made;
  // Organ 1: the liver as its scenario moves it, separable SSS.
  scene::OrganDesc simulated;
  simulated.scenario = dataDir() / "scenarios" / "liver_poke_grasp.json";
  simulated.material = dataDir() / "materials" / "liver.json";
  simulated.method = render::ShadingMethod::Separable;
  auto liver = s.addOrgan(simulated);
  if (!liver) return fail(liver.error().message);
  // Organ 2: a static copy, a quarter turn about z, scaled 0.6, 170 mm to the side, texture space.
  scene::OrganDesc copy;
  copy.mesh = dataDir() / "meshes" / "liver.obj";
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
  return {
      {"image", png.filename().string()},
      {"organs",
       {{{"method", "separable"}, {"simulated", true}},
        {{"method", "texture-space"}, {"simulated", false}, {"model", "quarter turn about z, scale 0.6"}}}},
      {"force_at_10mm_N", {f.x, f.y, f.z}},
      {"step_ms", {{"median", t.median}, {"p99", t.p99}, {"max", t.max}}}};
}

}  // namespace tissue::sim_app
