#pragma once
/// \file
/// The instrument: a rigid tool tip (sphere or capsule, contact.h) that follows a path of
/// keyframes or live input, pushes tissue by kinematic contact, grasps and releases it, and
/// reports the force on the tool every frame (what a haptic device needs).
///
/// Contact is kinematic and runs inside every simulation substep (a SubstepHook): the tool moves
/// from its pose at the substep's start to its pose at the end in sub-moves no longer than
/// `maxSubMoveFraction` times its radius; after each sub-move every free vertex inside the tool
/// is projected onto its surface and loses its inward normal velocity relative to the tool.
/// A vertex cannot end up behind the tool's core, because no sub-move is long enough to carry the
/// core past a vertex it has not yet pushed: no tunnelling at any tool speed. The cost is
/// O(sub-moves x vertices) per substep (a distance test per vertex, most rejected by a bounding
/// sphere), i.e. one extra pass over the vertices per sub-move; a fast tool costs more sub-moves.
/// Tissue moving into a resting tool is caught at the substep rate (springs cannot carry a vertex
/// through the tool within one substep unless it moves more than a radius per substep).
///
/// With a SurfaceEmbedding (an embedded lattice, lattice.h) the tool touches the render surface,
/// not the simulated nodes: after each sub-move the surface vertices inside the tool (positions
/// W x, the trilinear weights W) are the contacts; each one's correction (onto the tool's
/// surface, then the removal of its inward normal velocity) is scattered to the 8 nodes that
/// carry it by the transpose of its weights, as the least-norm node correction w_c d / sum w^2,
/// and a node shared by several contacts takes their weight-averaged correction. A few Jacobi
/// passes (InstrumentConfig::contactIterations) bring every contact onto the surface to within
/// contactToleranceFraction of the radius; the reaction, minus the momentum the nodes gained,
/// is the tool force. The no-tunnelling argument is the sub-move one, for the surface vertices;
/// the swept test of the tissue's own motion (stopSweptPoints) is replaced by the substep rate:
/// at the ~1 kHz haptic substeps a surface vertex would have to move faster than radius / h
/// (8 m/s for an 8 mm tool) to cross the tool within one substep.

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "tissue/core/result.h"
#include "tissue/sim/contact.h"
#include "tissue/sim/substep_hook.h"

namespace tissue::sim {

class Simulator;

/// One keyframe of a scripted path.
struct ToolKeyframe {
  double time = 0.0;  ///< s, strictly increasing along a path
  ToolPose pose;      ///< mm (and the unit axis of a capsule)
};

/// The pose on a path at time `t` (s): linear interpolation of the position and of the axis
/// (renormalised) between the keyframes around t, the end keyframes held outside the path.
ToolPose poseOnPath(std::span<const ToolKeyframe> path, double t);

/// Instrument settings (plain struct with defaults).
struct InstrumentConfig {
  ToolShape shape{};
  double maxSubMoveFraction = 0.25;  ///< longest sub-move, as a fraction of the radius (0, 1]
  double graspMarginMm = 0.5;        ///< grasp takes the vertices within radius + this (mm)
  /// Embedded surface only: Jacobi passes of the scattered projection per sub-move (>= 1).
  int contactIterations = 8;
  /// Embedded surface only: the passes stop once no contact is deeper than this fraction of
  /// the radius inside the tool (unitless, > 0).
  double contactToleranceFraction = 1e-3;
  /// Sub-moves per substep at most (>= 1): bounds a frame's contact work whatever the tool does.
  /// A tool that sweeps more than maxSubMoves * maxSubMoveFraction * radius in one substep (a
  /// teleport, a jerk of live input) takes longer sub-moves and may pass through tissue; each such
  /// substep is counted in InstrumentFrameReport::teleports.
  int maxSubMoves = 64;
};

/// The render surface an instrument touches when the simulated vertices are the nodes of an
/// embedded lattice: per surface vertex the 8 nodes that carry it and their weights (sum 1,
/// EmbeddedLattice::vertexNodes and vertexWeights). Plain views: the arrays are not copied and
/// must outlive the instrument's use.
struct SurfaceEmbedding {
  std::span<const std::array<std::uint32_t, 8>> nodes;
  std::span<const std::array<double, 8>> weights;
};

/// What the instrument did during one frame.
struct InstrumentFrameReport {
  /// Force on the tool (N), averaged over the frame:
  ///   F = -(1/T) sum_substeps sum_projected m dv  +  (1/T) sum_substeps h sum_grasped f_k,
  /// the reaction to the momentum the projections gave the tissue, plus (while grasping) the
  /// spring, spring-damping and gravity forces f_k on the grasped vertices, which the tool holds.
  /// For a vertex resting on the tool the projection removes exactly the normal velocity that the
  /// springs and gravity added during the substep, so the first term already is the force that
  /// resting vertices transmit (adding it again would count it twice). T = frame time (s).
  Vec3d forceN{};
  /// The same force per substep (N): sample k is the reaction to substep k's projections plus
  /// the pull on the grasped vertices during it (h_k-weighted, they average to forceN). With
  /// 17 substeps per 1/60 s frame the force updates at 1020 Hz (a haptic device's rate).
  std::vector<Vec3d> forceSamplesN;
  double sampleIntervalS = 0.0;    ///< s between samples (the substep length)
  std::uint32_t contacts = 0;      ///< vertices projected by the frame's last sub-move (surface
                                   ///< vertices with an embedding)
  double maxContactDepthMm = 0.0;  ///< embedding only: deepest contact left inside after the
                                   ///< last pass of the frame's sub-moves (mm, >= 0)
  std::uint32_t grasped = 0;       ///< vertices held
  int subMoves = 0;                ///< sub-moves over the frame's substeps (last try of the frame)
  int teleports = 0;               ///< substeps whose sweep needed more than maxSubMoves (last try)
  ToolPose pose{};                 ///< the tool at the end of the frame
};

/// A tool tip driven by a path or by live input; plug it into a Simulator with
/// setSubstepHook(&instrument). It acts on the simulated vertices, or, after setEmbedding, on
/// the embedded surface whose corrections are scattered to the nodes (see the file comment).
class Instrument final : public SubstepHook {
 public:
  /// A tool following `path` (at least one keyframe; times strictly increasing, s). Fails on a
  /// bad shape (radius <= 0, capsule length < 0), a zero axis, non-finite values, or unsorted times.
  static Result<Instrument> create(const InstrumentConfig& config, std::vector<ToolKeyframe> path);
  /// A tool under live input starting at `pose`; move it with setTarget.
  static Result<Instrument> createLive(const InstrumentConfig& config, const ToolPose& pose);

  /// Live input (viewer, haptic device): the tool moves linearly to `pose` over the next frame.
  /// Switches a path-driven tool to live input.
  void setTarget(const ToolPose& pose);
  /// Live input: a new radius (mm, > 0 and finite) from the next substep on (a host switching
  /// instruments). Fails, naming the value, otherwise.
  Result<void> setRadius(double radiusMm);

  /// Makes the tool touch the surface carried by the simulated vertices (`nodeCount` of them):
  /// contact and grasp then work on the surface vertices of `embedding` (see SurfaceEmbedding
  /// for its lifetime). Fails on arrays of different sizes or a node index out of range.
  Result<void> setEmbedding(const SurfaceEmbedding& embedding, std::size_t nodeCount);
  bool embedded() const { return !m_embedding.nodes.empty(); }

  /// Attaches the free vertices within radius + graspMarginMm of the tool: from now on they
  /// follow it rigidly (kinematic: inverse mass 0 in `simulator`), keeping their offsets, turned
  /// with a capsule's axis. With an embedding: the nodes that carry the surface vertices within
  /// radius + graspMarginMm (all 8 of each one's cell, so those vertices follow rigidly).
  /// Replaces a previous grasp. Returns how many simulated vertices (nodes) were taken.
  Result<std::uint32_t> grasp(Simulator& simulator);
  /// Lets the grasped vertices go with their current velocity (the tool's).
  Result<void> release(Simulator& simulator);

  bool grasping() const { return !m_grasped.empty(); }
  std::span<const std::uint32_t> graspedVertices() const { return m_grasped; }
  const ToolPose& pose() const { return m_pose; }
  const InstrumentConfig& config() const { return m_config; }
  /// The last frame's force, contacts and pose.
  InstrumentFrameReport lastFrame() const;

  void beginFrame(const MassSpringSystem& system, const State& state, long frame) override;
  void restartFrame() override;
  void afterSubstep(const MassSpringSystem& system, State& state, const SubstepInfo& info) override;

 private:
  Instrument(const InstrumentConfig& config, std::vector<ToolKeyframe> path, const ToolPose& start);
  ToolPose poseAt(double t, const SubstepInfo& info) const;
  void moveGrasped(const MassSpringSystem& system, State& state, const ToolPose& from, const ToolPose& to,
                   double h);
  /// One sub-move's contact on the embedded surface; returns the impulse given to the nodes
  /// (g*mm/s) and sets m_lastContacts, m_maxDepth.
  Vec3d projectEmbedded(const MassSpringSystem& system, State& state, const ToolPose& pose,
                        const ToolPose& previous, double dt);
  /// Surface position of vertex s (mm) from node positions.
  Vec3d surfacePoint(std::span<const Vec3d> x, std::uint32_t s) const;

  InstrumentConfig m_config;
  std::vector<ToolKeyframe> m_path;  ///< empty under live input
  ToolPose m_pose;                   ///< now (end of the last substep)
  ToolPose m_frameStartPose, m_liveTarget;
  std::vector<std::uint32_t> m_grasped;
  std::vector<Vec3d> m_graspOffsets;  ///< mm, vertex minus tool centre at grasp time
  Vec3d m_graspAxis{0.0, 0.0, 1.0};   ///< the tool's axis at grasp time
  // Accumulated over the frame's current try.
  Vec3d m_impulse{};       ///< g*mm/s given to the tissue by projections
  Vec3d m_graspImpulse{};  ///< g*mm/s: sum of h * forces on the grasped vertices
  double m_time = 0.0;     ///< s covered by the frame's substeps so far
  std::uint32_t m_lastContacts = 0;
  int m_subMoves = 0;
  int m_teleports = 0;
  double m_maxDepth = 0.0;        ///< mm, embedding only
  std::vector<Vec3d> m_samples;   ///< N per substep of the current try
  double m_sampleInterval = 0.0;  ///< s
  // The embedding and its cells: the surface vertices grouped by their 8 nodes (CSR), so that
  // a cell whose nodes' bounding sphere misses the tool is skipped whole (a trilinear point
  // lies in the convex hull of its 8 nodes, hence in their bounding sphere).
  SurfaceEmbedding m_embedding;
  std::vector<std::uint32_t> m_cellOfGroup;    ///< group -> a representative surface vertex
  std::vector<std::uint32_t> m_groupOffsets;   ///< group -> first entry in m_groupVertices
  std::vector<std::uint32_t> m_groupVertices;  ///< surface vertices, grouped
  // Scratch of the scattered projection (per node / per contact).
  std::vector<Vec3d> m_nodeSum;
  std::vector<double> m_nodeWeight;
  std::vector<std::uint32_t> m_touched, m_candidates, m_contacts;
  std::vector<Vec3d> m_contactNormals;
};

}  // namespace tissue::sim
