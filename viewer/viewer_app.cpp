// The viewer's set-up and frame loop.
#include "viewer_app.h"

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>

#include "frame_timer.h"
#include "glfw_window.h"
#include "instrument_poke.h"
#include "orbit_camera.h"
#include "organ_methods.h"
#include "poke_script.h"
#include "ray_pick.h"
#include "tissue/render/renderer.h"
#include "vec3_ops.h"

namespace tissue::viewer {
namespace {

/// The mean cost of DeformableSurface::update's own phases (ms), summed over the run.
struct MeshBreakdown {
  double gatherMs = 0.0, normalsMs = 0.0, planesMs = 0.0, tangentsMs = 0.0;
  long updates = 0;
  void add(const mesh::SurfaceUpdateStats& s) {
    gatherMs += s.gatherMs;
    normalsMs += s.normalsMs;
    planesMs += s.planesMs;
    tangentsMs += s.tangentsMs;
    ++updates;
  }
};

/// Everything the frames share. Members die in reverse order: the renderer before the window
/// whose context it needs.
struct Session {
  explicit Session(OrganAssets assets) : organ(std::move(assets)) {}

  OrganAssets organ;
  std::unique_ptr<Window> window;
  std::optional<render::Renderer> renderer;
  std::optional<OrbitCamera> orbit;
  std::optional<InstrumentPoke> poke;
  render::Scene scene;  ///< one object: the organ
  render::MeshHandle mesh;
  render::TextureHandle normalMap;              ///< none: the organ has no normal map
  std::vector<render::MethodSettings> methods;  ///< what M cycles through (organMethods)
  std::size_t method = 0;                       ///< the organ's method now, an index into methods
  bool normalMapping = true;
  bool scriptHeld = false;
  MeshBreakdown meshBreakdown;
};

/// The camera now, and a lamp above and to the right of the eye so the side in view is lit.
void updateScene(Session& s) {
  s.scene.camera = s.orbit->camera();
  const Float3 forward = normalize(s.scene.camera.target - s.scene.camera.eye);
  const Float3 right = normalize(cross(forward, s.scene.camera.up));
  const Float3 up = cross(right, forward);
  const float d = s.orbit->distanceMm();
  s.scene.lights[0].positionMm = s.scene.camera.eye + right * (0.5f * d) + up * (0.7f * d);
}

/// Uploads `image` when present; none otherwise.
Result<render::TextureHandle> upload(render::Renderer& renderer, const std::optional<Image8>& image) {
  if (!image) return render::TextureHandle{};
  return renderer.createTexture(*image);
}

/// Shows the organ with methods[method]; shadow maps when it scatters (the transmission of the
/// separable and texture-space methods reads them).
void applyMethod(Session& s) {
  render::SceneObject& organ = s.scene.objects[0];
  organ.method = s.methods[s.method];
  organ.normalMap = s.normalMapping ? s.normalMap : render::TextureHandle{};
  s.scene.lights[0].castsShadows = render::shadingMethod(organ.method) != render::ShadingMethod::Lit;
}

/// Creates the renderer on the window's context, uploads the organ and its textures, and
/// builds the shading methods the organ can switch between (`initialMethod` first shown).
Result<void> setUpRendering(Session& s, const std::string& initialMethod) {
  render::RendererSettings settings;
  settings.gpuTimers = false;  // timer queries would stall every frame waiting for the GPU
  auto renderer = render::Renderer::create(s.window->procAddress(), settings);
  if (!renderer) return renderer.error();
  s.renderer.emplace(std::move(*renderer));
  const auto& surface = s.organ.surface;
  auto mesh = s.renderer->createMesh(
      {surface.positions(), surface.normals(), surface.tangents(), surface.uvs(), surface.triangles(), {}});
  if (!mesh) return mesh.error();
  s.mesh = *mesh;
  auto base = upload(*s.renderer, s.organ.baseColor);
  auto normal = upload(*s.renderer, s.organ.normalMap);
  auto inner = upload(*s.renderer, s.organ.innerBase);
  auto opacity = upload(*s.renderer, s.organ.opacity);
  for (const auto* r : {&base, &normal, &inner, &opacity})
    if (!*r) return r->error();
  s.normalMap = *normal;
  auto methods = organMethods(s.organ, {*inner, *opacity});
  if (!methods) return methods.error();
  s.methods = std::move(*methods);
  auto index = findMethod(s.methods, initialMethod);
  if (!index) return index.error();
  s.method = *index;
  render::SceneObject organ;
  organ.mesh = s.mesh;
  organ.baseColor = *base;
  s.scene.objects = {organ};
  applyMethod(s);
  return {};
}

/// Right button down at (`x`, `y`) window pixels: the instrument touches the nearest surface
/// under the cursor and pushes along the view ray. Returns the hit, empty on a miss.
std::optional<RayHit> pokeAt(Session& s, double x, double y) {
  int width = 0, height = 0;
  s.window->windowSize(width, height);
  const Ray ray = rayFromCursor(s.scene.camera, x, y, width, height);
  const auto& surface = s.organ.surface;
  const auto hit = nearestHit(ray, surface.positions(), surface.triangles());
  if (hit) s.poke->press(hit->pointMm, ray.direction, surface.geometricPositions());
  return hit;
}

/// The input phase: events, the scripted poke, keys, orbit and zoom, picking.
/// Returns false when the user quits.
bool handleInput(Session& s, const PokeScript* script, double timeS) {
  InputFrame in = s.window->poll();
  if (script && script->holds(timeS) != s.scriptHeld) {
    s.scriptHeld = !s.scriptHeld;
    (s.scriptHeld ? in.rightPressed : in.rightReleased) = true;
    int width = 0, height = 0;
    s.window->windowSize(width, height);
    const Float3 top =
        s.organ.surface.geometricPositions()[topVertex(s.organ.surface.geometricRestPositions())];
    const auto cursor = projectToCursor(s.scene.camera, top, width, height);
    in.cursorX = cursor ? double(cursor->x) : width / 2.0;
    in.cursorY = cursor ? double(cursor->y) : height / 2.0;
  }
  if (in.quit) return false;
  if (in.reset) {
    s.poke->reset();
    s.orbit->reset();
  }
  if (in.toggleNormalMap) s.normalMapping = !s.normalMapping;
  if (in.cycleMethod) {
    s.method = (s.method + 1) % s.methods.size();
    std::printf("tissue-viewer: shading method %s\n",
                std::string(render::shadingMethodName(render::shadingMethod(s.methods[s.method]))).c_str());
  }
  applyMethod(s);
  s.orbit->orbit(in.dragX, in.dragY);
  s.orbit->zoom(in.scrollSteps);
  updateScene(s);
  if (in.rightPressed) {
    const auto hit = pokeAt(s, in.cursorX, in.cursorY);
    if (hit && script)
      std::printf("tissue-viewer: scripted poke hits triangle %u at (%.1f, %.1f, %.1f) mm\n", hit->triangle,
                  double(hit->pointMm.x), double(hit->pointMm.y), double(hit->pointMm.z));
  }
  if (in.rightReleased) s.poke->release();
  return true;
}

/// One line with the frame rate and the mean cost of each phase, on stdout and in the title.
void report(Session& s, FrameTimer& timer) {
  const auto [totals, fps] = timer.takeWindow();
  char head[32];
  std::snprintf(head, sizeof head, "%.1f fps | ", fps);
  const std::string method(render::shadingMethodName(render::shadingMethod(s.methods[s.method])));
  const std::string line = method + " | " + std::string(head) + totals.summary();
  s.window->setTitle("tissue-viewer - " + line);
  std::printf("tissue-viewer: %s\n", line.c_str());
  std::fflush(stdout);
}

/// The frame loop, top to bottom: input, deform, mesh, upload, render, present.
Result<void> runFrames(Session& s, const ViewerOptions& options, FrameTimer& timer) {
  const PokeScript script;
  Stopwatch frameClock;
  double timeS = 0.0;  // simulated time, s
  for (long frame = 0; options.frames == 0 || frame < options.frames; ++frame) {
    // A scripted run of N frames steps time evenly (the same pictures every time); otherwise
    // time is the wall clock's, a frame counting at most 0.1 s (a stall must not jump the poke).
    const bool evenSteps = options.pokeScript && options.frames > 0;
    const double dtS = evenSteps ? script.stepS : std::min(frameClock.elapsedMs() / 1000.0, 0.1);
    frameClock.restart();
    timeS += dtS;
    if (!timer.time(Phase::Input,
                    [&] { return handleInput(s, options.pokeScript ? &script : nullptr, timeS); }))
      break;
    const bool moved = timer.time(Phase::Deform, [&] { return s.poke->step(float(dtS)); });
    auto& surface = s.organ.surface;
    if (moved) timer.time(Phase::Mesh, [&] { s.meshBreakdown.add(surface.update(s.poke->positions())); });
    const auto uploaded = timer.time(Phase::Upload, [&]() -> Result<void> {
      if (!moved) return {};
      return s.renderer->updateMesh(s.mesh,
                                    {0, surface.positions(), surface.normals(), surface.tangents(), {}});
    });
    if (!uploaded) return uploaded;
    int width = 0, height = 0;
    s.window->framebufferSize(width, height);
    const auto drawn = timer.time(Phase::Render, [&]() -> Result<void> {
      if (width <= 0 || height <= 0) return {};  // minimised: nothing to draw into
      return s.renderer->renderTo(s.scene, render::HostFramebuffer{0, 0, 0, width, height});
    });
    if (!drawn) return drawn;
    timer.time(Phase::Present, [&] { s.window->present(); });
    if (timer.endFrame()) report(s, timer);
  }
  return {};
}

/// The last frame again, offscreen at the framebuffer's size, written atomically.
Result<void> writeScreenshot(Session& s, const std::filesystem::path& png) {
  int width = 0, height = 0;
  s.window->framebufferSize(width, height);
  auto image = s.renderer->renderImage(s.scene, width, height);
  if (!image) return image.error();
  return writePng(png, *image);
}

}  // namespace

Result<void> runViewer(const ViewerOptions& options) {
  auto organ = loadOrganAssets(options.mesh, options.folders);
  if (!organ) return organ.error();
  Session s(std::move(*organ));
  auto window =
      Window::open(options.width, options.height, "tissue-viewer - " + options.mesh.filename().string());
  if (!window)
    return Error{"cannot open a window: " + window.error().message + "; run under a display or xvfb-run"};
  s.window = std::move(*window);
  if (auto ok = setUpRendering(s, options.method); !ok) return ok;

  // The home view frames the rest shape; the poke starts at rest.
  const auto rest = s.organ.surface.geometricRestPositions();
  Float3 lo{std::numeric_limits<float>::max(), std::numeric_limits<float>::max(),
            std::numeric_limits<float>::max()};
  Float3 hi{-lo.x, -lo.y, -lo.z};
  for (const Float3& p : rest) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  s.orbit.emplace(lo, hi, float(options.width) / float(options.height));
  s.poke.emplace(rest);
  updateScene(s);

  FrameTimer timer;
  if (auto ok = runFrames(s, options, timer); !ok) return ok;
  const MeshBreakdown& m = s.meshBreakdown;
  const double n = double(std::max(m.updates, 1L));
  std::printf("tissue-viewer: %ld frames, mean per frame: %s\n", timer.run().frames,
              timer.run().summary().c_str());
  std::printf(
      "tissue-viewer: mesh update (%ld): gather %.2f | normals %.2f | planes %.2f | tangents %.2f ms\n",
      m.updates, m.gatherMs / n, m.normalsMs / n, m.planesMs / n, m.tangentsMs / n);
  if (!options.screenshot.empty()) {
    if (auto ok = writeScreenshot(s, options.screenshot); !ok) return ok;
    std::printf("tissue-viewer: wrote %s\n", options.screenshot.string().c_str());
  }
  return {};
}

}  // namespace tissue::viewer
