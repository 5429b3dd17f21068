// The viewer's set-up and frame loop: input, then the library's loop (simulate, mesh, upload,
// render into the window), then the panel and the buffer swap.
#include "viewer_app.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <memory>
#include <optional>

#include "frame_timer.h"
#include "glfw_window.h"
#include "instrument_control.h"
#include "orbit_camera.h"
#include "panel.h"
#include "ray_pick.h"
#include "tissue/inspect/inspection_views.h"
#include "tissue/render/renderer.h"
#include "tissue/scene/organ_loop.h"
#include "tissue/scene/session.h"
#include "vec3_ops.h"
#include "viewer_state.h"

namespace tissue::viewer {
namespace {

/// The camera now, and a lamp above and to the right of the eye so the side in view is lit.
void updateLight(Viewer& v) {
  const render::Camera& c = v.scene.camera;
  const Float3 forward = normalize(c.target - c.eye);
  const Float3 right = normalize(cross(forward, c.up));
  const Float3 up = cross(right, forward);
  const float d = length(c.target - c.eye);
  v.scene.lights[0].positionMm = c.eye + right * (0.5f * d) + up * (0.7f * d);
}

/// The interactive input: keys, orbit and zoom, the right button as the instrument.
void handleInteractive(Viewer& v, const InputFrame& in, scene::InstrumentInput& input) {
  const bool mouse = !v.panel || !v.panel->wantsMouse();
  if (in.resetView) v.orbit->reset();
  if (mouse) {
    v.orbit->orbit(in.dragX, in.dragY);
    v.orbit->zoom(in.scrollSteps);
  }
  v.scene.camera = v.orbit->camera();
  int width = 0, height = 0;
  v.window->windowSize(width, height);
  const Ray ray = rayFromCursor(v.scene.camera, in.cursorX, in.cursorY, width, height);
  if (in.rightPressed && mouse) {
    const auto& s = v.loop->surface();
    if (const auto hit = nearestHit(ray, s.positions(), s.triangles())) v.tool->press(ray, hit->distanceMm);
  }
  if (in.rightHeld) v.tool->aim(ray);
  if (in.rightReleased) v.tool->release(v.grasping);
  v.tool->moveDepth(in.depthSteps);
  if (in.toggleGrasp) v.grasping = !v.grasping, input.grasp = v.grasping;
  const Float3 p = v.tool->step();
  input.pose = sim::ToolPose{{p.x, p.y, p.z}};
}

/// The replayed input of frame `i`: pose and grasp, and the recorded camera and method.
Result<void> handleReplay(Viewer& v, std::size_t i, scene::InstrumentInput& input) {
  input = scene::sessionInput(*v.replay, i);
  const scene::SessionFrame& f = v.replay->frames[i];
  if (f.camera) v.scene.camera = *f.camera;
  if (f.method) {
    auto index = findMethod(v.methods, *f.method);
    if (!index)
      return Error{v.replay->file.string() + ": frames[" + std::to_string(i) +
                   "].method: " + index.error().message};
    v.method = *index;
  }
  return {};
}

/// One line with the frame rate, the mean cost of each phase and the force, on stdout and in the title.
void report(Viewer& v, FrameTimer& timer) {
  const auto [totals, fps] = timer.takeWindow();
  v.fps = fps;
  char tail[96];
  std::snprintf(tail, sizeof tail, " | force %.3f N | grasped %u", v.last.simulation.forceMagnitudeN,
                v.last.simulation.grasped);
  char head[32];
  std::snprintf(head, sizeof head, "%.1f fps | ", fps);
  std::string line = drawnMethod(v) + " | " + head + totals.summary() + tail;
  if (v.budgetChoice) {  // under a budget: the budget, and the options still being built
    char budget[96];
    std::snprintf(budget, sizeof budget, " | budget %.1f ms (%zu options pending)", v.budgetMs,
                  v.budgetOptions.pending());
    line += budget;
  }
  v.window->setTitle("tissue-viewer - " + line);
  std::printf("tissue-viewer: %s\n", line.c_str());
  std::fflush(stdout);
}

/// The force bar's full length (N): the first of 0.01, 0.02, 0.05, 0.1, ... N at or above the
/// largest force so far (a surface-spring liver pushes back with millinewtons, a stiff lattice
/// with newtons).
double forceBarScaleN(double maxForceN) {
  for (double decade = 0.01; decade < 100.0; decade *= 10.0)
    for (double m : {1.0, 2.0, 5.0})
      if (m * decade >= maxForceN) return m * decade;
  return 100.0;
}

/// The panel's view of the viewer now.
PanelView panelView(const Viewer& v, const FrameTimer& timer) {
  PanelView p;
  p.fps = v.fps;
  p.ms = {timer.lastMeanMs(Phase::Simulate), timer.lastMeanMs(Phase::Mesh), timer.lastMeanMs(Phase::Upload),
          timer.lastMeanMs(Phase::Render), 0.0};
  p.panelMs = timer.lastMeanMs(Phase::Panel);
  p.presentMs = timer.lastMeanMs(Phase::Present);
  p.forceN = v.last.simulation.forceMagnitudeN;
  p.forceScaleN = forceBarScaleN(v.maxForceN);
  p.contacts = v.last.simulation.contacts;
  p.grasped = v.last.simulation.grasped;
  p.toolDepthMm = v.tool ? v.tool->depthMm() : 0.0f;
  for (const auto& m : v.methods)
    p.methods.push_back(methodName(m));
  p.method = v.method;
  p.choices = v.choices;
  p.methodError = v.methodError;
  p.tissue = tissueLines(v.scenario);
  p.mode = v.replay ? "replay" : v.scripted ? "scripted" : "interactive";
  p.frame = v.loop->frame();
  p.recording = v.recorder.has_value();
  p.recordedFrames = v.recorder ? long(v.recorder->session().frames.size()) : 0;
  p.budgetMs = float(v.budgetMs);
  if (v.budgetChoice) {
    char line[160];
    std::snprintf(line, sizeof line, "%s %s%s, %.0f px, %s, %.1f ms", v.budgetChoice->method.c_str(),
                  v.budgetChoice->setting.c_str(), v.budgetChoice->fallback ? " (fallback)" : "",
                  v.budgetChoice->footprintPx, v.budgetChoice->view.c_str(), v.budgetChoice->predictedMs);
    p.budgetChoice = line;
    // The switches show the method the controller drew (its settings are the table option's).
    for (std::size_t i = 0; i < p.methods.size(); ++i)
      if (p.methods[i] == v.budgetChoice->method) p.method = i;
  }
  return p;
}

/// What the panel asked for: method, settings, grasp, recording, reset.
Result<void> applyPanel(Viewer& v, const PanelActions& a, scene::InstrumentInput& input) {
  if (a.method) v.method = *a.method;
  if (a.budgetMs) v.budgetMs = double(*a.budgetMs);
  if (a.choices) {
    if (auto ok = rebuildMethods(v, *a.choices); !ok)
      v.methodError = ok.error().message;
    else
      v.methodError.clear();
  }
  if (a.toggleGrasp && !v.replay && !v.scripted) v.grasping = !v.grasping, input.grasp = v.grasping;
  if (a.toggleRecord)
    if (auto ok = toggleRecording(v); !ok) return ok;
  if (a.reset) return resetLoop(v);
  return {};
}

/// I: the VTK inspection of the current frame. With a display, a window of the next view
/// (kInspectionViews in turn; the viewer waits until it is closed); without one, every view
/// written to tissue-inspect/frame_N. A failure is reported and the viewer goes on.
void inspectFrame(Viewer& v) {
  const auto snapshot = inspect::snapshotOf(v.loop->run(), v.loop->surface());
  if (inspect::hasDisplay()) {
    const auto view = inspect::kInspectionViews[v.inspectView++ % std::size(inspect::kInspectionViews)];
    std::printf("tissue-viewer: inspection window '%s' (close it to go on; I again: the next view)\n",
                inspect::viewName(view).c_str());
    auto shown = inspect::showInspectionWindow(snapshot, view);
    v.window->makeCurrent();  // VTK's window took the context
    if (!shown) std::fprintf(stderr, "tissue-viewer: %s\n", shown.error().message.c_str());
    return;
  }
  const std::filesystem::path dir = "tissue-inspect/frame_" + std::to_string(snapshot.frame);
  auto written = inspect::writeInspectionViews(snapshot, dir);
  if (!written) {
    std::fprintf(stderr, "tissue-viewer: %s\n", written.error().message.c_str());
    return;
  }
  std::printf("tissue-viewer: wrote %zu inspection views to %s\n", written->size(), dir.string().c_str());
}

/// The frame loop, top to bottom: input (and the panel's layout), the library's loop (simulate,
/// mesh, upload, render into the window), the panel, the screenshot, present, record, log.
Result<void> runFrames(Viewer& v, const ViewerOptions& options, FrameTimer& timer) {
  long frames = options.frames;
  if (v.replay)
    frames =
        frames > 0 ? std::min<long>(frames, long(v.replay->frames.size())) : long(v.replay->frames.size());
  for (long frame = 0; frames == 0 || frame < frames; ++frame) {
    scene::InstrumentInput input;
    PanelActions actions;
    const InputFrame in = timer.time(Phase::Input, [&] { return v.window->poll(); });
    if (in.quit) break;
    if (v.panel) actions = timer.time(Phase::Panel, [&] { return v.panel->build(panelView(v, timer)); });
    auto handled = timer.time(Phase::Input, [&]() -> Result<void> {
      const bool keys = !v.panel || !v.panel->wantsKeyboard();
      if (keys && in.toggleNormalMap) v.normalMapping = !v.normalMapping;
      if (keys && in.cycleMethod) v.method = (v.method + 1) % v.methods.size();
      if (keys && in.inspect) inspectFrame(v);
      if (keys && in.toggleRecord)
        if (auto ok = toggleRecording(v); !ok) return ok;
      if (v.replay) {
        if (auto ok = handleReplay(v, std::size_t(frame), input); !ok) return ok;
      } else if (!v.scripted) {
        InputFrame gated = in;
        if (!keys) gated.toggleGrasp = false, gated.depthSteps = 0.0, gated.resetView = false;
        handleInteractive(v, gated, input);
      }
      if (auto ok = applyPanel(v, actions, input); !ok) return ok;
      applyMethod(v);
      updateLight(v);
      return {};
    });
    if (!handled) return handled;
    int width = 0, height = 0;
    v.window->framebufferSize(width, height);
    scene::RenderRequest request;
    request.scene = &v.scene;
    request.host = render::HostFramebuffer{0, 0, 0, width, height};
    if (auto ok = applyBudget(v, width, height); !ok) return ok;
    auto f = v.loop->advance(input, width > 0 && height > 0 ? &request : nullptr);  // minimised: no render
    if (!f) return Error{"frame " + std::to_string(frame) + ": " + f.error().message};
    v.last = *f;
    timer.add(Phase::Simulate, f->ms.simulateMs);
    timer.add(Phase::Mesh, f->ms.meshMs);
    timer.add(Phase::Upload, f->ms.uploadMs);
    timer.add(Phase::Render, f->ms.renderMs);
    learnBudget(v, f->ms.uploadMs + f->ms.renderMs);
    if (v.panel) timer.time(Phase::Panel, [&] { v.panel->draw(); });
    if (frame + 1 == frames && !options.screenshot.empty()) {
      auto image = v.window->readBackBuffer();
      if (!image) return image.error();
      if (auto w = writePng(options.screenshot, *image); !w) return w;
      std::printf("tissue-viewer: wrote %s\n", options.screenshot.string().c_str());
    }
    timer.time(Phase::Present, [&] { v.window->present(); });
    if (v.recorder) {
      const std::string method = methodName(v.methods[v.method]);
      v.recorder->recordFrame(*v.loop, &v.scene.camera, &method);
    }
    logFrame(v, timer, *f);
    if (timer.endFrame() || frame + 1 == frames) report(v, timer);
  }
  return {};
}

}  // namespace

Result<void> runViewer(const ViewerOptions& options) {
  std::optional<scene::Session> session;
  std::filesystem::path scenarioFile = options.scenario;
  if (!options.replay.empty()) {
    auto loaded = scene::loadSession(options.replay);
    if (!loaded) return loaded.error();
    session = std::move(*loaded);
    scenarioFile = session->scenario;  // the session's own scenario
  }
  Viewer v;
  if (auto ok = loadOrgan(v, scenarioFile, options.folders); !ok) return ok;
  v.scripted = options.pokeScript;
  v.budgetMs = options.budgetMs;
  if (auto ok = createLoop(v); !ok) return ok;
  if (session) {
    if (auto match = scene::checkSessionMatches(*session, *v.loop); !match) return match;
    v.replay = std::move(session);
  }
  if (!options.log.empty()) {
    v.log.open(options.log);
    if (!v.log) return Error{options.log.string() + ": cannot write the per-frame log; check the folder"};
    v.log << "frame,simulate_ms,mesh_ms,upload_ms,render_ms,total_loop_ms,force_N,contacts,grasped,method\n";
  }
  auto window =
      Window::open(options.width, options.height, "tissue-viewer - " + scenarioFile.filename().string());
  if (!window)
    return Error{"cannot open a window: " + window.error().message + "; run under a display or xvfb-run"};
  v.window = std::move(*window);
  if (auto ok = setUpRendering(v, options.method); !ok) return ok;
  auto panel = Panel::create(v.window->handle());
  if (!panel) return panel.error();
  v.panel = std::move(*panel);
  v.orbit.emplace(v.box.lo, v.box.hi, float(options.width) / float(options.height));
  v.scene.camera = v.orbit->camera();
  v.recordFile =
      options.record.empty() ? std::filesystem::path("tissue-viewer-session.json") : options.record;
  if (!options.record.empty())
    if (auto ok = toggleRecording(v); !ok) return ok;

  FrameTimer timer;
  auto ran = runFrames(v, options, timer);
  if (v.recorder)  // saved at exit too
    if (auto ok = toggleRecording(v); !ok && ran) ran = ok;
  if (!ran) return ran;
  std::printf("tissue-viewer: %ld frames, mean per frame: %s; largest force %.3f N\n", timer.run().frames,
              timer.run().summary().c_str(), v.maxForceN);
  return {};
}

}  // namespace tissue::viewer
