#pragma once
/// \file
/// A scene of organs, as a host embeds it: each organ is a mesh, a material file, a model
/// transform, a shading method and an optional simulation (a scenario), all set up here once
/// for tissue-sim, the viewer, the C API and any host. The frame, top to bottom:
///
///   step(dt)     1 simulate  2 mesh    fixed scenario frames as time accumulates; no GL, so it
///                                      may run on a simulation thread (not during render)
///   render(...)  3 upload    4 render  what changed, then the frame, into a host framebuffer
///                                      (its depth tested and written) or the scene's own target
///
/// GL: create(), addOrgan(), upload(), render*() and the destructor need the context current:
/// the host's (create() given its getProcAddress) or the scene's own headless one, which these
/// calls make current themselves. Nothing here reads the environment, aborts or throws.
/// Units: mm, s, N; model matrices column-major, object mm to world mm.

#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "tissue/context/headless_context.h"
#include "tissue/core/image.h"
#include "tissue/core/result.h"
#include "tissue/core/vec_math.h"
#include "tissue/gl/proc_address.h"
#include "tissue/quality/controller.h"
#include "tissue/render/renderer.h"
#include "tissue/render/scene.h"
#include "tissue/scenario/scenario.h"
#include "tissue/scene/budget.h"
#include "tissue/scene/organ_assets.h"
#include "tissue/scene/organ_loop.h"
#include "tissue/scene/organ_methods.h"

namespace tissue::scene {

/// An organ to add (plain struct with defaults).
struct OrganDesc {
  std::filesystem::path mesh{};      ///< with a scenario: simulated instead of its own (empty: its own)
  std::filesystem::path material{};  ///< data/materials/<organ>.json; empty: defaultMaterial()
  std::filesystem::path scenario{};  ///< data/scenarios/*.json; empty: a static organ
  Mat4 model = kIdentity4;           ///< column-major, object (mm) to world (mm); rigid + uniform scale
  /// Without GL (SceneSettings::gl) nothing is built, but its mesh work follows it all the same.
  render::ShadingMethod method = render::ShadingMethod::Lit;
  float meshScaleToMm = 1.0f;  ///< mm per file unit of a static organ's mesh (a scenario states its own)
  std::optional<MethodChoices> methods{};  ///< this organ's kernel, taps, ...; empty: SceneSettings::methods
  double importance = 1.0;  ///< >= 0, its weight in the quality controller's error (Scene::setBudgetMs)
};

/// Settings of a scene (plain struct with defaults).
struct SceneSettings {
  render::RendererSettings renderer;  ///< shaders (embedded or a folder), MSAA; no timers by default
  context::ContextRequest context;    ///< the scene's own headless context only
  context::HeadlessOptions headless{.backend = {}, .log = false};  ///< EGL, then OSMesa
  MaterialFileOptions materials;                                   ///< where material textures are looked up
  /// An organ without a material file gets <materialsDir>/<its mesh's stem>.json when that file
  /// exists (a project's data/materials/), else defaultMaterial(). Empty: always the default.
  std::filesystem::path materialsDir;
  std::filesystem::path sharedMeshesDir;  ///< where scenarios find meshes they name by bare name
  OrganLoopConfig loop;                   ///< planes, re-fit tolerance, mesh threads, the instrument
  MethodChoices methods;                  ///< kernel, taps, Gaussians, ray-march samples
  /// Linear RGB ambient radiance on every organ drawn lit, separable, texture space or parallax:
  /// an artist's fill light that the path-traced truth does not have (the atlas and the budget
  /// bench score with 0; docs/RESULTS.md gives its error).
  Float3 ambient{0.06f, 0.055f, 0.055f};  ///< render::Material{}.ambient
  /// Draw each organ's normal map (its material's textures.normal_map): mesoscale bumps that the
  /// mesh does not have and the path-traced truth does not model, so the atlas and the budget
  /// bench score with false (docs/RESULTS.md gives its error). false also drops the tangent
  /// frames the map needed (quality::meshWorkOf).
  bool normalMaps = true;
  /// false: no context nor renderer, the simulation only (a replay, a server): step() and
  /// advance() without an image work, render*() and setMethod() fail, upload() does nothing.
  bool gl = true;
  /// step(dt) runs at most this many scenario frames (a host that stalls does not make the next
  /// frame slower still); the time beyond is dropped and counted in StepReport::droppedS.
  int maxFramesPerStep = 4;
  /// The quality controller under Scene::setBudgetMs: footprint threshold, hysteresis, learning.
  quality::ControllerSettings quality;
  /// Its table: an atlas's JSON (tissue-sim atlas --json); empty: quality::defaultQualityTable().
  std::filesystem::path qualityTable;
  /// true: each organ's mesh update keeps only what its current method reads
  /// (quality::meshWorkOf: the local planes for the ray march, tangents for a normal map, the ray
  /// march and parallax), with or without a budget; a switch to a method that reads more brings
  /// it up to date before that frame renders. false: planes and tangents every frame, whatever
  /// the method (a host or an inspection that reads OrganLoop::surface()'s planes).
  bool meshWorkFollowsMethod = true;
};

/// The instrument as a host moves it (world space).
struct InstrumentPose {
  Float3 tipMm{};                 ///< mm, centre of the tool's tip sphere (of a capsule's core)
  Float3 axis{0.0f, 0.0f, 1.0f};  ///< unit, a capsule's core direction
  float radiusMm = 0.0f;          ///< mm; <= 0 keeps the scenario's
};

/// What one step(dt) did.
struct StepReport {
  int frames = 0;           ///< scenario frames run
  double simulatedS = 0.0;  ///< s, their total time
  double droppedS = 0.0;    ///< s, time not simulated (maxFramesPerStep)
  LoopPhases ms;            ///< ms, summed over the frames and organs (upload and render: 0)
  Float3 forceN{};          ///< N, world space, the last frame's force on the tool, over all organs
  int divergences = 0;      ///< divergence events (rollbacks) in its frames, all recovered
};

using OrganId = std::size_t;

/// A scenario and the organ it moves, loaded as Scene::addOrgan loads them (GL-free): for a loop
/// without a renderer (OrganLoop::create with assets.mesh and assets.planes).
struct SimulatedOrgan {
  scenario::Scenario scenario;
  OrganAssets assets;
};

/// Loads `desc`'s scenario (its mesh, or desc.mesh instead) and the organ's assets, with the
/// material rule and folders of `settings`. Errors name the file at fault.
Result<SimulatedOrgan> loadSimulatedOrgan(const OrganDesc& desc, const SceneSettings& settings = {});

/// The scene. Movable, not copyable.
class Scene {
 public:
  /// With the host's `getProcAddress` (its context current), the scene renders with the host's
  /// context. Empty: the scene creates its own headless context (EGL, then OSMesa).
  static Result<Scene> create(const gl::GetProcAddressFn& getProcAddress, const SceneSettings& settings = {});
  ~Scene();
  Scene(Scene&&) noexcept;
  Scene& operator=(Scene&&) noexcept;

  /// Loads an organ (GL: uploads it). Errors name the file at fault.
  Result<OrganId> addOrgan(const OrganDesc& organ);
  /// Switches an organ's method at run time; the error says which this organ offers. A method
  /// that reads planes or tangents the last one did not gets them brought up to date at once
  /// (SceneSettings::meshWorkFollowsMethod).
  Result<void> setMethod(OrganId organ, render::ShadingMethod method);
  /// Sets an organ's method and setting to a quality table option (quality/quality_table.h, the
  /// atlas's names; "lit wrap" the fallback), as the controller would; the budget, when on,
  /// replaces it at the next render. While no budget is set and every organ is drawn with a table
  /// option, each frame teaches the controller (made here, from SceneSettings::qualityTable)
  /// what those options cost on this machine, so that a budget set later plans from measured
  /// costs (quality::QualityController::observeUnplanned). Errors: the option's method is not
  /// offered by the organ's material, or the quality table does not load.
  Result<void> setMethodOption(OrganId organ, const quality::QualityOption& option);
  /// A static organ's shape as the host deforms it (its own simulator, a recorded state): one
  /// position per geometric vertex of its mesh (mm, object space); normals, planes and tangents
  /// follow, uploaded at the next render. A simulated organ's scenario moves it: an error.
  Result<void> setPositions(OrganId organ, std::span<const Float3> geometricPositionsMm);
  /// Column-major, object mm to world mm: rigid motion and uniform scale.
  Result<void> setTransform(OrganId organ, const Mat4& model);
  std::size_t organCount() const;
  const OrganAssets& assets(OrganId organ) const;
  /// The organ's simulation loop; nullptr for a static organ.
  const OrganLoop* loop(OrganId organ) const;

  /// Live instrument input for every simulated organ (in each organ's own frame through its
  /// model matrix), from the next step on; the scenario's script stops.
  Result<void> setInstrumentPose(const InstrumentPose& pose);
  /// Grasps (true) or releases (false) at the next step.
  Result<void> setGrasp(bool grasp);
  /// N, world space: the last frame's force on the tool, over all organs.
  Float3 instrumentForceN() const;
  /// Draws the scenarios' instruments (true, the default) or leaves them to the host.
  void setInstrumentVisible(bool visible);

  /// A fixed camera (the host's own: the same view and projection as its frame when depth is
  /// shared). Until one is set, the camera frames every organ for each render's aspect.
  void setCamera(const render::Camera& camera);
  /// Back to framing every organ.
  void frameOrgans();
  /// The camera of the last render (framed or fixed).
  const render::Camera& camera() const;
  /// The first light casts shadows (and gives the separable method its transmission) or not
  /// (the default); the same as renderScene().lights[0].castsShadows, with the lights still
  /// following the framing.
  void setShadows(bool shadows);
  /// Lights, background, exposure (the objects are the scene's). Lights follow the framing
  /// until this is called.
  render::Scene& renderScene();

  /// Phases 1-2 for `dtS` seconds of simulation (>= 0, finite). No GL.
  Result<StepReport> step(double dtS);
  /// Phase 3 (GL): what the last steps changed. render*() call it.
  Result<void> upload();
  /// step(dtS) then upload(): the whole update of a frame.
  Result<StepReport> update(double dtS);

  /// One frame of simulated organ `organ` with exact input (a recorded session's frame, a haptic
  /// device's sample; poses in the organ's own frame), the host's fixed-step loop: OrganLoop::advance's
  /// four phases, the fourth rendering the whole scene into `image` (`width` x `height` pixels,
  /// read back) when `image` is given. Other organs do not move. GL with `image`.
  Result<LoopFrame> advance(OrganId organ, const InstrumentInput& input = {}, Image8* image = nullptr,
                            int width = 0, int height = 0);

  /// Phases 3-4 into the host's framebuffer (state restored; see render::Renderer::renderTo).
  Result<void> render(const render::HostFramebuffer& target);
  /// Phases 3-4 into the scene's own target, read back (RGBA8, rows top to bottom).
  Result<Image8> renderImage(int width, int height);
  /// renderImage, written as PNG atomically.
  Result<void> renderPng(const std::filesystem::path& png, int width, int height);

  /// A frame budget (ms, >= 0; 0: off, the organs keep the methods they have): each render*()
  /// then lets the quality controller (quality/controller.h) choose every organ's method and
  /// setting from its projected footprint, distance, view angle and motion, under the budget, and
  /// learns the costs from the renderer's measured pass times (on lazy rasterisers such as
  /// llvmpipe only with RendererSettings::finishPasses). The instruments count as overhead.
  Result<void> setBudgetMs(double budgetMs);
  double budgetMs() const;
  /// Per organ, what the controller chose at the last render (empty while the budget is off).
  const std::vector<BudgetChoice>& budgetChoices() const;
  /// The controller (its table, learned costs, plan); nullptr until a budget is set.
  const quality::QualityController* qualityController() const;
  /// The organs' offered table options whose renderer settings are still being built. An option's
  /// settings are a CPU fit of the material's optics (separable kernels ~10 ms, texture space's
  /// Gaussians up to ~100 ms each, 2-core VM), built on a worker thread from the first budget on
  /// (setBudgetMs, or an organ's first budgeted frame), never on the frame path: the controller
  /// chooses among the built ones (lit's at once). 0 once all are, and while no budget was set.
  std::size_t budgetOptionsPending() const;
  /// Waits on the calling thread until every organ's offered options are built (a host's loading
  /// screen: its first budgeted frames then choose from all). Not for the frame path.
  Result<void> prepareBudgetOptions();

  /// The renderer (context current for its calls), e.g. for its last timings; SceneSettings::gl only.
  render::Renderer& renderer();

 private:
  struct Impl;
  explicit Scene(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> m_impl;
};

}  // namespace tissue::scene
