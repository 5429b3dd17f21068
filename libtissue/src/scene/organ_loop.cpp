// The per-frame loop of a simulated organ: simulate -> mesh -> upload -> render, each phase
// named and timed (organ_loop.h).
#include "tissue/scene/organ_loop.h"

#include <string>
#include <utility>

#include <algorithm>

#include "tissue/core/stopwatch.h"

namespace tissue::scene {

struct OrganLoop::Impl {
  std::unique_ptr<scenario::ScenarioRun> run;
  std::optional<mesh::DeformableSurface> surface;
  OrganLoopConfig config;
  std::vector<Float3> positions;  ///< mm, simulated surface, one per geometric vertex
  render::Renderer* renderer = nullptr;
  render::MeshHandle mesh;
  // The instrument's drawable: its rest mesh (tip centre at the origin) and renderer objects.
  InstrumentMesh tool;
  std::vector<Float3> toolPositions, toolNormals;  ///< mm, unit: moved to the pose each frame
  render::MeshHandle toolMesh;
  render::TextureHandle toolColor;
  InstrumentLook instrumentLook;
  double toolBuiltRadiusMm = 0.0;  ///< the radius the drawn mesh was built with
};

namespace {

/// Steel grey, as a 1x1 sRGB base colour.
Image8 steelGrey() {
  Image8 image(1, 1, 4);
  const std::uint8_t grey[4] = {150, 155, 162, 255};
  std::copy_n(grey, 4, image.at(0, 0));
  return image;
}

/// The rest tool mesh placed at `pose` (rotated from its build axis for a capsule).
void placeTool(const InstrumentMesh& rest, const sim::ToolShape& shape, const Float3& buildAxis,
               const sim::ToolPose& pose, std::vector<Float3>& positions, std::vector<Float3>& normals) {
  const bool turn = shape.kind == sim::ToolShapeKind::Capsule;
  const sim::Vec3d from{buildAxis.x, buildAxis.y, buildAxis.z};
  for (std::size_t i = 0; i < rest.positions.size(); ++i) {
    sim::Vec3d p{rest.positions[i].x, rest.positions[i].y, rest.positions[i].z};
    sim::Vec3d n{rest.normals[i].x, rest.normals[i].y, rest.normals[i].z};
    if (turn) p = sim::rotateBetween(from, pose.axis, p), n = sim::rotateBetween(from, pose.axis, n);
    positions[i] = {float(p.x + pose.position.x), float(p.y + pose.position.y), float(p.z + pose.position.z)};
    normals[i] = {float(n.x), float(n.y), float(n.z)};
  }
}

}  // namespace

OrganLoop::OrganLoop(std::unique_ptr<Impl> impl) : m_impl(std::move(impl)) {}
OrganLoop::~OrganLoop() = default;
OrganLoop::OrganLoop(OrganLoop&&) noexcept = default;
OrganLoop& OrganLoop::operator=(OrganLoop&&) noexcept = default;

Result<OrganLoop> OrganLoop::create(const scenario::Scenario& scenario, SurfaceMesh surface,
                                    const OrganLoopConfig& config) {
  auto impl = std::make_unique<Impl>();
  impl->config = config;
  auto shaded =
      mesh::DeformableSurface::create(std::move(surface), config.planes, config.meshThreads, config.refit);
  if (!shaded) return shaded.error();
  impl->surface.emplace(std::move(*shaded));
  auto run = scenario::ScenarioRun::create(scenario);
  if (!run) return run.error();
  impl->run = std::move(*run);
  // The simulation must move exactly the surface that is shaded: same geometric vertices.
  const std::size_t simulated = impl->run->mesh().positions.size();
  const std::size_t shadedCount = impl->surface->geometricRestPositions().size();
  if (simulated != shadedCount)
    return Error{scenario.file.string() + ": the simulated mesh " + scenario.mesh.string() + " has " +
                 std::to_string(simulated) + " surface vertices but the shaded mesh has " +
                 std::to_string(shadedCount) + "; shade the scenario's own mesh"};
  const auto rest = impl->surface->geometricRestPositions();
  impl->positions.assign(rest.begin(), rest.end());
  return OrganLoop(std::move(impl));
}

Result<void> OrganLoop::buildToolMesh() {
  Impl& s = *m_impl;
  const sim::Instrument* tool = s.run->instrument();
  if (!s.renderer || !s.config.drawInstrument || !tool) return {};
  if (s.toolMesh) s.renderer->destroyMesh(s.toolMesh), s.toolMesh = {};
  InstrumentLook look = s.config.instrumentLook;
  if (tool->config().shape.kind == sim::ToolShapeKind::Capsule) {
    const auto& a = tool->pose().axis;
    look.shaftDirection = {float(a.x), float(a.y), float(a.z)};
  }
  s.tool = makeInstrumentMesh(tool->config().shape, look);
  s.instrumentLook = look;
  s.toolBuiltRadiusMm = tool->config().shape.radius;
  s.toolPositions.resize(s.tool.positions.size());
  s.toolNormals.resize(s.tool.normals.size());
  placeTool(s.tool, tool->config().shape, look.shaftDirection, tool->pose(), s.toolPositions, s.toolNormals);
  auto mesh = s.renderer->createMesh(
      {s.toolPositions, s.toolNormals, s.tool.tangents, s.tool.uvs, s.tool.triangles, {}});
  if (!mesh) return mesh.error();
  s.toolMesh = *mesh;
  if (!s.toolColor) {
    auto color = s.renderer->createTexture(steelGrey());
    if (!color) return color.error();
    s.toolColor = *color;
  }
  return {};
}

Result<render::MeshHandle> OrganLoop::attach(render::Renderer& renderer) {
  detach();
  const auto& organ = *m_impl->surface;
  auto handle = renderer.createMesh(
      {organ.positions(), organ.normals(), organ.tangents(), organ.uvs(), organ.triangles(),
       m_impl->config.uploadPlanes ? organ.planes() : std::span<const Float4>{}});
  if (!handle) return handle.error();
  m_impl->renderer = &renderer;
  m_impl->mesh = *handle;
  // The instrument: built once around its tip, moved in phase 3.
  if (auto tool = buildToolMesh(); !tool) return tool.error();
  return *handle;
}

std::optional<render::SceneObject> OrganLoop::instrumentObject() const {
  if (!m_impl->toolMesh) return std::nullopt;
  render::SceneObject o;
  o.mesh = m_impl->toolMesh;
  o.baseColor = m_impl->toolColor;
  o.material.specular = 0.5f;  // polished steel: a strong, tight highlight
  o.material.shininess = 128.0f;
  return o;
}

void OrganLoop::detach() {
  Impl& s = *m_impl;
  if (s.renderer) {
    if (s.mesh) s.renderer->destroyMesh(s.mesh);
    if (s.toolMesh) s.renderer->destroyMesh(s.toolMesh);
    if (s.toolColor) s.renderer->destroyTexture(s.toolColor);
  }
  s.renderer = nullptr;
  s.mesh = s.toolMesh = {};
  s.toolColor = {};
}

Result<LoopFrame> OrganLoop::step(const InstrumentInput& input) {
  Impl& s = *m_impl;
  LoopFrame f;
  Stopwatch total;

  // 1 simulate: live input first (the tool's target for this frame, grasp or release), then the
  // scenario frame (springs, integration, contact and grasp inside every substep).
  Stopwatch phase;
  if (input.grasp)
    if (auto g = s.run->setGrasp(*input.grasp); !g) return g.error();
  if (input.pose)
    if (auto p = s.run->setInstrumentTarget(*input.pose); !p) return p.error();
  if (input.radiusMm)
    if (auto r = s.run->setInstrumentRadius(*input.radiusMm); !r) return r.error();
  auto metrics = s.run->advance();
  if (!metrics) return metrics.error();
  if (!metrics->finite)
    return Error{"frame " + std::to_string(metrics->frame) + ": the simulation produced non-finite values (" +
                 metrics->divergenceReason + "); lower dt or the stiffness in " +
                 s.run->scenario().file.string()};
  f.simulation = *metrics;
  s.positions = s.run->positions();
  f.ms.simulateMs = phase.elapsedMs();

  // 2 mesh: positions in, normals, planes (incremental re-fit), tangent frames.
  phase.restart();
  f.mesh = s.surface->update(s.positions);
  f.ms.meshMs = phase.elapsedMs();
  f.ms.totalMs = total.elapsedMs();
  return f;
}

Result<double> OrganLoop::upload() {
  Impl& s = *m_impl;
  if (!s.renderer) return 0.0;
  // 3 upload: what deforms, in place (the topology and UVs never change).
  Stopwatch phase;
  const auto& m = *s.surface;
  // Stale planes or tangents (mesh::SurfaceWork off) stay as they were: nothing reads them.
  const bool planes = s.config.uploadPlanes && m.planesCurrent(), tangents = m.tangentsCurrent();
  auto up = s.renderer->updateMesh(
      s.mesh, {0, m.positions(), m.normals(), tangents ? m.tangents() : std::span<const Float4>{},
               planes ? m.planes() : std::span<const Float4>{}});
  if (!up) return up.error();
  if (const sim::Instrument* tool = s.run->instrument(); tool && s.toolMesh) {
    if (tool->config().shape.radius != s.toolBuiltRadiusMm)  // a host switched instruments
      if (auto rebuilt = buildToolMesh(); !rebuilt) return rebuilt.error();
    placeTool(s.tool, tool->config().shape, s.instrumentLook.shaftDirection, tool->pose(), s.toolPositions,
              s.toolNormals);
    if (auto moved = s.renderer->updateMesh(s.toolMesh, {0, s.toolPositions, s.toolNormals, {}, {}}); !moved)
      return moved.error();
  }
  return phase.elapsedMs();
}

mesh::SurfaceWork OrganLoop::setMeshWork(const mesh::SurfaceWork& work) {
  return m_impl->surface->setWork(work);
}

Result<LoopFrame> OrganLoop::advance(const InstrumentInput& input, const RenderRequest* request) {
  Impl& s = *m_impl;
  Stopwatch total;
  // 1 simulate, 2 mesh
  auto f = step(input);
  if (!f) return f.error();
  // 3 upload
  auto uploaded = upload();
  if (!uploaded) return uploaded.error();
  f->ms.uploadMs = *uploaded;
  // 4 render: offscreen (read back into the caller's image) or into the host's framebuffer.
  if (s.renderer && request && request->scene) {
    Stopwatch phase;
    if (request->host) {
      if (auto r = s.renderer->renderTo(*request->scene, *request->host); !r) return r.error();
    } else {
      auto image = s.renderer->renderImage(*request->scene, request->width, request->height);
      if (!image) return image.error();
      if (request->image) *request->image = std::move(*image);
    }
    f->ms.renderMs = phase.elapsedMs();
  }
  f->ms.totalMs = total.elapsedMs();
  return f;
}

const scenario::ScenarioRun& OrganLoop::run() const {
  return *m_impl->run;
}
const mesh::DeformableSurface& OrganLoop::surface() const {
  return *m_impl->surface;
}
std::span<const Float3> OrganLoop::geometricPositions() const {
  return m_impl->positions;
}
render::MeshHandle OrganLoop::meshHandle() const {
  return m_impl->mesh;
}
long OrganLoop::frame() const {
  return m_impl->run->simulator().frame();
}

void LoopPhaseSamples::add(const LoopFrame& f) {
  const double values[] = {f.ms.simulateMs,   f.mesh.gatherMs, f.mesh.normalsMs, f.mesh.planesMs,
                           f.mesh.tangentsMs, f.ms.uploadMs,   f.ms.renderMs,    f.ms.totalMs};
  for (std::size_t i = 0; i < phases.size(); ++i)
    phases[i].second.push_back(values[i]);
}

void LoopRecord::add(const LoopFrame& f, const OrganLoop& loop) {
  const auto positions = loop.geometricPositions();
  const scenario::FrameMetrics& m = f.simulation;
  const long index = long(frames.size());
  phases.add(f);
  frames.push_back(m);
  refittedFraction +=
      double(f.mesh.refit.refittedPlanes) / double(std::max<std::size_t>(1, positions.size()));
  planeFrames += f.mesh.planes ? 1 : 0;
  tangentFrames += f.mesh.tangents ? 1 : 0;
  if (m.grasped == 0 && m.forceN.z > maxPushN) {
    maxPushN = m.forceN.z, pokedFrame = index;
    pokedPositions.assign(positions.begin(), positions.end());
  }
  if (m.grasped > 0 && -m.forceN.z > maxPullN) {
    maxPullN = -m.forceN.z, liftedFrame = index;
    liftedPositions.assign(positions.begin(), positions.end());
  }
}

}  // namespace tissue::scene
