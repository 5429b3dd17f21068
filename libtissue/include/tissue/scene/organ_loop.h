#pragma once
/// \file
/// The per-frame loop of a simulated organ, owned by the library and shared by tissue-sim's
/// `demo` and `replay`, the viewer and any host. One frame runs four named, timed phases, top to
/// bottom (STYLE.md rule 14; the shape of PositionBasedDynamics' TimeStepController::step):
///
///   1 simulate   live instrument input (pose, grasp), then one scenario frame: springs,
///                integration, contact and grasp inside the substeps
///   2 mesh       the simulated surface positions into the mesh module: normals, local planes
///                (incremental re-fit), tangent frames
///   3 upload     what changed, into the renderer's buffers (glBufferSubData)
///   4 render     the scene, into the renderer's own target (read back) or a host framebuffer
///
/// Phases 3 and 4 run only when a renderer is attached and a render is requested; the loop
/// itself never touches GL otherwise, and never reads the clock back from the GPU.

#include <memory>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "tissue/core/image.h"
#include "tissue/core/result.h"
#include "tissue/core/surface_mesh.h"
#include "tissue/mesh/deformable_surface.h"
#include "tissue/render/renderer.h"
#include "tissue/render/scene.h"
#include "tissue/scenario/scenario_run.h"
#include "tissue/scene/instrument_mesh.h"

namespace tissue::scene {

/// Live instrument input for one frame (viewer, replayed session, host, haptic device). Empty
/// fields leave the scenario's script (or the last live input) in charge.
struct InstrumentInput {
  std::optional<sim::ToolPose> pose;  ///< mm: the tool moves linearly to it over the frame
  std::optional<bool> grasp;          ///< true grasps, false releases (before the frame's simulation)
  std::optional<double> radiusMm;     ///< mm, > 0: a new tool radius (its drawn mesh follows at upload)
};

/// Wall-clock cost of one frame per phase (ms).
struct LoopPhases {
  double simulateMs = 0.0;  ///< 1: input and the scenario frame (substeps, contact, grasp)
  double meshMs = 0.0;      ///< 2: positions, normals, planes and tangents
  double uploadMs = 0.0;    ///< 3: glBufferSubData of what changed
  double renderMs = 0.0;    ///< 4: the render call (with read-back when offscreen)
  double totalMs = 0.0;     ///< the whole frame
};

/// What one frame did.
struct LoopFrame {
  scenario::FrameMetrics simulation;  ///< force on the tool (N), contacts, divergence, ...
  mesh::SurfaceUpdateStats mesh;      ///< per mesh phase ms and the planes re-fitted
  LoopPhases ms;
};

/// Per-frame cost of each phase over a run (ms), in the order the loop runs them: what a loop
/// report summarises (median, p99, max per phase; tissue/core/statistics.h).
struct LoopPhaseSamples {
  std::vector<std::pair<std::string, std::vector<double>>> phases{
      {"1 simulate (springs, contact, grasp)", {}},
      {"2 mesh: positions in", {}},
      {"2 mesh: normals", {}},
      {"2 mesh: planes (incremental)", {}},
      {"2 mesh: tangent frames", {}},
      {"3 upload", {}},
      {"4 render (lit, read back)", {}},
      {"frame total", {}}};
  /// Appends one frame's figures.
  void add(const LoopFrame& frame);
};

/// Where phase 4 draws. Offscreen: into `image` (renderImage, read back); host: into the
/// host's framebuffer (renderTo; the host's GL state is restored).
struct RenderRequest {
  const render::Scene* scene = nullptr;         ///< must contain the organ's object (object())
  int width = 0;                                ///< pixels (offscreen)
  int height = 0;                               ///< pixels (offscreen)
  Image8* image = nullptr;                      ///< offscreen result; nullptr with `host`
  std::optional<render::HostFramebuffer> host;  ///< draw into this framebuffer instead
};

/// Settings of the loop (plain struct with defaults).
struct OrganLoopConfig {
  mesh::PlaneFitSettings planes{};  ///< the local planes (sigma_t mm^-1 sets their radius)
  /// The incremental re-fit's stated tolerance: normals within 1e-4 rad of a full re-fit by
  /// default; maxNormalErrorRad = 0 re-fits exactly (bit-identical to a full re-fit).
  mesh::PlaneRefitSettings refit{};
  unsigned meshThreads = 0;         ///< threads of the mesh update (0: the hardware's)
  bool uploadPlanes = false;        ///< create the renderer mesh with planes and upload them each frame
  bool drawInstrument = true;       ///< attach() also uploads the scenario's instrument (instrumentObject())
  InstrumentLook instrumentLook{};  ///< its shaft
};

/// A simulated organ: the scenario's simulation and the surface the renderer draws, kept in step
/// frame by frame. Not copyable; movable.
class OrganLoop {
 public:
  /// `scenario` moves `surface` (a render mesh with UVs, mm): the scenario's simulated surface
  /// must have the same geometric vertices (the same mesh file). Fails, naming both files, when
  /// they differ, and on any error of the scenario, the mesh or the planes.
  static Result<OrganLoop> create(const scenario::Scenario& scenario, SurfaceMesh surface,
                                  const OrganLoopConfig& config = {});
  /// Does not detach: destroying GL objects needs the renderer's context current, which a
  /// destructor cannot know. Call detach() first with the context current, or destroy the
  /// renderer (which frees everything it holds).
  ~OrganLoop();
  OrganLoop(OrganLoop&&) noexcept;
  OrganLoop& operator=(OrganLoop&&) noexcept;

  /// Uploads the organ's mesh (its current shape) to `renderer` and returns its handle; later
  /// frames update it in place. The renderer's context must be current; the renderer must
  /// outlive the loop or be detached first.
  Result<render::MeshHandle> attach(render::Renderer& renderer);
  /// Forgets the renderer (destroys the meshes; its context must be current).
  void detach();
  /// The instrument as a scene object (a steel-grey Lit tip and shaft, moved every frame in
  /// phase 3), when attached with OrganLoopConfig::drawInstrument and the scenario has one. Add it
  /// to the scene's objects to draw it.
  std::optional<render::SceneObject> instrumentObject() const;

  /// One frame: 1 simulate, 2 mesh, 3 upload (attached), 4 render (when `render` is given and
  /// attached). Fails on bad input (a NaN pose names it), on a render error, and when the
  /// simulation produced non-finite values (never handed on).
  Result<LoopFrame> advance(const InstrumentInput& input = {}, const RenderRequest* render = nullptr);

  /// Phases 1 and 2 only (simulate, mesh): no GL, so a host may run them on its simulation
  /// thread while its render thread draws the previous frame; then upload() on the GL thread.
  /// LoopFrame::ms.uploadMs and renderMs stay 0.
  Result<LoopFrame> step(const InstrumentInput& input = {});
  /// Phase 3 only: uploads what the last step() changed (attached; the renderer's context
  /// current): the planes and tangents only while the mesh work keeps them. Returns its ms; 0
  /// when not attached.
  Result<double> upload();

  /// What phase 2 keeps current besides positions and normals (mesh::DeformableSurface::setWork):
  /// the local planes only for a method that reads them, the tangents only for one that does.
  /// Switching one on brings it up to date at once; returns what it brought up to date (the next
  /// upload() sends it).
  mesh::SurfaceWork setMeshWork(const mesh::SurfaceWork& work);

  const scenario::ScenarioRun& run() const;
  const mesh::DeformableSurface& surface() const;
  /// The simulated surface positions (mm), one per geometric vertex, as of the last frame.
  std::span<const Float3> geometricPositions() const;
  /// The renderer's handle of the organ's mesh (valid while attached).
  render::MeshHandle meshHandle() const;
  long frame() const;

 private:
  Result<void> buildToolMesh();  ///< (re)creates the drawn instrument (attached, context current)
  struct Impl;
  explicit OrganLoop(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> m_impl;
};

/// What a run of the loop keeps for its report (a host's session summary; tissue-sim's demo and
/// replay): every frame's metrics and phase costs, the planes re-fitted, and the shapes at the
/// hardest push without a grasp and the hardest pull while grasping (the force along z, N).
struct LoopRecord {
  std::vector<scenario::FrameMetrics> frames;
  LoopPhaseSamples phases;
  double refittedFraction = 0.0;           ///< planes re-fitted per frame, as a fraction of all (summed)
  long planeFrames = 0;                    ///< frames whose mesh phase ran the plane re-fit (SurfaceWork)
  long tangentFrames = 0;                  ///< frames whose mesh phase computed the tangent frames
  double maxPushN = 0.0;                   ///< N, the largest +z force on the tool without a grasp
  double maxPullN = 0.0;                   ///< N, the largest -z force while grasping
  long pokedFrame = -1, liftedFrame = -1;  ///< frames of those two (-1: none)
  std::vector<Float3> pokedPositions, liftedPositions;  ///< mm, the geometric vertices then
  /// Appends the frame `loop` just ran (`frame`, its result).
  void add(const LoopFrame& frame, const OrganLoop& loop);
  /// The mean fraction of planes re-fitted per frame.
  double meanRefittedFraction() const {
    return frames.empty() ? 0.0 : refittedFraction / double(frames.size());
  }
};

}  // namespace tissue::scene
