// Building and rebuilding the viewer's shared state.
#include "viewer_state.h"

#include <cstdio>
#include <limits>

#include "frame_timer.h"

namespace tissue::viewer {
namespace {

/// Uploads `image` when present; none otherwise.
Result<render::TextureHandle> upload(render::Renderer& renderer, const std::optional<Image8>& image,
                                     render::TextureEncoding encoding = render::TextureEncoding::Srgb) {
  if (!image) return render::TextureHandle{};
  return renderer.createTexture(*image, encoding);
}

/// The organ and the instrument as the scene's objects (after attach).
void placeObjects(Viewer& v, render::TextureHandle baseColor) {
  render::SceneObject organ;
  organ.mesh = v.loop->meshHandle();
  organ.baseColor = baseColor;
  v.scene.objects = {organ};
  if (auto tool = v.loop->instrumentObject()) v.scene.objects.push_back(*tool);
}

}  // namespace

Result<void> createLoop(Viewer& v) {
  scene::OrganLoopConfig config;
  config.planes = v.organ.planes;
  config.uploadPlanes = true;  // the ray-march method reads them (the others ignore them)
  auto loop = scene::OrganLoop::create(v.organ.scenario, v.organ.mesh, config);
  if (!loop) return loop.error();
  if (v.loop) v.loop->detach();
  v.loop.emplace(std::move(*loop));
  const sim::Instrument* tool = v.loop->run().instrument();
  const auto& p = tool->pose().position;
  v.tool.emplace(Float3{float(p.x), float(p.y), float(p.z)}, float(tool->config().shape.radius));
  v.grasping = false;
  const auto rest = v.loop->surface().geometricRestPositions();
  Float3 lo{std::numeric_limits<float>::max(), std::numeric_limits<float>::max(),
            std::numeric_limits<float>::max()};
  Float3 hi{-lo.x, -lo.y, -lo.z};
  for (const Float3& q : rest) {
    lo = {std::min(lo.x, q.x), std::min(lo.y, q.y), std::min(lo.z, q.z)};
    hi = {std::max(hi.x, q.x), std::max(hi.y, q.y), std::max(hi.z, q.z)};
  }
  v.boxLo = lo, v.boxHi = hi;
  return {};
}

Result<void> setUpRendering(Viewer& v, const std::string& initialMethod) {
  render::RendererSettings settings;
  settings.gpuTimers = false;  // timer queries would stall every frame waiting for the GPU
  auto renderer = render::Renderer::create(v.window->procAddress(), settings);
  if (!renderer) return renderer.error();
  v.renderer.emplace(std::move(*renderer));
  if (auto attached = v.loop->attach(*v.renderer); !attached) return attached.error();
  const OrganAssets& o = v.organ;
  auto base = upload(*v.renderer, o.baseColor);
  auto normal = upload(*v.renderer, o.normalMap);
  auto inner = upload(*v.renderer, o.innerBase);
  auto opacity = upload(*v.renderer, o.opacity);
  auto map = upload(*v.renderer, o.rayMarch ? std::optional<Image8>(o.rayMarch->subsurfaceMap) : std::nullopt,
                    render::TextureEncoding::LinearData);
  for (const auto* r : {&base, &normal, &inner, &opacity, &map})
    if (!*r) return r->error();
  v.normalMap = *normal;
  v.layers = {*inner, *opacity, *map};
  auto methods = organMethods(o, v.layers, v.choices);
  if (!methods) return methods.error();
  v.methods = std::move(*methods);
  auto index = findMethod(v.methods, initialMethod);
  if (!index) return Error{"--" + index.error().message};
  v.method = *index;
  placeObjects(v, *base);
  applyMethod(v);
  return {};
}

Result<void> rebuildMethods(Viewer& v, const MethodChoices& choices) {
  auto methods = organMethods(v.organ, v.layers, choices);
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
  organ.normalMap = v.normalMapping ? v.normalMap : render::TextureHandle{};
  // The separable and texture-space transmission reads shadow maps; ray marching is its own
  // light transport (no shadow maps).
  const auto m = render::shadingMethod(organ.method);
  v.scene.lights[0].castsShadows =
      m == render::ShadingMethod::Separable || m == render::ShadingMethod::TextureSpace;
}

Result<void> resetLoop(Viewer& v) {
  if (v.recorder)
    if (auto ok = toggleRecording(v); !ok) return ok;
  const render::TextureHandle base = v.scene.objects[0].baseColor;
  if (auto ok = createLoop(v); !ok) return ok;
  if (auto attached = v.loop->attach(*v.renderer); !attached) return attached.error();
  placeObjects(v, base);
  applyMethod(v);
  v.maxForceN = 0.0;
  std::printf("tissue-viewer: reset: the loop restarts from %s\n", v.organ.scenario.file.string().c_str());
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

void logFrame(Viewer& v, const FrameTimer& /*timer*/, const scene::LoopFrame& f) {
  v.maxForceN = std::max(v.maxForceN, f.simulation.forceMagnitudeN);
  if (!v.log.is_open()) return;
  char line[256];
  std::snprintf(line, sizeof line, "%ld,%.3f,%.3f,%.3f,%.3f,%.3f,%.5f,%u,%u,", f.simulation.frame,
                f.ms.simulateMs, f.ms.meshMs, f.ms.uploadMs, f.ms.renderMs, f.ms.totalMs,
                f.simulation.forceMagnitudeN, f.simulation.contacts, f.simulation.grasped);
  v.log << line << methodName(v.methods[v.method]) << '\n';
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
