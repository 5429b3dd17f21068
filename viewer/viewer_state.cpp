// Building and rebuilding the viewer's shared state.
#include "viewer_state.h"

#include <cstdio>

#include "frame_timer.h"

namespace tissue::viewer {
namespace {

/// The organ and the instrument as the scene's objects (after attach).
void placeObjects(Viewer& v) {
  v.scene.objects = {scene::organObject(v.loop->meshHandle(), v.textures, render::LitSettings{},
                                        scene::surfaceMaterialOf(v.organ))};
  if (auto tool = v.loop->instrumentObject()) v.scene.objects.push_back(*tool);
}

/// Every method the organ offers, with `choices`, Lit first.
Result<std::vector<render::MethodSettings>> organMethods(const Viewer& v,
                                                         const scene::MethodChoices& choices) {
  std::vector<render::MethodSettings> methods;
  for (render::ShadingMethod m : scene::offeredMethods(v.organ)) {
    auto settings = scene::organMethod(m, v.organ, v.textures, choices);
    if (!settings) return settings.error();
    methods.push_back(std::move(*settings));
  }
  return methods;
}

}  // namespace

scene::MethodChoices viewerChoices() {
  scene::MethodChoices c;
  c.adaptive = false;  // the panel's samples slider sets the count
  return c;
}

Result<void> loadOrgan(Viewer& v, const std::filesystem::path& scenarioFile, const DataFolders& folders) {
  if (!std::filesystem::exists(scenarioFile))
    return Error{scenarioFile.string() +
                 ": no such scenario file; give --scenario FILE (data/scenarios/*.json)"};
  auto scenario = scenario::loadScenario(scenarioFile, {.sharedMeshesDir = folders.shared / "meshes"});
  if (!scenario) return scenario.error();
  if (!scenario->instrument)
    return Error{scenarioFile.string() +
                 ": the scenario has no instrument; the viewer pokes with it (key "
                 "\"instrument\", docs/SCENARIOS.md)"};
  scene::OrganSource source;
  source.mesh = scenario->mesh;
  source.meshScaleToMm = float(scenario->meshScaleToMm);
  // A mesh from outside the project has no material file: the default organ material.
  if (const auto file = folders.data / "materials" / (scenario->mesh.stem().string() + ".json");
      std::filesystem::exists(file))
    source.material = file;
  source.materialOptions.textureRoots = {folders.generated, folders.data};
  auto organ = scene::loadOrganAssets(source);
  if (!organ) return organ.error();
  v.scenario = std::move(*scenario);
  v.organ = std::move(*organ);
  return {};
}

std::string methodName(const render::MethodSettings& method) {
  return std::string(render::shadingMethodName(render::shadingMethod(method)));
}

Result<std::size_t> findMethod(const std::vector<render::MethodSettings>& methods, const std::string& name) {
  std::string offered;
  for (std::size_t i = 0; i < methods.size(); ++i) {
    const std::string n = methodName(methods[i]);
    if (n == name) return i;
    offered += (offered.empty() ? "" : ", ") + n;
  }
  return Error{"method " + name + ": this organ offers " + offered +
               " (texture-space needs unique UVs, ray-march a material naming textures.subsurface, "
               "parallax one naming textures.inner_base; docs/DATA.md)"};
}

Result<void> createLoop(Viewer& v) {
  scene::OrganLoopConfig config;
  config.planes = v.organ.planes;
  config.uploadPlanes = true;  // the ray-march method reads them (the others ignore them)
  auto loop = scene::OrganLoop::create(v.scenario, v.organ.mesh, config);
  if (!loop) return loop.error();
  if (v.loop) v.loop->detach();
  v.loop.emplace(std::move(*loop));
  const sim::Instrument* tool = v.loop->run().instrument();
  const auto& p = tool->pose().position;
  v.tool.emplace(Float3{float(p.x), float(p.y), float(p.z)}, float(tool->config().shape.radius));
  v.grasping = false;
  v.box = boundsOf(v.loop->surface().geometricRestPositions());
  return {};
}

Result<void> setUpRendering(Viewer& v, const std::string& initialMethod) {
  render::RendererSettings settings;
  settings.gpuTimers = false;  // timer queries would stall every frame waiting for the GPU
  auto renderer = render::Renderer::create(v.window->procAddress(), settings);
  if (!renderer) return renderer.error();
  v.renderer.emplace(std::move(*renderer));
  if (auto attached = v.loop->attach(*v.renderer); !attached) return attached.error();
  auto textures = scene::uploadOrganTextures(*v.renderer, v.organ);
  if (!textures) return textures.error();
  v.textures = *textures;
  auto methods = organMethods(v, v.choices);
  if (!methods) return methods.error();
  v.methods = std::move(*methods);
  auto index = findMethod(v.methods, initialMethod);
  if (!index) return Error{"--" + index.error().message};
  v.method = *index;
  placeObjects(v);
  applyMethod(v);
  return {};
}

Result<void> rebuildMethods(Viewer& v, const scene::MethodChoices& choices) {
  auto methods = organMethods(v, choices);
  if (!methods) return methods.error();
  const std::string shown = methodName(v.methods[v.method]);
  v.methods = std::move(*methods);
  v.choices = choices;
  auto index = findMethod(v.methods, shown);
  v.method = index ? *index : 0;
  return {};
}

void applyMethod(Viewer& v) {
  render::SceneObject& organ = v.scene.objects[0];
  organ.method = v.methods[v.method];
  organ.normalMap = v.normalMapping ? v.textures.normalMap : render::TextureHandle{};
  // The separable and texture-space transmission reads shadow maps; ray marching is its own
  // light transport (no shadow maps).
  const auto m = render::shadingMethod(organ.method);
  v.scene.lights[0].castsShadows =
      m == render::ShadingMethod::Separable || m == render::ShadingMethod::TextureSpace;
}

Result<void> applyBudget(Viewer& v, int width, int height) {
  if (v.budgetMs <= 0.0 || width <= 0 || height <= 0) {
    v.budgetChoice.reset();
    return {};
  }
  if (!v.controller) v.controller.emplace(quality::defaultQualityTable());
  // The options' settings are built off the frame path; the controller chooses among the built.
  v.budgetOptions.offer(0, v.controller->table(), v.organ, v.textures, v.choices);
  v.budgetOptions.collect();
  quality::ObjectView view = scene::organView(v.organ.mesh, v.box, kIdentity4, v.scene.camera, width, height);
  view.deforming = v.last.simulation.contacts > 0 || v.last.simulation.grasped > 0;
  view.hasNormalMap = v.normalMapping && bool(v.textures.normalMap);
  view.allowed = v.budgetOptions.ready(0);
  const quality::ObjectChoice& c =
      v.controller->update({&view, 1}, double(width) * double(height), v.budgetMs)[0];
  if (c.option != v.budgetOption) {
    auto m = v.budgetOptions.chosen(0, c.option, v.controller->table(), v.organ, v.textures, v.choices);
    if (!m) return m.error();
    v.budgetMethod = std::move(*m);
    v.budgetOption = c.option;
  }
  v.scene.objects[0].method = v.budgetMethod;
  v.budgetChoice =
      scene::BudgetChoice{c.method,          c.setting,        view.footprintPx,
                          c.predictedMs,     c.expectedRelRms, std::string(quality::viewClassFrame(c.view)),
                          view.viewAngleDeg, c.fallback,       c.mesh};
  return {};
}

void learnBudget(Viewer& v, double frameMs) {
  if (!v.controller || !v.budgetChoice || !v.renderer) return;
  std::vector<double> weights(v.scene.objects.size(), 0.0);
  weights[0] = 1.0;  // the organ; an instrument drawn in its pass is overhead
  const auto costs = scene::framePassCosts(v.renderer->lastTimings(), weights);
  const auto m = render::shadingMethod(v.scene.objects[0].method);
  const quality::CostSample sample{0, costs.objectMs[0]};
  const quality::PassSample pass{std::string(render::shadingMethodName(m)), costs.methodMs[std::size_t(m)]};
  v.controller->observe({&sample, 1}, {&pass, 1}, frameMs);
}

Result<void> resetLoop(Viewer& v) {
  if (v.recorder)
    if (auto ok = toggleRecording(v); !ok) return ok;
  if (auto ok = createLoop(v); !ok) return ok;
  if (auto attached = v.loop->attach(*v.renderer); !attached) return attached.error();
  placeObjects(v);
  applyMethod(v);
  v.maxForceN = 0.0;
  std::printf("tissue-viewer: reset: the loop restarts from %s\n", v.scenario.file.string().c_str());
  return {};
}

Result<void> toggleRecording(Viewer& v) {
  if (!v.recorder) {
    v.recorder.emplace(*v.loop);
    std::printf("tissue-viewer: recording into %s (R stops)\n", v.recordFile.string().c_str());
    return {};
  }
  const std::size_t frames = v.recorder->session().frames.size();
  auto saved = scene::saveSession(v.recorder->session(), v.recordFile);
  v.recorder.reset();
  if (!saved) return saved;
  std::printf("tissue-viewer: recorded %zu frames into %s\n", frames, v.recordFile.string().c_str());
  return {};
}

std::string drawnMethod(const Viewer& v) {
  if (v.budgetChoice) return v.budgetChoice->method + " " + v.budgetChoice->setting;
  return methodName(v.methods[v.method]);
}

void logFrame(Viewer& v, const FrameTimer& /*timer*/, const scene::LoopFrame& f) {
  v.maxForceN = std::max(v.maxForceN, f.simulation.forceMagnitudeN);
  if (!v.log.is_open()) return;
  char line[256];
  std::snprintf(line, sizeof line, "%ld,%.3f,%.3f,%.3f,%.3f,%.3f,%.5f,%u,%u,", f.simulation.frame,
                f.ms.simulateMs, f.ms.meshMs, f.ms.uploadMs, f.ms.renderMs, f.ms.totalMs,
                f.simulation.forceMagnitudeN, f.simulation.contacts, f.simulation.grasped);
  v.log << line << drawnMethod(v) << '\n';
}

std::vector<std::string> tissueLines(const scenario::Scenario& s) {
  const char* source = s.springSource == scenario::SpringSource::Surface   ? "surface"
                       : s.springSource == scenario::SpringSource::Lattice ? "lattice"
                                                                           : "tet-edges";
  const bool perLength = s.springs.law != sim::StiffnessLaw::Constant;
  char a[96], b[96], c[96], d[96];
  std::snprintf(a, sizeof a, "springs: %s%s", source,
                s.springSource == scenario::SpringSource::Lattice
                    ? (" (cell " + std::to_string(int(s.latticeCellSizeMm)) + " mm)").c_str()
                    : "");
  std::snprintf(b, sizeof b, "stiffness %.3g %s, bending %.3g", s.springs.stiffness, perLength ? "N" : "N/mm",
                s.springs.bendingStiffness);
  std::snprintf(c, sizeof c, "damping %.3g N*s/mm, Rayleigh %.3g /s, %.3g s", s.springs.damping,
                s.system.rayleighMass, s.system.rayleighStiffness);
  std::snprintf(d, sizeof d, "mass %.4g g, dt %.2f ms x %d", s.mass.total, 1000.0 * s.frameTime, s.substeps);
  return {a, b, c, d};
}

}  // namespace tissue::viewer
