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

Result<std::uint32_t> Instrument::grasp(Simulator& simulator) {
  const State& state = simulator.state();
  const MassSpringSystem& system = simulator.system();
  std::vector<std::uint32_t> taken;
  std::vector<Vec3d> offsets;
  const double reach = m_config.shape.radius + m_config.graspMarginMm;
  for (std::uint32_t k = 0; k < state.x.size(); ++k) {
    const bool held = std::find(m_grasped.begin(), m_grasped.end(), k) != m_grasped.end();
    if (system.invMasses[k] == 0.0 && !held) continue;  // pinned
    if (signedDistance(m_config.shape, m_pose, state.x[k]) + m_config.shape.radius > reach) continue;
    taken.push_back(k);
    offsets.push_back(state.x[k] - m_pose.position);
  }
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
  r.contacts = m_lastContacts;
  r.grasped = static_cast<std::uint32_t>(m_grasped.size());
  r.subMoves = m_subMoves;
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
  const int moves =
      std::max(1, static_cast<int>(std::ceil(sweep / (m_config.maxSubMoveFraction * m_config.shape.radius))));
  const double dt = info.h / moves;
  // First the vertices' own step against the tool where the integrator saw it.
  if (info.xBefore.size() == state.x.size())
    m_impulse += stopSweptPoints(m_config.shape, from, lerpPose(from, to, 1.0 / moves), dt, system.masses,
                                 system.invMasses, info.xBefore, state.x, state.v)
                     .impulse;
  ToolPose previous = from;
  for (int i = 1; i <= moves; ++i) {
    const ToolPose current = i == moves ? to : lerpPose(from, to, double(i) / moves);
    const ProjectionResult r = projectOutOfTool(m_config.shape, current, previous, dt, system.masses,
                                                system.invMasses, state.x, state.v);
    m_impulse += r.impulse;
    m_lastContacts = r.projected;
    previous = current;
  }
  m_subMoves += moves;
  moveGrasped(system, state, from, to, info.h);
  m_pose = to;
  m_time += info.h;
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
