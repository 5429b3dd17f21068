// The instrument: path or live pose, sub-moved kinematic contact per substep, grasp, force.
#include "tissue/sim/instrument.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "tissue/sim/forces.h"
#include "tissue/sim/simulator.h"
#include "tissue/sim/units.h"

namespace tissue::sim {
namespace {

ToolPose lerpPose(const ToolPose& a, const ToolPose& b, double s) {
  return {a.position + s * (b.position - a.position), normalizedOr(a.axis + s * (b.axis - a.axis), a.axis)};
}

Result<void> checkPose(const ToolPose& pose, const std::string& where) {
  if (!isFinite(pose.position) || !isFinite(pose.axis))
    return Error{"instrument: " + where + " holds NaN or Inf; give finite mm"};
  if (!(length(pose.axis) > 0.0)) return Error{"instrument: " + where + " has a zero axis; give a direction"};
  return {};
}

Result<void> checkConfig(const InstrumentConfig& c) {
  if (!(c.shape.radius > 0.0) || !std::isfinite(c.shape.radius))
    return Error{"instrument: the radius must be a positive number of mm"};
  if (!(c.shape.length >= 0.0) || !std::isfinite(c.shape.length))
    return Error{"instrument: the capsule length must be >= 0 mm"};
  if (!(c.maxSubMoveFraction > 0.0 && c.maxSubMoveFraction <= 1.0))
    return Error{"instrument: maxSubMoveFraction must be in (0, 1]"};
  if (!(c.graspMarginMm >= 0.0) || !std::isfinite(c.graspMarginMm))
    return Error{"instrument: the grasp margin must be >= 0 mm"};
  if (c.contactIterations < 1) return Error{"instrument: contactIterations must be >= 1"};
  if (c.maxSubMoves < 1) return Error{"instrument: maxSubMoves must be >= 1"};
  if (!(c.contactToleranceFraction > 0.0) || !std::isfinite(c.contactToleranceFraction))
    return Error{"instrument: contactToleranceFraction must be a positive fraction of the radius"};
  return {};
}

/// Spring (with its damping) and gravity force on vertex `k`, g*mm/s^2.
Vec3d vertexForce(const MassSpringSystem& system, const State& state, std::uint32_t k) {
  const SpringNetwork& s = system.springs;
  Vec3d f = system.masses[k] * system.config.gravity;
  for (std::uint32_t q = s.vertexSpringOffsets[k]; q < s.vertexSpringOffsets[k + 1]; ++q) {
    const std::uint32_t e = s.vertexSprings[q];
    const Vec3d fe = springForce(state.x[s.i[e]], state.x[s.j[e]], state.v[s.i[e]], state.v[s.j[e]],
                                 s.restLength[e], s.stiffness[e], s.damping[e]);
    f += s.i[e] == k ? fe : -fe;
  }
  return f;
}

}  // namespace

ToolPose poseOnPath(std::span<const ToolKeyframe> path, double t) {
  if (path.empty()) return {};
  if (t <= path.front().time) return path.front().pose;
  if (t >= path.back().time) return path.back().pose;
  const auto next = std::upper_bound(path.begin(), path.end(), t,
                                     [](double value, const ToolKeyframe& k) { return value < k.time; });
  const ToolKeyframe& b = *next;
  const ToolKeyframe& a = *(next - 1);
  return lerpPose(a.pose, b.pose, (t - a.time) / (b.time - a.time));
}

Instrument::Instrument(const InstrumentConfig& config, std::vector<ToolKeyframe> path, const ToolPose& start)
    : m_config(config),
      m_path(std::move(path)),
      m_pose(start),
      m_frameStartPose(start),
      m_liveTarget(start) {}

Result<Instrument> Instrument::create(const InstrumentConfig& config, std::vector<ToolKeyframe> path) {
  if (auto ok = checkConfig(config); !ok) return ok.error();
  if (path.empty()) return Error{"instrument: the path has no keyframe; give at least one"};
  for (std::size_t k = 0; k < path.size(); ++k) {
    const std::string where = "keyframe " + std::to_string(k);
    if (auto ok = checkPose(path[k].pose, where); !ok) return ok.error();
    path[k].pose.axis = normalizedOr(path[k].pose.axis);
    if (!std::isfinite(path[k].time)) return Error{"instrument: " + where + " has a non-finite time"};
    if (k > 0 && !(path[k].time > path[k - 1].time))
      return Error{"instrument: " + where + " is not later than the one before; sort the times (s)"};
  }
  const ToolPose start = poseOnPath(path, 0.0);
  return Instrument(config, std::move(path), start);
}

Result<Instrument> Instrument::createLive(const InstrumentConfig& config, const ToolPose& pose) {
  if (auto ok = checkConfig(config); !ok) return ok.error();
  if (auto ok = checkPose(pose, "the start pose"); !ok) return ok.error();
  ToolPose start{pose.position, normalizedOr(pose.axis)};
  return Instrument(config, {}, start);
}

void Instrument::setTarget(const ToolPose& pose) {
  m_path.clear();
  if (isFinite(pose.position) && isFinite(pose.axis))  // the tool never takes a NaN pose
    m_liveTarget = {pose.position, normalizedOr(pose.axis, m_pose.axis)};
}

Result<void> Instrument::setRadius(double radiusMm) {
  if (!(radiusMm > 0.0) || !std::isfinite(radiusMm))
    return Error{"instrument radius " + std::to_string(radiusMm) + " mm: give a positive number of mm"};
  m_config.shape.radius = radiusMm;
  return {};
}

Result<void> Instrument::setEmbedding(const SurfaceEmbedding& embedding, std::size_t nodeCount) {
  if (embedding.nodes.size() != embedding.weights.size())
    return Error{"instrument: the embedding has " + std::to_string(embedding.nodes.size()) +
                 " node sets for " + std::to_string(embedding.weights.size()) +
                 " weight sets; give one of each per surface vertex"};
  std::vector<std::uint32_t> order(embedding.nodes.size());
  for (std::uint32_t s = 0; s < order.size(); ++s) {
    for (std::uint32_t n : embedding.nodes[s])
      if (n >= nodeCount)
        return Error{"instrument: surface vertex " + std::to_string(s) + " is carried by node " +
                     std::to_string(n) + ", out of range (" + std::to_string(nodeCount) + " nodes)"};
    order[s] = s;
  }
  // Group the surface vertices by the 8 nodes that carry them (one group per lattice cell).
  std::stable_sort(order.begin(), order.end(),
                   [&](std::uint32_t a, std::uint32_t b) { return embedding.nodes[a] < embedding.nodes[b]; });
  m_embedding = embedding;
  m_cellOfGroup.clear();
  m_groupOffsets.clear();
  m_groupVertices = order;
  for (std::uint32_t k = 0; k < order.size(); ++k)
    if (k == 0 || embedding.nodes[order[k]] != embedding.nodes[order[k - 1]]) {
      m_cellOfGroup.push_back(order[k]);
      m_groupOffsets.push_back(k);
    }
  m_groupOffsets.push_back(static_cast<std::uint32_t>(order.size()));
  m_nodeSum.assign(nodeCount, Vec3d{});
  m_nodeWeight.assign(nodeCount, 0.0);
  return {};
}

Vec3d Instrument::surfacePoint(std::span<const Vec3d> x, std::uint32_t s) const {
  Vec3d p{};
  for (int c = 0; c < 8; ++c)
    p += m_embedding.weights[s][c] * x[m_embedding.nodes[s][c]];
  return p;
}

Result<std::uint32_t> Instrument::grasp(Simulator& simulator) {
  const State& state = simulator.state();
  const MassSpringSystem& system = simulator.system();
  auto held = [&](std::uint32_t k) {
    return std::find(m_grasped.begin(), m_grasped.end(), k) != m_grasped.end();
  };
  std::vector<std::uint32_t> taken;
  const double reach = m_config.shape.radius + m_config.graspMarginMm;
  if (embedded()) {
    // The nodes that carry the surface vertices within reach: all 8 of each one's cell, so that
    // those vertices ride rigidly with the tool.
    for (std::uint32_t s = 0; s < m_embedding.nodes.size(); ++s) {
      if (signedDistance(m_config.shape, m_pose, surfacePoint(state.x, s)) + m_config.shape.radius > reach)
        continue;
      for (std::uint32_t n : m_embedding.nodes[s])
        taken.push_back(n);
    }
    std::sort(taken.begin(), taken.end());
    taken.erase(std::unique(taken.begin(), taken.end()), taken.end());
    std::erase_if(taken, [&](std::uint32_t k) { return system.invMasses[k] == 0.0 && !held(k); });  // pinned
  } else {
    for (std::uint32_t k = 0; k < state.x.size(); ++k) {
      if (system.invMasses[k] == 0.0 && !held(k)) continue;  // pinned
      if (signedDistance(m_config.shape, m_pose, state.x[k]) + m_config.shape.radius > reach) continue;
      taken.push_back(k);
    }
  }
  std::vector<Vec3d> offsets;
  for (std::uint32_t k : taken)
    offsets.push_back(state.x[k] - m_pose.position);
  if (auto ok = simulator.setKinematic(taken); !ok) return ok.error();
  m_grasped = std::move(taken);
  m_graspOffsets = std::move(offsets);
  m_graspAxis = m_pose.axis;
  return static_cast<std::uint32_t>(m_grasped.size());
}

Result<void> Instrument::release(Simulator& simulator) {
  if (auto ok = simulator.setKinematic({}); !ok) return ok.error();
  m_grasped.clear();
  m_graspOffsets.clear();
  return {};
}

InstrumentFrameReport Instrument::lastFrame() const {
  InstrumentFrameReport r;
  if (m_time > 0.0) r.forceN = (1.0 / (m_time * kForcePerNewton)) * (m_graspImpulse - m_impulse);
  r.forceSamplesN = m_samples;
  r.sampleIntervalS = m_sampleInterval;
  r.contacts = m_lastContacts;
  r.maxContactDepthMm = m_maxDepth;
  r.grasped = static_cast<std::uint32_t>(m_grasped.size());
  r.subMoves = m_subMoves;
  r.teleports = m_teleports;
  r.pose = m_pose;
  return r;
}

void Instrument::beginFrame(const MassSpringSystem&, const State&, long) {
  m_frameStartPose = m_pose;
  restartFrame();
}

void Instrument::restartFrame() {
  m_pose = m_frameStartPose;
  m_impulse = m_graspImpulse = {};
  m_time = 0.0;
  m_lastContacts = 0;
  m_subMoves = 0;
  m_teleports = 0;
  m_maxDepth = 0.0;
  m_samples.clear();
}

ToolPose Instrument::poseAt(double t, const SubstepInfo& info) const {
  if (!m_path.empty()) return poseOnPath(m_path, t);
  const double s = info.frameTime > 0.0 ? std::clamp((t - info.frameStart) / info.frameTime, 0.0, 1.0) : 1.0;
  return lerpPose(m_frameStartPose, m_liveTarget, s);
}

void Instrument::afterSubstep(const MassSpringSystem& system, State& state, const SubstepInfo& info) {
  const ToolPose from = m_pose;
  const ToolPose to = poseAt(info.t0 + info.h, info);

  // Sub-moves no longer than a fraction of the radius; a capsule's ends sweep L/2 * angle more.
  const double angle = std::acos(std::clamp(dot(from.axis, to.axis), -1.0, 1.0));
  const double sweep =
      length(to.position - from.position) +
      (m_config.shape.kind == ToolShapeKind::Capsule ? 0.5 * m_config.shape.length * angle : 0.0);
  // In double, then capped: a sweep of 1e12 mm must neither overflow int nor cost 1e12 passes.
  const double wanted = std::ceil(sweep / (m_config.maxSubMoveFraction * m_config.shape.radius));
  const int moves =
      wanted <= m_config.maxSubMoves ? std::max(1, static_cast<int>(wanted)) : m_config.maxSubMoves;
  if (!(wanted <= m_config.maxSubMoves)) ++m_teleports;
  const double dt = info.h / moves;
  const Vec3d impulseBefore = m_impulse, graspBefore = m_graspImpulse;
  // First the vertices' own step against the tool where the integrator saw it (simulated
  // vertices only; an embedded surface relies on the substep rate, see the header).
  if (!embedded() && info.xBefore.size() == state.x.size())
    m_impulse += stopSweptPoints(m_config.shape, from, lerpPose(from, to, 1.0 / moves), dt, system.masses,
                                 system.invMasses, info.xBefore, state.x, state.v)
                     .impulse;
  ToolPose previous = from;
  if (embedded()) m_maxDepth = 0.0;
  for (int i = 1; i <= moves; ++i) {
    const ToolPose current = i == moves ? to : lerpPose(from, to, double(i) / moves);
    if (embedded()) {
      m_impulse += projectEmbedded(system, state, current, previous, dt);
    } else {
      const ProjectionResult r = projectOutOfTool(m_config.shape, current, previous, dt, system.masses,
                                                  system.invMasses, state.x, state.v);
      m_impulse += r.impulse;
      m_lastContacts = r.projected;
    }
    previous = current;
  }
  m_subMoves += moves;
  moveGrasped(system, state, from, to, info.h);
  m_pose = to;
  m_time += info.h;
  // This substep's force sample (N): the haptic-rate output.
  m_sampleInterval = info.h;
  m_samples.push_back((1.0 / (info.h * kForcePerNewton)) *
                      ((m_graspImpulse - graspBefore) - (m_impulse - impulseBefore)));
}

Vec3d Instrument::projectEmbedded(const MassSpringSystem& system, State& state, const ToolPose& pose,
                                  const ToolPose& previous, double dt) {
  const ToolShape& shape = m_config.shape;
  const double r = shape.radius;
  const Vec3d motion = pose.position - previous.position;
  const double tolerance = m_config.contactToleranceFraction * r;

  // Candidates: the surface vertices of cells whose nodes' bounding sphere meets the tool.
  m_candidates.clear();
  for (std::size_t g = 0; g < m_cellOfGroup.size(); ++g) {
    const auto& nodes = m_embedding.nodes[m_cellOfGroup[g]];
    Vec3d centre{};
    for (std::uint32_t n : nodes)
      centre += 0.125 * state.x[n];
    double radius2 = 0.0;
    for (std::uint32_t n : nodes)
      radius2 = std::max(radius2, dot(state.x[n] - centre, state.x[n] - centre));
    const Vec3d toCore = centre - closestCorePoint(shape, pose, centre);
    const double reach = r + std::sqrt(radius2);
    if (dot(toCore, toCore) >= reach * reach) continue;
    m_candidates.insert(m_candidates.end(), m_groupVertices.begin() + m_groupOffsets[g],
                        m_groupVertices.begin() + m_groupOffsets[g + 1]);
  }

  // Scatters one correction per contact to its free nodes: node c of contact s proposes
  // w_sc / sum_free(w_s^2) * d_s (the least-norm node change that moves s by d_s), and a node
  // takes the w-weighted mean of its proposals (a sum would over-correct shared nodes).
  auto scatter = [&](std::uint32_t s, const Vec3d& d) {
    const auto& w = m_embedding.weights[s];
    const auto& nodes = m_embedding.nodes[s];
    double w2 = 0.0;
    for (int c = 0; c < 8; ++c)
      if (system.invMasses[nodes[c]] != 0.0) w2 += w[c] * w[c];
    if (!(w2 > 0.0)) return;
    for (int c = 0; c < 8; ++c) {
      const std::uint32_t n = nodes[c];
      if (system.invMasses[n] == 0.0 || w[c] <= 0.0) continue;
      if (m_nodeWeight[n] == 0.0) m_touched.push_back(n);
      m_nodeSum[n] += (w[c] * w[c] / w2) * d;
      m_nodeWeight[n] += w[c];
    }
  };
  auto apply = [&](std::vector<Vec3d>& target, Vec3d* impulse) {
    for (std::uint32_t n : m_touched) {
      const Vec3d delta = (1.0 / m_nodeWeight[n]) * m_nodeSum[n];
      target[n] += delta;
      if (impulse) *impulse += system.masses[n] * delta;
      m_nodeSum[n] = {};
      m_nodeWeight[n] = 0.0;
    }
    m_touched.clear();
  };

  // Positions: Jacobi passes until no contact is deeper than the tolerance.
  m_contacts.clear();
  for (int pass = 0; pass < std::max(1, m_config.contactIterations); ++pass) {
    for (std::uint32_t s : m_candidates) {
      const Vec3d p = surfacePoint(state.x, s);
      const double inside = -signedDistance(shape, pose, p);
      if (inside <= (pass == 0 ? 0.0 : tolerance)) continue;
      if (pass == 0) m_contacts.push_back(s);
      Vec3d n;
      scatter(s, pushOutOfTool(shape, pose, motion, p, n) - p);
    }
    if (m_touched.empty()) break;
    apply(state.x, nullptr);
  }
  // What is left inside after the last pass (0 when the passes converged).
  double left = 0.0;
  for (std::uint32_t s : m_contacts)
    left = std::max(left, -signedDistance(shape, pose, surfacePoint(state.x, s)));
  m_maxDepth = std::max(m_maxDepth, left);

  // Velocities: each contact loses its inward normal velocity relative to the tool's surface
  // point, scattered the same way; the nodes' momentum change is the impulse on the tissue.
  Vec3d impulse{};
  for (std::uint32_t s : m_contacts) {
    const Vec3d p = surfacePoint(state.x, s);
    const Vec3d n = normalizedOr(p - closestCorePoint(shape, pose, p), Vec3d{1.0, 0.0, 0.0});
    const double vn = dot(surfacePoint(state.v, s) - toolPointVelocity(previous, pose, dt, p), n);
    if (vn < 0.0) scatter(s, -vn * n);
  }
  apply(state.v, &impulse);
  m_lastContacts = static_cast<std::uint32_t>(m_contacts.size());
  return impulse;
}

void Instrument::moveGrasped(const MassSpringSystem& system, State& state, const ToolPose& from,
                             const ToolPose& to, double h) {
  // The grasped vertices ride with the tool (offset turned from the grasp-time axis), at the
  // tool's point velocity; the tool feels the forces the tissue puts on them.
  for (std::size_t g = 0; g < m_grasped.size(); ++g) {
    const std::uint32_t k = m_grasped[g];
    state.x[k] = to.position + rotateBetween(m_graspAxis, to.axis, m_graspOffsets[g]);
    state.v[k] = toolPointVelocity(from, to, h, state.x[k]);
  }
  for (std::uint32_t k : m_grasped)
    m_graspImpulse += h * vertexForce(system, state, k);
}

}  // namespace tissue::sim
