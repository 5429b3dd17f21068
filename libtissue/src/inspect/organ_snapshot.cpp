// One frame of a simulated organ as plain arrays (no VTK): built with and without it.
#include "tissue/inspect/organ_snapshot.h"

#include <algorithm>

#include "tissue/core/vec_math.h"
#include "tissue/mesh/deformable_surface.h"
#if TISSUE_INSPECT_TEXTURE_STRETCH
#include "tissue/render/texture_space_math.h"
#endif
#include "tissue/scenario/scenario_run.h"
#include "tissue/sim/contact.h"
#include "tissue/sim/forces.h"

namespace tissue::inspect {
namespace {

constexpr double kNewtonPerGMmPerS2 = 1e-6;  ///< g*mm/s^2 -> N
/// VTK_HEXAHEDRON corner order (bottom face counter-clockwise, then top) from the lattice's
/// bit order (bit 0 = +x, bit 1 = +y, bit 2 = +z).
constexpr std::array<int, 8> kVtkHexCorner{0, 1, 3, 2, 4, 5, 7, 6};

Float3 toFloat3(const sim::Vec3d& v) {
  return {float(v.x), float(v.y), float(v.z)};
}

/// Simulated nodes: positions, velocities, springs with their strain, volume cells.
void fillNodes(const scenario::ScenarioRun& run, NodeState& nodes) {
  const sim::State& state = run.simulator().state();
  const sim::SpringNetwork& springs = run.simulator().system().springs;
  for (std::size_t n = 0; n < state.x.size(); ++n) {
    nodes.positions.push_back(toFloat3(state.x[n]));
    nodes.velocities.push_back(toFloat3(state.v[n]));
  }
  nodes.springs.resize(springs.i.size());
  for (std::size_t s = 0; s < springs.i.size(); ++s)
    nodes.springs[s] = {springs.i[s], springs.j[s]};
  nodes.strain = springStrain(nodes.positions, nodes.springs, springs.restLength);
  nodes.stretch = vertexStretch(nodes.positions.size(), nodes.springs, nodes.strain);
  nodes.tets = run.mesh().tets;
  if (run.mesh().lattice)
    for (const auto& cell : run.mesh().lattice->cells) {
      std::array<std::uint32_t, 8> hex{};
      for (int k = 0; k < 8; ++k)
        hex[std::size_t(k)] = cell[std::size_t(kVtkHexCorner[std::size_t(k)])];
      nodes.hexes.push_back(hex);
    }
}

/// The contact force per node and per surface vertex (see snapshotOf).
void fillContactForces(const scenario::ScenarioRun& run, const SnapshotSettings& settings, OrganSnapshot& s) {
  const std::size_t nodeCount = s.nodes.positions.size(), vertexCount = s.surface.positions.size();
  s.nodes.contactForceN.assign(nodeCount, {});
  s.surface.contactForceN.assign(vertexCount, {});
  const sim::Instrument* tool = run.instrument();
  if (!tool) return;
  const sim::MassSpringSystem& system = run.simulator().system();
  const sim::State& state = run.simulator().state();
  std::vector<sim::Vec3d> forces(nodeCount);
  sim::ForceScratch scratch;
  sim::computeForces(system, state.x, state.v, forces, scratch);

  // The contact set: surface vertices on the tool (or, while grasping, within the grasp margin).
  const sim::ToolShape& shape = tool->config().shape;
  const double reach =
      tool->grasping() ? tool->config().graspMarginMm : settings.contactToleranceFraction * shape.radius;
  std::vector<std::uint32_t> contacts;
  for (std::uint32_t c = 0; c < vertexCount; ++c) {
    const Float3 p = s.surface.positions[c];
    if (sim::signedDistance(shape, tool->pose(), {p.x, p.y, p.z}) <= reach) contacts.push_back(c);
  }
  s.contactVertices = std::uint32_t(contacts.size());
  std::vector<std::uint8_t> held(nodeCount, 0);
  for (std::uint32_t n : tool->graspedVertices())
    held[n] = 1;
  // A node passes its force on when the tool touches or holds it; pinned nodes (inverse mass 0,
  // not held) pass theirs to the pin.
  const auto passes = [&](std::uint32_t n) { return held[n] || system.invMasses[n] > 0.0; };
  const auto& lattice = run.mesh().lattice;
  if (!lattice) {
    if (nodeCount != vertexCount) return;
    std::vector<std::uint8_t> touched = held;
    for (std::uint32_t c : contacts)
      touched[c] = 1;
    for (std::uint32_t n = 0; n < nodeCount; ++n)
      if (touched[n] && passes(n)) {
        s.nodes.contactForceN[n] = toFloat3(kNewtonPerGMmPerS2 * forces[n]);
        s.surface.contactForceN[n] = s.nodes.contactForceN[n];
      }
    return;
  }
  // Lattice: the weight of each node's contact vertices, then each node's force spread over them.
  std::vector<double> weight(nodeCount, 0.0);
  for (std::uint32_t c : contacts)
    for (int k = 0; k < 8; ++k)
      weight[lattice->vertexNodes[c][std::size_t(k)]] += lattice->vertexWeights[c][std::size_t(k)];
  for (std::uint32_t n = 0; n < nodeCount; ++n)
    if (weight[n] > 0.0 && passes(n)) s.nodes.contactForceN[n] = toFloat3(kNewtonPerGMmPerS2 * forces[n]);
  for (std::uint32_t c : contacts) {
    sim::Vec3d f{};
    for (int k = 0; k < 8; ++k) {
      const std::uint32_t n = lattice->vertexNodes[c][std::size_t(k)];
      if (weight[n] > 0.0 && passes(n))
        f += (lattice->vertexWeights[c][std::size_t(k)] / weight[n] * kNewtonPerGMmPerS2) * forces[n];
    }
    s.surface.contactForceN[c] = toFloat3(f);
  }
}

/// Node values at the surface's geometric vertices: the same (no lattice) or interpolated.
std::vector<Float3> atSurface(const scenario::ScenarioRun& run, const std::vector<Float3>& perNode,
                              std::size_t vertexCount) {
  const auto& lattice = run.mesh().lattice;
  if (!lattice) return perNode.size() == vertexCount ? perNode : std::vector<Float3>(vertexCount);
  std::vector<Float3> out(vertexCount);
  for (std::size_t c = 0; c < vertexCount && c < lattice->vertexNodes.size(); ++c)
    for (int k = 0; k < 8; ++k)
      out[c] = out[c] + float(lattice->vertexWeights[c][std::size_t(k)]) *
                            perNode[lattice->vertexNodes[c][std::size_t(k)]];
  return out;
}

std::vector<float> atSurface(const scenario::ScenarioRun& run, const std::vector<float>& perNode,
                             std::size_t vertexCount) {
  std::vector<Float3> wide(perNode.size());
  for (std::size_t n = 0; n < perNode.size(); ++n)
    wide[n].x = perNode[n];
  std::vector<float> out(vertexCount, 1.0f);
  const auto spread = atSurface(run, wide, vertexCount);
  if (run.mesh().lattice || perNode.size() == vertexCount)
    for (std::size_t c = 0; c < vertexCount; ++c)
      out[c] = spread[c].x;
  return out;
}

/// The surface's shading fields per geometric vertex (from its first render copy) and the planes.
void fillSurface(const mesh::DeformableSurface& surface, SurfaceState& out) {
  out.positions.assign(surface.geometricPositions().begin(), surface.geometricPositions().end());
  out.triangles.assign(surface.geometricTriangles().begin(), surface.geometricTriangles().end());
  const std::size_t vertexCount = out.positions.size();
  const auto& index = surface.mesh().geometricIndex;
  out.normals.assign(vertexCount, {0, 0, 1});
  out.tangents.assign(vertexCount, {1, 0, 0, 1});
  std::vector<std::uint8_t> done(vertexCount, 0);
  for (std::size_t r = 0; r < index.size(); ++r)
    if (!done[index[r]]) {
      done[index[r]] = 1;
      out.normals[index[r]] = surface.normals()[r];
      out.tangents[index[r]] = surface.tangents()[r];
    }
  // The planes as the mesh module fitted them (geometric vertices), and their residuals.
  const auto planes = surface.planeFitter().planes();
  const auto& hoods = surface.planeFitter().neighbourhoods();
  for (const Float4& p : planes) {
    out.planeNormals.push_back({p.x, p.y, p.z});
    out.planeOffsetMm.push_back(p.w);
  }
  out.planeResidualMm = planeResidualMm(out.positions, out.normals, planes, hoods.offsets, hoods.indices);
}

/// The render mesh, its seam flips and the texture-space stretch per triangle.
void fillRender(const mesh::DeformableSurface& surface, RenderState& out) {
  out.positions.assign(surface.positions().begin(), surface.positions().end());
  out.triangles.assign(surface.triangles().begin(), surface.triangles().end());
  out.uvs.assign(surface.uvs().begin(), surface.uvs().end());
  out.normals.assign(surface.normals().begin(), surface.normals().end());
  out.tangents.assign(surface.tangents().begin(), surface.tangents().end());
  out.geometricIndex = surface.mesh().geometricIndex;
  out.handednessFlip = handednessFlips(out.tangents, out.geometricIndex);
#if TISSUE_INSPECT_TEXTURE_STRETCH
  std::vector<Float2> stretch(out.triangles.size());
  for (std::size_t t = 0; t < out.triangles.size(); ++t) {
    const Triangle& tri = out.triangles[t];
    stretch[t] = render::uvStretch({out.positions[tri[0]], out.positions[tri[1]], out.positions[tri[2]]},
                                   {out.uvs[tri[0]], out.uvs[tri[1]], out.uvs[tri[2]]});
  }
  out.textureStretch =
      relativeTextureStretch(stretch, render::uvDensity(out.positions, out.uvs, out.triangles));
#else
  out.textureStretch.assign(out.triangles.size(), 1.0f);  // built without the renderer (TISSUE_WITH_GL=OFF)
#endif
}

}  // namespace

OrganSnapshot snapshotOf(const scenario::ScenarioRun& run, const mesh::DeformableSurface& surface,
                         const SnapshotSettings& settings) {
  OrganSnapshot s;
  s.frame = run.simulator().frame();
  s.timeS = double(s.frame) * run.scenario().frameTime;
  fillNodes(run, s.nodes);
  fillSurface(surface, s.surface);
  fillRender(surface, s.render);
  const std::size_t vertexCount = s.surface.positions.size();
  s.surface.velocities = atSurface(run, s.nodes.velocities, vertexCount);
  s.surface.stretch = atSurface(run, s.nodes.stretch, vertexCount);
  fillContactForces(run, settings, s);
  if (const sim::Instrument* tool = run.instrument()) {
    const auto report = tool->lastFrame();
    s.tool.present = true;
    s.tool.centreMm = toFloat3(tool->pose().position);
    s.tool.axis = toFloat3(tool->pose().axis);
    s.tool.radiusMm = float(tool->config().shape.radius);
    s.tool.lengthMm = float(tool->config().shape.length);
    s.tool.forceN = toFloat3(report.forceN);
    s.tool.contacts = report.contacts;
    s.tool.grasping = tool->grasping();
  }
  return s;
}

}  // namespace tissue::inspect
