// A scene of organs for apps and hosts: set-up once, step (simulate, mesh), upload, render
// (scene.h).
#include "tissue/scene/scene.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "tissue/context/headless_context.h"
#include "tissue/core/atomic_file.h"
#include "tissue/core/stopwatch.h"
#include "tissue/mesh/deformable_surface.h"
#include "tissue/scenario/scenario.h"
#include "tissue/scene/option_catalog.h"

namespace tissue::scene {
namespace {

/// The uniform scale of a rigid-plus-uniform-scale model matrix (the first column's length).
float uniformScaleOf(const Mat4& m) {
  return length({m[0], m[1], m[2]});
}

/// Model matrices the renderer and the simulation both take: affine, finite, not mirrored
/// (mirroring flips the winding and the tangents' handedness).
Result<void> checkModel(const Mat4& m) {
  if (!isAffineInvertible(m) || !(determinant3(m) > 0.0f))
    return Error{
        "model matrix: must be affine (last row 0 0 0 1), finite and invertible without mirroring "
        "(det > 0); column-major, mm"};
  return {};
}

sim::Vec3d toVec3d(Float3 v) {
  return {double(v.x), double(v.y), double(v.z)};
}

/// Where `desc`'s assets come from: its mesh (else `scenarioMesh`), its material (else the
/// materials folder's file for the mesh, when there is one).
OrganSource sourceOf(const OrganDesc& desc, const SceneSettings& settings,
                     const scenario::Scenario* scenario) {
  OrganSource source{.mesh = desc.mesh,
                     .material = desc.material,
                     .meshScaleToMm = desc.meshScaleToMm,
                     .materialOptions = settings.materials,
                     .uvAtlasFallback = true};
  if (scenario) {
    if (source.mesh.empty()) source.mesh = scenario->mesh;
    source.meshScaleToMm = float(scenario->meshScaleToMm);
  }
  if (source.material.empty() && !settings.materialsDir.empty()) {
    const auto file = settings.materialsDir / (source.mesh.stem().string() + ".json");
    if (std::filesystem::is_regular_file(file)) source.material = file;
  }
  return source;
}

}  // namespace

struct Scene::Impl {
  SceneSettings settings;
  std::unique_ptr<context::GlContext> ownContext;  ///< when the host gave no getProcAddress
  std::optional<render::Renderer> renderer;

  struct Organ {
    OrganAssets assets;
    OrganTextures textures;
    Mat4 model = kIdentity4;
    render::MethodSettings method;
    MethodChoices choices;                         ///< the organ's (OrganDesc::methods) or the scene's
    std::optional<OrganLoop> loop;                 ///< simulated organs
    std::optional<mesh::DeformableSurface> still;  ///< static organs: normals, tangents, planes once
    render::MeshHandle mesh;                       ///< static organs (a loop holds its own)
    double pendingS = 0.0;                         ///< s, time not yet simulated
    bool changed = false;                          ///< stepped since the last upload
    bool openSurface = false;                      ///< the surface has boundary edges: drawn double-sided
    bool moved = false;                            ///< changed at the last upload (deforming)
    bool hasNormalMap = false;                     ///< its material has one (the lit method's tangents)
    double importance = 1.0;                       ///< OrganDesc::importance
    /// The quality table option it is drawn with (the budget's choice or setMethodOption's); -1:
    /// a method of its own (setMethod, OrganDesc::method)
    int budgetOption = -1;
    bool optionNew = true;        ///< its method changed since the last frame learned from
    double footprintPx = 0.0;     ///< px covered at the last render (organView)
    std::size_t objectIndex = 0;  ///< its index in render::Scene::objects (buildObjects)
  };
  std::vector<Organ> organs;
  /// Each organ's offered table options and their settings, built off the frame path
  /// (option_catalog.h) from the first budget on; indexed as `organs`.
  OptionCatalog options;

  render::Scene scene;  ///< lights, background, exposure; objects rebuilt per render
  std::optional<render::Camera> fixedCamera;
  bool lightsFollowFraming = true;
  render::Camera lastCamera;

  std::optional<InstrumentPose> lastPose;  ///< world space, for interpolation across frames of one step
  std::optional<InstrumentPose> pendingPose;
  std::optional<bool> pendingGrasp;
  Float3 forceN{};
  bool instrumentVisible = true;

  double budgetMs = 0.0;
  std::optional<quality::QualityController> controller;
  std::vector<BudgetChoice> budgetChoices;

  /// The controller, made at the first budget or setMethodOption (SceneSettings::qualityTable).
  Result<void> ensureController() {
    if (controller) return {};
    auto table = quality::qualityTableOrDefault(settings.qualityTable);
    if (!table) return Error{"budget: " + table.error().message};
    controller.emplace(std::move(*table), settings.quality);
    return {};
  }
  /// The controller's choice for this frame (after frame()), as each organ's method. Without a
  /// budget, each organ's footprint for the costs learned from the host's choice (learnBudget).
  Result<void> applyBudget(int width, int height) {
    if (!renderer || organs.empty()) return {};
    if (budgetMs <= 0.0) {
      if (controller)
        for (Organ& o : organs)
          o.footprintPx =
              organView(o.assets.mesh, o.assets.bounds, o.model, lastCamera, width, height).footprintPx;
      return {};
    }
    if (auto offered = offerOptions(); !offered) return offered;
    options.collect();
    std::vector<quality::ObjectView> views;
    for (std::size_t i = 0; i < organs.size(); ++i) {
      Organ& o = organs[i];
      quality::ObjectView v = organView(o.assets.mesh, o.assets.bounds, o.model, lastCamera, width, height);
      o.footprintPx = v.footprintPx;
      v.deforming = o.moved;
      v.importance = o.importance;
      v.hasNormalMap = o.hasNormalMap;
      v.allowed = options.ready(i);  // the built ones: no frame waits for a fit
      views.push_back(std::move(v));
    }
    const auto& chosen = controller->update(views, double(width) * double(height), budgetMs);
    budgetChoices.clear();
    for (std::size_t i = 0; i < organs.size(); ++i) {
      Organ& o = organs[i];
      const quality::ObjectChoice& c = chosen[i];
      if (c.option != o.budgetOption) {
        auto m = options.chosen(i, c.option, controller->table(), o.assets, o.textures, o.choices);
        if (!m) return Error{"budget: organ " + std::to_string(i) + ": " + m.error().message};
        o.method = std::move(*m);
        o.budgetOption = c.option;
        o.optionNew = true;
      }
      budgetChoices.push_back({c.method, c.setting, views[i].footprintPx, c.predictedMs, c.expectedRelRms,
                               std::string(quality::viewClassFrame(c.view)), views[i].viewAngleDeg,
                               c.fallback, c.mesh});
    }
    return {};
  }
  /// Each organ's offered table options, their settings queued for building (once per organ).
  Result<void> offerOptions() {
    if (auto c = ensureController(); !c) return c.error();
    for (std::size_t i = 0; i < organs.size(); ++i)
      options.offer(i, controller->table(), organs[i].assets, organs[i].textures, organs[i].choices);
    return {};
  }
  /// The last frame's measured costs: each organ's own passes and draws (framePassCosts) and each
  /// method's passes of no object; the instruments' and the frame's passes are overhead. Under a
  /// budget they teach the controller's plan; without one, where every organ is drawn with a
  /// table option (setMethodOption), the costs of the options the host chose, so that a budget
  /// set later plans from this machine's costs (QualityController::observeUnplanned).
  void learnBudget(double frameMs) {
    if (!controller || !renderer) return;
    const bool planned = budgetMs > 0.0;
    if (planned
            ? budgetChoices.size() != organs.size()
            : std::any_of(organs.begin(), organs.end(), [](const Organ& o) { return o.budgetOption < 0; }))
      return;
    // The rest of a pass of several organs goes by covered pixels times the option's per-pixel
    // cost (the table's, relative between settings drawn in one pass).
    std::vector<double> weights(scene.objects.size(), 0.0);
    const quality::QualityTable& table = controller->table();
    for (const Organ& o : organs)
      weights[o.objectIndex] =
          std::max(0.0, o.footprintPx) * std::max(table.options[std::size_t(o.budgetOption)].msPerPx, 1e-9);
    const FramePassCosts costs = framePassCosts(renderer->lastTimings(), weights);
    std::vector<bool> used(costs.methodMs.size(), false);
    for (const Organ& o : organs)
      used[std::size_t(render::shadingMethod(o.method))] = true;
    std::vector<quality::PassSample> passes;
    for (std::size_t m = 0; m < used.size(); ++m)
      if (used[m])
        passes.push_back(
            {std::string(render::shadingMethodName(render::ShadingMethod(m))), costs.methodMs[m]});
    if (planned) {
      std::vector<quality::CostSample> samples;
      for (std::size_t i = 0; i < organs.size(); ++i)
        samples.push_back({i, costs.objectMs[organs[i].objectIndex]});
      controller->observe(samples, passes, frameMs);
    } else {
      std::vector<quality::OptionCostSample> samples;
      for (const Organ& o : organs)
        samples.push_back({o.budgetOption, o.footprintPx, costs.objectMs[o.objectIndex], o.optionNew});
      controller->observeUnplanned(samples, passes, frameMs);
    }
    for (Organ& o : organs)
      o.optionNew = false;
  }

  mesh::SurfaceWork meshWork(const Organ& o, render::ShadingMethod method) const {
    if (!settings.meshWorkFollowsMethod) return {};
    const quality::MeshWork w = quality::meshWorkOf(render::shadingMethodName(method), o.hasNormalMap);
    return {.planes = w.planes, .tangents = w.tangents};
  }
  /// The organ's mesh work as its method needs it; what that brought up to date goes up with the
  /// next upload.
  void syncMeshWork(Organ& o, render::ShadingMethod method) {
    const mesh::SurfaceWork work = meshWork(o, method);
    const mesh::SurfaceWork fresh = o.loop ? o.loop->setMeshWork(work) : o.still->setWork(work);
    if (fresh.planes || fresh.tangents) o.changed = true;
  }
  /// Uploads the organs changed since the last upload (GL, context current).
  Result<void> uploadChanged() {
    for (Organ& o : organs) {
      if (!o.changed) continue;
      if (o.loop) {
        auto uploaded = o.loop->upload();
        if (!uploaded) return uploaded.error();
      } else {
        // A host's shape (setPositions): what deforms; stale planes or tangents stay as they are.
        const auto& m = *o.still;
        auto up =
            renderer->updateMesh(o.mesh, {0, m.positions(), m.normals(),
                                          m.tangentsCurrent() ? m.tangents() : std::span<const Float4>{},
                                          m.planesCurrent() ? m.planes() : std::span<const Float4>{}});
        if (!up) return up.error();
      }
      o.changed = false;
    }
    return {};
  }
  /// After the budget's choice: every organ's mesh work follows its method of this frame, and
  /// what that brought up to date is uploaded before the frame renders.
  Result<void> followMethods() {
    for (Organ& o : organs)
      syncMeshWork(o, render::shadingMethod(o.method));
    return uploadChanged();
  }

  Result<void> makeCurrent() {
    if (ownContext) return ownContext->makeCurrent();
    return {};
  }
  Result<Organ*> organ(OrganId id) {
    if (id >= organs.size())
      return Error{"organ " + std::to_string(id) + ": no such organ (the scene has " +
                   std::to_string(organs.size()) + ")"};
    return &organs[id];
  }
  Bounds3 worldBounds() const {
    Bounds3 b;
    for (const Organ& o : organs)
      b.add(transformBounds(o.model, o.assets.bounds));
    return b;
  }
  /// The camera of a render of `aspect` = width / height, and the lights that follow it.
  void frame(float aspect) {
    const Bounds3 b = worldBounds();
    if (fixedCamera) {
      lastCamera = *fixedCamera;
    } else if (!b.empty()) {
      lastCamera = render::frameBoundingBox(b.lo, b.hi, aspect);
    }
    if (lightsFollowFraming && !b.empty() && !scene.lights.empty()) {
      // The main job's key light: above, right and in front of the field (a surgical lamp).
      const Float3 c = b.centre();
      scene.lights[0].positionMm = {c.x + 150.0f, c.y + 200.0f, b.hi.z + 300.0f};
    }
    scene.camera = lastCamera;
  }
  void buildObjects() {
    scene.objects.clear();
    for (Organ& o : organs) {
      render::SceneObject object = organObject(o.loop ? o.loop->meshHandle() : o.mesh, o.textures, o.method,
                                               surfaceMaterialOf(o.assets, settings.ambient));
      if (!o.hasNormalMap) object.normalMap = {};  // SceneSettings::normalMaps off
      object.model = o.model;
      object.doubleSided = o.openSurface;
      // The ray march's texture units per mm are world values (render::SceneObject::model).
      if (auto* march = std::get_if<render::RayMarchSettings>(&object.method))
        march->uvPerMm /= uniformScaleOf(o.model);
      o.objectIndex = scene.objects.size();
      scene.objects.push_back(std::move(object));
      if (o.loop && instrumentVisible)
        if (auto tool = o.loop->instrumentObject()) {
          tool->model = o.model;  // the tool moves in the organ's frame
          scene.objects.push_back(*tool);
        }
    }
  }
};

Scene::Scene(std::unique_ptr<Impl> impl) : m_impl(std::move(impl)) {}
Scene::Scene(Scene&&) noexcept = default;
Scene& Scene::operator=(Scene&&) noexcept = default;

Scene::~Scene() {
  if (!m_impl) return;
  // GL objects die with the context current: the scene's own (a host's must be current).
  if (m_impl->ownContext) (void)m_impl->ownContext->makeCurrent();
  for (auto& o : m_impl->organs)
    if (o.loop) o.loop->detach();
  m_impl->renderer.reset();
}

Result<Scene> Scene::create(const gl::GetProcAddressFn& getProcAddress, const SceneSettings& settings) {
  auto impl = std::make_unique<Impl>();
  impl->settings = settings;
  if (!settings.gl) return Scene(std::move(impl));  // simulation only
  gl::GetProcAddressFn lookup = getProcAddress;
  if (!lookup) {
    auto context = context::createHeadlessContext(settings.context, settings.headless);
    if (!context) return Error{"no headless GL context (EGL, then OSMesa): " + context.error().message};
    impl->ownContext = std::move(*context);
    lookup = impl->ownContext->procAddressFunction();
  }
  auto renderer = render::Renderer::create(lookup, settings.renderer);
  if (!renderer) return renderer.error();
  impl->renderer.emplace(std::move(*renderer));
  return Scene(std::move(impl));
}

Result<OrganId> Scene::addOrgan(const OrganDesc& desc) {
  Impl& s = *m_impl;
  if (auto ok = checkModel(desc.model); !ok)
    return Error{"organ " + desc.mesh.string() + ": " + ok.error().message};
  if (auto current = s.makeCurrent(); !current) return current.error();
  Impl::Organ organ;
  organ.model = desc.model;
  // 1 what moves it (a scenario) and what it looks like (mesh, material, textures).
  std::optional<scenario::Scenario> scenario;
  if (!desc.scenario.empty()) {
    auto parsed = scenario::loadScenario(desc.scenario, {.sharedMeshesDir = s.settings.sharedMeshesDir});
    if (!parsed) return parsed.error();
    if (!desc.mesh.empty()) parsed->mesh = desc.mesh;  // the scenario simulates the organ drawn
    scenario = std::move(*parsed);
  } else if (desc.mesh.empty()) {
    return Error{"organ: give a mesh file, or a scenario that names one"};
  }
  const OrganSource source = sourceOf(desc, s.settings, scenario ? &*scenario : nullptr);
  auto assets = loadOrganAssets(source);
  if (!assets) return assets.error();
  organ.assets = std::move(*assets);
  // 2 its mesh on the renderer: a loop for a simulated organ, else the rest shape once.
  if (scenario) {
    OrganLoopConfig config = s.settings.loop;
    config.planes = organ.assets.planes;
    config.uploadPlanes = true;  // any method may be chosen at run time, ray marching among them
    auto loop = OrganLoop::create(*scenario, organ.assets.mesh, config);
    if (!loop) return loop.error();
    organ.loop.emplace(std::move(*loop));
  } else {
    auto still = mesh::DeformableSurface::create(organ.assets.mesh, organ.assets.planes);
    if (!still) return still.error();
    organ.still.emplace(std::move(*still));
  }
  organ.choices = desc.methods.value_or(s.settings.methods);
  organ.importance = std::max(0.0, desc.importance);
  // An open surface (a patch, a cut organ) must not vanish when seen from behind (issue 14).
  organ.openSurface = !(organ.loop ? organ.loop->surface() : *organ.still).boundaryVertices().empty();
  organ.hasNormalMap = organ.assets.normalMap.has_value() && s.settings.normalMaps;
  if (!s.renderer) {  // simulation only: the method is not built, its mesh work is kept
    s.syncMeshWork(organ, desc.method);
    s.organs.push_back(std::move(organ));
    return s.organs.size() - 1;
  }
  render::Renderer& r = *s.renderer;
  if (organ.loop) {
    if (auto attached = organ.loop->attach(r); !attached) return attached.error();
  } else {
    const auto& m = *organ.still;
    auto handle =
        r.createMesh({m.positions(), m.normals(), m.tangents(), m.uvs(), m.triangles(), m.planes()});
    if (!handle) return handle.error();
    organ.mesh = *handle;
  }
  // 3 its textures and method.
  auto textures = uploadOrganTextures(r, organ.assets);
  if (!textures) return textures.error();
  organ.textures = *textures;
  auto method = organMethod(desc.method, organ.assets, organ.textures, organ.choices);
  if (!method) return method.error();
  organ.method = std::move(*method);
  s.syncMeshWork(organ, desc.method);
  s.organs.push_back(std::move(organ));
  return s.organs.size() - 1;
}

Result<void> Scene::setMethod(OrganId id, render::ShadingMethod method) {
  auto o = m_impl->organ(id);
  if (!o) return o.error();
  if (!m_impl->renderer) return Error{"setMethod: this scene has no renderer (SceneSettings::gl)"};
  auto settings = organMethod(method, (*o)->assets, (*o)->textures, (*o)->choices);
  if (!settings) return settings.error();
  (*o)->method = std::move(*settings);
  (*o)->budgetOption = -1;  // a budget's next choice replaces it
  (*o)->optionNew = true;
  m_impl->syncMeshWork(**o, method);
  return {};
}

Result<void> Scene::setMethodOption(OrganId id, const quality::QualityOption& option) {
  auto o = m_impl->organ(id);
  if (!o) return o.error();
  if (!m_impl->renderer) return Error{"setMethodOption: this scene has no renderer (SceneSettings::gl)"};
  auto settings = methodOfOption(option, (*o)->assets, (*o)->textures, (*o)->choices);
  if (!settings) return settings.error();
  // The option's index in the controller's table: its frames teach the controller its cost, and
  // its settings are kept for a budget's choice of it.
  if (auto c = m_impl->ensureController(); !c) return c.error();
  (*o)->budgetOption = m_impl->controller->table().find(option.method, option.setting);
  if ((*o)->budgetOption >= 0) m_impl->options.keep(id, (*o)->budgetOption, *settings);
  (*o)->method = std::move(*settings);
  (*o)->optionNew = true;
  m_impl->syncMeshWork(**o, render::shadingMethod((*o)->method));
  return {};
}

Result<void> Scene::setPositions(OrganId id, std::span<const Float3> positions) {
  auto o = m_impl->organ(id);
  if (!o) return o.error();
  if (!(*o)->still)
    return Error{"organ " + std::to_string(id) + ": its scenario moves it; set positions of static organs"};
  const auto rest = (*o)->still->geometricRestPositions();
  if (positions.size() != rest.size())
    return Error{"organ " + std::to_string(id) + ": give " + std::to_string(rest.size()) +
                 " positions (one per geometric vertex), not " + std::to_string(positions.size())};
  (*o)->still->update(positions);
  (*o)->changed = true;
  return {};
}

Result<void> Scene::setTransform(OrganId id, const Mat4& model) {
  auto o = m_impl->organ(id);
  if (!o) return o.error();
  if (auto ok = checkModel(model); !ok) return ok.error();
  (*o)->model = model;
  return {};
}

std::size_t Scene::organCount() const {
  return m_impl->organs.size();
}
const OrganAssets& Scene::assets(OrganId id) const {
  return m_impl->organs.at(id).assets;
}
const OrganLoop* Scene::loop(OrganId id) const {
  const auto& o = m_impl->organs.at(id);
  return o.loop ? &*o.loop : nullptr;
}

Result<void> Scene::setInstrumentPose(const InstrumentPose& pose) {
  if (!isFinite(pose.tipMm) || !isFinite(pose.axis) || !std::isfinite(pose.radiusMm))
    return Error{"instrument pose: give finite numbers (mm)"};
  if (length(pose.axis) < 1e-6f) return Error{"instrument pose: the axis must not be zero"};
  m_impl->pendingPose = pose;
  return {};
}

Result<void> Scene::setGrasp(bool grasp) {
  m_impl->pendingGrasp = grasp;
  return {};
}

Float3 Scene::instrumentForceN() const {
  return m_impl->forceN;
}

void Scene::setInstrumentVisible(bool visible) {
  m_impl->instrumentVisible = visible;
}

void Scene::setCamera(const render::Camera& camera) {
  m_impl->fixedCamera = camera;
}
void Scene::frameOrgans() {
  m_impl->fixedCamera.reset();
}
const render::Camera& Scene::camera() const {
  return m_impl->lastCamera;
}
void Scene::setShadows(bool shadows) {
  if (!m_impl->scene.lights.empty()) m_impl->scene.lights[0].castsShadows = shadows;
}
render::Scene& Scene::renderScene() {
  m_impl->lightsFollowFraming = false;
  return m_impl->scene;
}
Result<void> Scene::setBudgetMs(double budgetMs) {
  if (!(budgetMs >= 0.0) || !std::isfinite(budgetMs))
    return Error{"budget: give a finite frame budget in ms >= 0 (0: off)"};
  if (budgetMs > 0.0 && !m_impl->renderer)
    return Error{"budget: this scene has no renderer (SceneSettings::gl)"};
  m_impl->budgetMs = budgetMs;
  if (budgetMs == 0.0) m_impl->budgetChoices.clear();
  if (budgetMs > 0.0) return m_impl->offerOptions();  // their settings start building now
  return {};
}
std::size_t Scene::budgetOptionsPending() const {
  return m_impl->options.pending();
}
Result<void> Scene::prepareBudgetOptions() {
  if (!m_impl->renderer) return Error{"prepareBudgetOptions: this scene has no renderer (SceneSettings::gl)"};
  if (auto offered = m_impl->offerOptions(); !offered) return offered;
  m_impl->options.finish();
  return {};
}
double Scene::budgetMs() const {
  return m_impl->budgetMs;
}
const std::vector<BudgetChoice>& Scene::budgetChoices() const {
  return m_impl->budgetChoices;
}
const quality::QualityController* Scene::qualityController() const {
  return m_impl->controller ? &*m_impl->controller : nullptr;
}
render::Renderer& Scene::renderer() {
  return *m_impl->renderer;
}

Result<StepReport> Scene::step(double dtS) {
  Impl& s = *m_impl;
  if (!(dtS >= 0.0) || !std::isfinite(dtS)) return Error{"step: dt must be a finite number of seconds >= 0"};
  StepReport report;
  // The first pose is taken at once; later ones are approached over the step's frames.
  const InstrumentPose from = s.lastPose ? *s.lastPose : s.pendingPose.value_or(InstrumentPose{});
  const std::optional<InstrumentPose> to = s.pendingPose;
  const std::optional<bool> grasp = s.pendingGrasp;
  s.pendingPose.reset();
  s.pendingGrasp.reset();
  Float3 force{};
  for (Impl::Organ& o : s.organs) {
    if (!o.loop) continue;
    const double frameS = o.loop->run().scenario().frameTime;
    o.pendingS += dtS;
    int frames = int(std::floor(o.pendingS / frameS + 1e-9));
    if (frames > s.settings.maxFramesPerStep) {
      report.droppedS += (frames - s.settings.maxFramesPerStep) * frameS;
      frames = s.settings.maxFramesPerStep;
      o.pendingS = 0.0;
    } else {
      o.pendingS = std::max(0.0, o.pendingS - frames * frameS);
    }
    // The host's pose in this organ's own frame (the inverse of its model matrix).
    const Mat4 toLocal = inverseAffine(o.model);
    const float scale = uniformScaleOf(o.model);
    for (int k = 0; k < frames; ++k) {
      InstrumentInput input;
      if (to) {
        // The tool moves linearly from the last pose to the new one over this step's frames.
        const float t = float(k + 1) / float(frames);
        const Float3 tip = from.tipMm + (to->tipMm - from.tipMm) * t;
        const Float3 axis = normalizeOr(from.axis + (to->axis - from.axis) * t, to->axis);
        input.pose = sim::ToolPose{toVec3d(transformPoint(toLocal, tip)),
                                   toVec3d(normalizeOr(transformDirection(toLocal, axis), {0, 0, 1}))};
        if (to->radiusMm > 0.0f && k == 0) input.radiusMm = double(to->radiusMm / scale);
      }
      if (grasp && k == 0) input.grasp = grasp;
      auto f = o.loop->step(input);
      if (!f) return f.error();
      report.ms.simulateMs += f->ms.simulateMs;
      report.ms.meshMs += f->ms.meshMs;
      report.ms.totalMs += f->ms.totalMs;
      report.divergences += f->simulation.divergenceEvents;
      if (k + 1 == frames) {
        const auto& F = f->simulation.forceN;
        force = force + transformDirection(o.model, {float(F.x), float(F.y), float(F.z)}) * (1.0f / scale);
      }
    }
    if (frames > 0) o.changed = true;
    report.frames = std::max(report.frames, frames);
    report.simulatedS = std::max(report.simulatedS, frames * frameS);
  }
  if (to) s.lastPose = *to;
  if (report.frames > 0) s.forceN = force;
  report.forceN = s.forceN;
  return report;
}

Result<void> Scene::upload() {
  Impl& s = *m_impl;
  if (!s.renderer) return {};  // simulation only: nothing to upload
  if (auto current = s.makeCurrent(); !current) return current.error();
  for (Impl::Organ& o : s.organs)
    o.moved = o.changed;
  return s.uploadChanged();
}

Result<StepReport> Scene::update(double dtS) {
  auto report = step(dtS);
  if (!report) return report.error();
  if (auto up = upload(); !up) return up.error();
  return report;
}

Result<LoopFrame> Scene::advance(OrganId id, const InstrumentInput& input, Image8* image, int width,
                                 int height) {
  Impl& s = *m_impl;
  auto o = s.organ(id);
  if (!o) return o.error();
  if (!(*o)->loop) return Error{"organ " + std::to_string(id) + ": a static organ has no frames to advance"};
  if (!image) {  // phases 1-2; the next render uploads
    (*o)->changed = true;
    return (*o)->loop->step(input);
  }
  if (!s.renderer) return Error{"advance: this scene has no renderer to render with (SceneSettings::gl)"};
  if (width <= 0 || height <= 0) return Error{"advance: the image must be at least 1 x 1 pixels"};
  const Stopwatch watch;
  if (auto up = upload(); !up) return up.error();  // the other organs' changes
  s.frame(float(width) / float(height));
  if (auto b = s.applyBudget(width, height); !b) return b.error();
  if (auto w = s.followMethods(); !w) return w.error();
  s.buildObjects();
  const RenderRequest request{
      .scene = &s.scene, .width = width, .height = height, .image = image, .host = {}};
  auto frame = (*o)->loop->advance(input, &request);
  if (frame) s.learnBudget(watch.elapsedMs());
  return frame;
}

Result<void> Scene::render(const render::HostFramebuffer& target) {
  Impl& s = *m_impl;
  if (!s.renderer) return Error{"render: this scene has no renderer (SceneSettings::gl)"};
  if (target.width <= 0 || target.height <= 0)
    return Error{"render: the viewport must be at least 1 x 1 pixels"};
  const Stopwatch watch;  // the frame as the host sees it: upload and render
  if (auto up = upload(); !up) return up.error();
  s.frame(float(target.width) / float(target.height));
  if (auto b = s.applyBudget(target.width, target.height); !b) return b.error();
  if (auto w = s.followMethods(); !w) return w.error();
  s.buildObjects();
  auto done = s.renderer->renderTo(s.scene, target);
  if (done) s.learnBudget(watch.elapsedMs());
  return done;
}

Result<Image8> Scene::renderImage(int width, int height) {
  Impl& s = *m_impl;
  if (!s.renderer) return Error{"render: this scene has no renderer (SceneSettings::gl)"};
  if (width <= 0 || height <= 0) return Error{"render: the image must be at least 1 x 1 pixels"};
  const Stopwatch watch;  // the frame as the host sees it: upload, render, read back
  if (auto up = upload(); !up) return up.error();
  s.frame(float(width) / float(height));
  if (auto b = s.applyBudget(width, height); !b) return b.error();
  if (auto w = s.followMethods(); !w) return w.error();
  s.buildObjects();
  auto image = s.renderer->renderImage(s.scene, width, height);
  if (image) s.learnBudget(watch.elapsedMs());
  return image;
}

Result<void> Scene::renderPng(const std::filesystem::path& png, int width, int height) {
  auto image = renderImage(width, height);
  if (!image) return image.error();
  return writePng(png, *image);
}

}  // namespace tissue::scene

namespace tissue::scene {

Result<SimulatedOrgan> loadSimulatedOrgan(const OrganDesc& desc, const SceneSettings& settings) {
  auto parsed = scenario::loadScenario(desc.scenario, {.sharedMeshesDir = settings.sharedMeshesDir});
  if (!parsed) return parsed.error();
  if (!desc.mesh.empty()) parsed->mesh = desc.mesh;  // the scenario simulates the organ drawn
  auto assets = loadOrganAssets(sourceOf(desc, settings, &*parsed));
  if (!assets) return assets.error();
  return SimulatedOrgan{.scenario = std::move(*parsed), .assets = std::move(*assets)};
}

}  // namespace tissue::scene
