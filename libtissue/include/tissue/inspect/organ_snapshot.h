#pragma once
/// \file
/// One frame of a simulated organ as plain arrays: what every inspection view and every frame
/// of a ParaView series shows. Taken from the scenario's run (simulator state, springs, the
/// instrument) and the mesh module's surface (normals, planes, tangents), which the scene's
/// OrganLoop exposes as run() and surface(); nothing the mesh module computes is recomputed.
///
/// Three vertex sets: the simulated nodes (the surface's vertices, a tet mesh's vertices or an
/// embedded lattice's nodes), the surface's geometric vertices (one per point of the surface)
/// and its render vertices (split at UV seams, where UVs and tangents live).

#include <array>
#include <cstdint>
#include <vector>

#include "tissue/core/types.h"
#include "tissue/inspect/organ_fields.h"

namespace tissue::scenario {
class ScenarioRun;
}  // namespace tissue::scenario
namespace tissue::mesh {
class DeformableSurface;
}  // namespace tissue::mesh

namespace tissue::inspect {

/// The simulated nodes, their springs and (tets or lattice) their volume cells.
struct NodeState {
  std::vector<Float3> positions;                    ///< #N mm
  std::vector<Float3> velocities;                   ///< #N mm/s
  std::vector<Edge> springs;                        ///< #S
  std::vector<float> strain;                        ///< #S L / L0 - 1, unitless
  std::vector<float> stretch;                       ///< #N mean L / L0 of the node's springs, unitless
  std::vector<Float3> contactForceN;                ///< #N N: the force each node exerts on the tool
  std::vector<Tet> tets;                            ///< springs.from = "tet-edges": the volume mesh
  std::vector<std::array<std::uint32_t, 8>> hexes;  ///< springs.from = "lattice": cells in VTK order
};

/// The surface over its geometric vertices.
struct SurfaceState {
  std::vector<Float3> positions;       ///< #G mm
  std::vector<Triangle> triangles;     ///< #F over the geometric vertices
  std::vector<Float3> velocities;      ///< #G mm/s (a lattice's: interpolated by the embedding)
  std::vector<float> stretch;          ///< #G unitless (a lattice's: interpolated)
  std::vector<Float3> contactForceN;   ///< #G N: the force each vertex exerts on the tool
  std::vector<Float3> normals;         ///< #G unit vertex normals
  std::vector<Float3> planeNormals;    ///< #G unit N_S (François et al. eq. 14)
  std::vector<float> planeOffsetMm;    ///< #G d, mm
  std::vector<float> planeResidualMm;  ///< #G RMS distance of the neighbours from the plane, mm
  std::vector<Float4> tangents;        ///< #G (T, w) of the vertex's first render copy
};

/// The render mesh (split at UV seams): where the tangent frames and the texture live.
struct RenderState {
  std::vector<Float3> positions;              ///< #R mm
  std::vector<Triangle> triangles;            ///< #F over the render vertices
  std::vector<Float2> uvs;                    ///< #R
  std::vector<Float3> normals;                ///< #R unit
  std::vector<Float4> tangents;               ///< #R (T, w)
  std::vector<std::uint32_t> geometricIndex;  ///< #R
  std::vector<float> handednessFlip;          ///< #R 1 where a seam copy has the other w
  std::vector<float> textureStretch;          ///< #F relativeTextureStretch, unitless
};

/// The instrument at the end of the frame.
struct ToolState {
  bool present = false;        ///< false: the scenario has no instrument
  Float3 centreMm{};           ///< mm, the tip sphere's (capsule core's) centre
  Float3 axis{0, 0, 1};        ///< unit, a capsule's core direction
  float radiusMm = 0.0f;       ///< mm
  float lengthMm = 0.0f;       ///< mm, capsule only
  Float3 forceN{};             ///< N, the force on the tool the instrument reports (frame average)
  std::uint32_t contacts = 0;  ///< vertices the tool's last sub-move projected
  bool grasping = false;
};

/// One frame of an organ.
struct OrganSnapshot {
  long frame = 0;      ///< 0-based frames simulated so far
  double timeS = 0.0;  ///< s
  NodeState nodes;
  SurfaceState surface;
  RenderState render;
  ToolState tool;
  /// How many vertices lie within a tolerance of the tool (the contact set the per-vertex
  /// forces are spread over).
  std::uint32_t contactVertices = 0;
};

/// Settings of a snapshot (plain struct with defaults).
struct SnapshotSettings {
  /// A vertex is in contact when it lies within this fraction of the radius of the tool's
  /// surface (the instrument leaves its contacts on the surface after each sub-move).
  double contactToleranceFraction = 0.02;
};

/// The frame `run` and `surface` are at (an OrganLoop's run() and surface(), in step).
///
/// The contact force per vertex is the quasi-static reaction: every node that the tool touches
/// or holds passes the tool the net internal force on it (springs with damping, gravity,
/// Rayleigh damping: sim::computeForces), the force the tool's projection cancels; with a
/// lattice each touched node's share is spread over its contact surface vertices by their
/// trilinear weights. Summed, it equals the instrument's reported force once the tissue rests
/// against the tool (inertia, which the projection also absorbs, is left out).
OrganSnapshot snapshotOf(const scenario::ScenarioRun& run, const mesh::DeformableSurface& surface,
                         const SnapshotSettings& settings = {});

}  // namespace tissue::inspect
