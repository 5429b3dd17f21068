// The instrument: no tunnelling at frame rate, the force on the tool (weight, Newton's third
// law), grasp and release.
#include "tissue/sim/instrument.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "closed_surfaces.h"
#include "test_systems.h"
#include "tissue/sim/forces.h"
#include "tissue/sim/lattice.h"
#include "tissue/sim/simulator.h"
#include "tissue/sim/units.h"

namespace tissue::sim {
namespace {

/// Border vertices of an nx by ny grid.
std::vector<std::uint32_t> border(int nx, int ny) {
  std::vector<std::uint32_t> out;
  for (int y = 0; y < ny; ++y)
    for (int x = 0; x < nx; ++x)
      if (x == 0 || y == 0 || x == nx - 1 || y == ny - 1)
        out.push_back(static_cast<std::uint32_t>(y * nx + x));
  return out;
}

/// Simulator over `system` from rest, implicit Euler, one substep per 60 Hz frame. The stretch
/// limit is raised: a tool may stretch a fine membrane locally far beyond 3 times its rest length.
Simulator restSimulator(MassSpringSystem system, const test::Patch& patch, double cgTolerance = 1e-10) {
  SimulatorConfig config{.integrator = Integrator::ImplicitEuler, .frameTime = 1.0 / 60.0, .substeps = 1};
  config.solver.relativeTolerance = cgTolerance;
  config.limits.maxStretch = 20.0;
  return Simulator::create(std::move(system), restState(patch.positions), config).value();
}

TEST(Instrument, SphereAtFrameRateThroughAPinnedMembranePushesItInsteadOfTunnelling) {
  // A 20 x 20 mm membrane (1 mm spacing) pinned at its border; a sphere of radius 3 mm comes up
  // under its centre at 0.36 m/s (6 mm, two radii, per frame) and stops 5 mm above it.
  const auto patch = test::gridPatch(21, 21, 1.0f);
  auto sim = restSimulator(test::patchSystem(patch, 0.05, 1e-4, 1.0, border(21, 21), {.gravity = {}}), patch);
  const Vec3d centre{10.0, 10.0, 0.0};
  std::vector<ToolKeyframe> path{{0.0, {centre + Vec3d{0, 0, -7.0}}},
                                 {2.0 / 60.0, {centre + Vec3d{0, 0, 5.0}}}};
  auto tool = Instrument::create({.shape = {ToolShapeKind::Sphere, 3.0}}, path);
  ASSERT_TRUE(tool.ok()) << tool.error().message;
  sim.setSubstepHook(&*tool);
  for (int f = 0; f < 6; ++f) {
    EXPECT_TRUE(sim.advanceFrame().events.empty()) << "frame " << f;
    const ToolPose pose = tool->pose();
    for (std::size_t k = 0; k < sim.state().x.size(); ++k) {
      const Vec3d& x = sim.state().x[k];
      EXPECT_GE(signedDistance(tool->config().shape, pose, x), -1e-9) << "vertex " << k << " inside";
      // Vertices over the sphere's path stay ahead of (above) its centre.
      const double axial = std::hypot(x.x - centre.x, x.y - centre.y);
      if (axial < 1.0 && pose.position.z > -3.0) {
        EXPECT_GT(x.z, pose.position.z) << "vertex " << k << " frame " << f;
      }
    }
  }
  EXPECT_LT(tool->lastFrame().forceN.z, 0.0);  // the stretched membrane pushes the tool down
}

TEST(Instrument, OneRadialProjectionPerFrameWouldTunnel) {
  const auto patch = test::gridPatch(21, 21, 1.0f);
  auto state = restState(patch.positions);
  std::vector<double> mass(state.x.size(), 1.0), invMass(state.x.size(), 1.0);
  // The control: one radial projection at the end of an 8 mm jump (no sub-moves, no motion
  // direction, as a naive per-frame contact does) leaves the centre vertex behind the sphere.
  const ToolPose after{{10.0, 10.0, 1.0}};
  (void)projectOutOfTool({ToolShapeKind::Sphere, 3.0}, after, after, 1.0 / 60.0, mass, invMass, state.x,
                         state.v);
  EXPECT_LT(state.x[10 * 21 + 10].z, after.position.z);
}

TEST(Instrument, RestingPatchWeighsOnTheToolAndMomentumBalances) {
  // A free 10 x 10 mm patch of 1 g resting on the top of a sphere of radius 50 mm: the force on
  // the tool settles to the patch's weight, and every frame it equals M g - dP/dt, the momentum
  // balance of the whole patch (Newton's third law) computed without the contact code.
  const auto patch = test::gridPatch(6, 6, 2.0f);
  const double totalMass = 1.0;
  SystemConfig config{.gravity = {0.0, 0.0, -kStandardGravity}};
  auto sim = restSimulator(test::patchSystem(patch, 0.05, 2e-4, totalMass, {}, config), patch);
  auto tool = Instrument::createLive({.shape = {ToolShapeKind::Sphere, 50.0}}, {{5.0, 5.0, -50.0}});
  ASSERT_TRUE(tool.ok());
  sim.setSubstepHook(&*tool);
  const double weightN = totalMass * kStandardGravity / kForcePerNewton;
  const double T = 1.0 / 60.0;
  // The frictionless top of a sphere is an unstable equilibrium: rounding seeds a slide that
  // grows about 14 times every 10 frames and is still below 1e-10 mm after 45 frames (0.75 s),
  // when the patch has long settled (its residual motion is below 1e-6 of the weight).
  for (int f = 0; f < 45; ++f) {
    const Vec3d p0 = linearMomentum(sim.system(), sim.state().v);
    sim.advanceFrame();
    const Vec3d p1 = linearMomentum(sim.system(), sim.state().v);
    const Vec3d expected = (1.0 / kForcePerNewton) * (totalMass * config.gravity - (1.0 / T) * (p1 - p0));
    const Vec3d got = tool->lastFrame().forceN;
    ASSERT_NEAR(got.x, expected.x, 1e-6 * weightN) << "frame " << f;
    ASSERT_NEAR(got.y, expected.y, 1e-6 * weightN) << "frame " << f;
    ASSERT_NEAR(got.z, expected.z, 1e-6 * weightN) << "frame " << f;
  }
  // At rest: the tool carries the weight, downwards.
  const Vec3d f = tool->lastFrame().forceN;
  EXPECT_NEAR(f.z, -weightN, 0.01 * weightN);
  EXPECT_NEAR(f.x, 0.0, 0.01 * weightN);
  EXPECT_NEAR(f.y, 0.0, 0.01 * weightN);
  EXPECT_GT(tool->lastFrame().contacts, 0u);
}

TEST(Instrument, GraspLiftsTheVerticesWithTheToolAndReleaseLetsThemFall) {
  // A 20 x 20 mm membrane (1 mm spacing) pinned at its border, under gravity; a sphere touches
  // its centre from above, grasps, lifts 5 mm, holds, releases and leaves.
  const auto patch = test::gridPatch(21, 21, 1.0f);
  SystemConfig config{.gravity = {0.0, 0.0, -kStandardGravity}};
  auto sim = restSimulator(test::patchSystem(patch, 0.02, 2e-4, 5.0, border(21, 21), config), patch, 1e-6);
  const Vec3d start{10.0, 10.0, 2.2};
  auto tool = Instrument::createLive({.shape = {ToolShapeKind::Sphere, 2.0}, .graspMarginMm = 0.5}, {start});
  ASSERT_TRUE(tool.ok());
  sim.setSubstepHook(&*tool);
  // Let the membrane sag under gravity, then bring the tool down onto it.
  for (int f = 0; f < 30; ++f)
    sim.advanceFrame();
  const double sag = sim.state().x[10 * 21 + 10].z;
  tool->setTarget({start + Vec3d{0.0, 0.0, sag}});
  sim.advanceFrame();
  auto taken = tool->grasp(sim);
  ASSERT_TRUE(taken.ok());
  ASSERT_EQ(*taken, 5u);  // the centre and its four edge neighbours
  std::vector<Vec3d> atGrasp;
  for (std::uint32_t k : tool->graspedVertices())
    atGrasp.push_back(sim.state().x[k]);

  // Lift 5 mm over 30 frames and hold: the grasped vertices move rigidly with the tool.
  const ToolPose graspPose = tool->pose();
  for (int f = 1; f <= 40; ++f) {
    tool->setTarget({graspPose.position + Vec3d{0.0, 0.0, 5.0 * std::min(1.0, f / 20.0)}});
    sim.advanceFrame();
  }
  for (std::size_t g = 0; g < atGrasp.size(); ++g) {
    const Vec3d moved = sim.state().x[tool->graspedVertices()[g]] - atGrasp[g];
    EXPECT_NEAR(moved.x, 0.0, 1e-9);
    EXPECT_NEAR(moved.y, 0.0, 1e-9);
    EXPECT_NEAR(moved.z, 5.0, 1e-9);
  }
  // Holding still: the force on the tool is the pull of the tissue on the grasped vertices,
  // computed here independently from the full force pass.
  std::vector<Vec3d> forces(sim.state().x.size());
  ForceScratch scratch;
  computeForces(sim.system(), sim.state().x, sim.state().v, forces, scratch);
  Vec3d pull{};
  for (std::uint32_t k : tool->graspedVertices())
    pull += forces[k];
  const Vec3d got = tool->lastFrame().forceN;
  EXPECT_LT(got.z, 0.0);  // the stretched membrane pulls the tool down
  EXPECT_NEAR(got.z, forceToNewton(pull.z), 1e-9 + 1e-6 * std::abs(forceToNewton(pull.z)));
  EXPECT_EQ(tool->lastFrame().contacts, 0u);

  // Release and take the tool away upwards: the vertices fall back towards the sag.
  const auto grasped =
      std::vector<std::uint32_t>(tool->graspedVertices().begin(), tool->graspedVertices().end());
  ASSERT_TRUE(tool->release(sim).ok());
  EXPECT_FALSE(tool->grasping());
  tool->setTarget({graspPose.position + Vec3d{0.0, 0.0, 30.0}});
  for (int f = 0; f < 90; ++f)
    sim.advanceFrame();
  for (std::uint32_t k : grasped)
    EXPECT_LT(sim.state().x[k].z, sag + 1.0) << "vertex " << k;
  EXPECT_NEAR(tool->lastFrame().forceN.z, 0.0, 1e-12);
}

TEST(Instrument, CapsuleGraspTurnsWithTheAxis) {
  const auto patch = test::gridPatch(5, 5, 1.0f);
  auto sim = restSimulator(test::patchSystem(patch, 0.05, 1e-4, 1.0, {}, {.gravity = {}}), patch);
  const ToolPose start{{2.0, 2.0, 1.0}, {1.0, 0.0, 0.0}};
  auto tool =
      Instrument::createLive({.shape = {ToolShapeKind::Capsule, 1.0, 2.0}, .graspMarginMm = 0.1}, start);
  ASSERT_TRUE(tool.ok());
  sim.setSubstepHook(&*tool);
  ASSERT_EQ(*tool->grasp(sim), 3u);  // (1,2), (2,2), (3,2): the row under the capsule's core
  tool->setTarget({start.position, {0.0, 1.0, 0.0}});  // a quarter turn about z
  sim.advanceFrame();
  const Vec3d end = sim.state().x[2 * 5 + 3];  // was at (3, 2, 0): offset (1, 0, -1)
  EXPECT_NEAR(end.x, 2.0, 1e-9);
  EXPECT_NEAR(end.y, 3.0, 1e-9);
  EXPECT_NEAR(end.z, 0.0, 1e-9);
}

TEST(Instrument, BadSettingsAreRejected) {
  EXPECT_FALSE(Instrument::create({.shape = {ToolShapeKind::Sphere, 0.0}}, {{0.0, {}}}).ok());
  EXPECT_FALSE(Instrument::create({}, {}).ok());
  EXPECT_FALSE(Instrument::create({}, {{1.0, {}}, {0.5, {}}}).ok());
  EXPECT_FALSE(Instrument::createLive({}, {{std::nan(""), 0.0, 0.0}}).ok());
}

TEST(Instrument, PathInterpolatesLinearly) {
  std::vector<ToolKeyframe> path{{0.0, {{0, 0, 0}}}, {1.0, {{10, 0, 0}}}, {3.0, {{10, 20, 0}}}};
  EXPECT_NEAR(poseOnPath(path, 0.5).position.x, 5.0, 1e-12);
  EXPECT_NEAR(poseOnPath(path, 2.0).position.y, 10.0, 1e-12);
  EXPECT_NEAR(poseOnPath(path, 9.0).position.y, 20.0, 1e-12);
  EXPECT_NEAR(poseOnPath(path, -1.0).position.x, 0.0, 1e-12);
}

/// An icosphere of radius 20 mm (642 surface vertices) carried by a 5 mm lattice (springs
/// 0.002 N/mm, 1e-6 N*s/mm; 1e-3 g/mm^3: below symplectic Euler's limit at 1 ms even for the
/// lightest corner node): the embedded organ of the lattice contact tests. Nodes
/// below z = `pinBelow` (mm) are pinned (none by default).
struct LatticeOrgan {
  test::ClosedSurface surface = test::icosphere(20.0, {0.0f, 0.0f, 0.0f}, 3);
  EmbeddedLattice lattice;
  MassSpringSystem system;
};

LatticeOrgan latticeOrgan(const SystemConfig& config, double pinBelow = -1e9) {
  LatticeOrgan o;
  o.lattice =
      buildEmbeddedLattice(
          o.surface.positions, o.surface.triangles,
          {.cellSize = 5.0, .springs = {.stiffness = 0.002, .damping = 1e-6}, .mass = {.density = 1e-3}})
          .value();
  std::vector<std::uint32_t> pinned;
  for (std::uint32_t n = 0; n < o.lattice.nodeCount(); ++n)
    if (o.lattice.nodePositions[n].z < pinBelow) pinned.push_back(n);
  o.system = makeSystem(o.lattice.springs, o.lattice.masses, pinned, config).value();
  return o;
}

/// Symplectic Euler at 17 substeps per 60 Hz frame (the default scenario's haptic rate).
Simulator latticeSimulator(const LatticeOrgan& o) {
  SimulatorConfig config{.integrator = Integrator::SymplecticEuler, .frameTime = 1.0 / 60.0, .substeps = 17};
  return Simulator::create(o.system, {o.lattice.nodePositions, std::vector<Vec3d>(o.lattice.nodeCount())},
                           config)
      .value();
}

std::vector<Vec3d> surfaceOf(const LatticeOrgan& o, const State& state) {
  std::vector<Vec3d> out(o.lattice.vertexNodes.size());
  for (std::size_t s = 0; s < out.size(); ++s)
    for (int c = 0; c < 8; ++c)
      out[s] += o.lattice.vertexWeights[s][c] * state.x[o.lattice.vertexNodes[s][c]];
  return out;
}

TEST(Instrument, LatticePokePushesTheEmbeddedSurfaceOutOfTheTool) {
  // A sphere of radius 6 mm comes down onto the top (z = 20 mm) of the lattice ball, pinned
  // below z = -12 mm, 8 mm deep over 0.5 s, and holds: every surface vertex (W x) stays out of
  // the tool to within the contact tolerance, while the lattice nodes need not.
  const LatticeOrgan o = latticeOrgan({.gravity = {}}, -12.0);
  Simulator sim = latticeSimulator(o);
  const double radius = 6.0;
  std::vector<ToolKeyframe> path{
      {0.0, {{0.0, 0.0, 27.0}}}, {0.1, {{0.0, 0.0, 27.0}}}, {0.6, {{0.0, 0.0, 18.0}}}};
  auto tool = Instrument::create({.shape = {ToolShapeKind::Sphere, radius}}, path);
  ASSERT_TRUE(tool.ok());
  ASSERT_TRUE(
      tool->setEmbedding({o.lattice.vertexNodes, o.lattice.vertexWeights}, o.lattice.nodeCount()).ok());
  sim.setSubstepHook(&*tool);
  const double tolerance = tool->config().contactToleranceFraction * radius;
  for (int f = 0; f < 60; ++f) {
    const FrameReport report = sim.advanceFrame();
    ASSERT_TRUE(report.events.empty()) << "frame " << f;
    const auto surface = surfaceOf(o, sim.state());
    for (std::size_t s = 0; s < surface.size(); ++s) {
      ASSERT_TRUE(isFinite(surface[s]));
      ASSERT_GE(signedDistance(tool->config().shape, tool->pose(), surface[s]), -tolerance - 1e-9)
          << "surface vertex " << s << " frame " << f;
    }
    const InstrumentFrameReport r = tool->lastFrame();
    ASSERT_TRUE(isFinite(r.forceN));
    EXPECT_LE(r.maxContactDepthMm, tolerance + 1e-12);
    ASSERT_EQ(r.forceSamplesN.size(), 17u);
  }
  const InstrumentFrameReport r = tool->lastFrame();
  EXPECT_GT(r.contacts, 3u);                           // surface vertices, not nodes
  EXPECT_GT(r.forceN.z, 0.0);                          // the compressed ball pushes the tool up
  EXPECT_LT(std::abs(r.forceN.x), 0.05 * r.forceN.z);  // the poke is symmetric
  // The top of the ball is pressed down, the bottom held by the pins.
  EXPECT_LT(surfaceOf(o, sim.state())[0].z, 20.5);
}

TEST(Instrument, LatticeContactForceIsTheReactionToTheNodesMomentum) {
  // A free lattice ball (no pins, no Rayleigh damping: only gravity and the tool act on it)
  // falls 1 mm onto a sphere of radius 60 mm: every frame the force on the tool is M g - dP/dt,
  // the whole ball's momentum balance, computed without the contact code; the per-substep
  // samples average to it.
  SystemConfig config{.gravity = {0.0, 0.0, -kStandardGravity}};
  const LatticeOrgan o = latticeOrgan(config);
  Simulator sim = latticeSimulator(o);
  double totalMass = 0.0;
  for (double m : o.system.masses)
    totalMass += m;
  auto tool = Instrument::createLive({.shape = {ToolShapeKind::Sphere, 60.0}}, {{0.0, 0.0, -81.0}});
  ASSERT_TRUE(tool.ok());
  ASSERT_TRUE(
      tool->setEmbedding({o.lattice.vertexNodes, o.lattice.vertexWeights}, o.lattice.nodeCount()).ok());
  sim.setSubstepHook(&*tool);
  const double T = 1.0 / 60.0;
  const double weightN = totalMass * kStandardGravity / kForcePerNewton;
  bool touched = false;
  double hardest = 0.0;
  for (int f = 0; f < 40; ++f) {
    const Vec3d p0 = linearMomentum(sim.system(), sim.state().v);
    ASSERT_TRUE(sim.advanceFrame().events.empty()) << "frame " << f;
    const Vec3d p1 = linearMomentum(sim.system(), sim.state().v);
    const Vec3d expected = (1.0 / kForcePerNewton) * (totalMass * config.gravity - (1.0 / T) * (p1 - p0));
    const InstrumentFrameReport r = tool->lastFrame();
    ASSERT_NEAR(r.forceN.x, expected.x, 1e-9 * weightN) << "frame " << f;
    ASSERT_NEAR(r.forceN.y, expected.y, 1e-9 * weightN) << "frame " << f;
    ASSERT_NEAR(r.forceN.z, expected.z, 1e-9 * weightN) << "frame " << f;
    Vec3d mean{};
    for (const Vec3d& sample : r.forceSamplesN)
      mean += (1.0 / static_cast<double>(r.forceSamplesN.size())) * sample;
    ASSERT_NEAR(mean.z, r.forceN.z, 1e-9 * weightN);
    touched = touched || r.contacts > 0;
    hardest = std::min(hardest, r.forceN.z);
  }
  EXPECT_TRUE(touched);
  EXPECT_LT(hardest, -0.5 * weightN);  // the landing ball pushes the tool down (it bounces off)
  for (const Vec3d& x : sim.state().x)
    ASSERT_TRUE(isFinite(x));
}

TEST(Instrument, LatticeGraspTakesTheCarryingNodesAndTheSurfaceFollowsRigidly) {
  const LatticeOrgan o = latticeOrgan({.gravity = {}}, -12.0);
  Simulator sim = latticeSimulator(o);
  const ToolPose start{{0.0, 0.0, 24.0}};
  auto tool = Instrument::createLive({.shape = {ToolShapeKind::Sphere, 3.0}, .graspMarginMm = 1.5}, start);
  ASSERT_TRUE(tool.ok());
  ASSERT_TRUE(
      tool->setEmbedding({o.lattice.vertexNodes, o.lattice.vertexWeights}, o.lattice.nodeCount()).ok());
  sim.setSubstepHook(&*tool);
  // The surface vertices within 4.5 mm of the tool centre: the top cap of the ball.
  std::vector<std::uint32_t> near;
  const auto rest = surfaceOf(o, sim.state());
  for (std::uint32_t s = 0; s < rest.size(); ++s)
    if (length(rest[s] - start.position) <= 4.5) near.push_back(s);
  ASSERT_FALSE(near.empty());
  auto taken = tool->grasp(sim);
  ASSERT_TRUE(taken.ok()) << taken.error().message;
  const std::vector<std::uint32_t> expected = cellNodes(o.lattice, near);
  ASSERT_EQ(std::vector<std::uint32_t>(tool->graspedVertices().begin(), tool->graspedVertices().end()),
            expected);
  for (int f = 1; f <= 20; ++f) {
    tool->setTarget({start.position + Vec3d{0.0, 0.0, 4.0 * f / 20.0}});
    ASSERT_TRUE(sim.advanceFrame().events.empty());
  }
  const auto lifted = surfaceOf(o, sim.state());
  for (std::uint32_t s : near) {
    EXPECT_NEAR(lifted[s].z - rest[s].z, 4.0, 1e-9) << "surface vertex " << s;
    EXPECT_NEAR(lifted[s].x, rest[s].x, 1e-9);
  }
  EXPECT_LT(tool->lastFrame().forceN.z, 0.0);  // the stretched ball pulls the tool down
  ASSERT_TRUE(tool->release(sim).ok());
  EXPECT_FALSE(tool->grasping());
}

TEST(Instrument, BadEmbeddingIsRejected) {
  const LatticeOrgan o = latticeOrgan({.gravity = {}});
  auto tool = Instrument::createLive({}, {});
  ASSERT_TRUE(tool.ok());
  EXPECT_FALSE(tool->setEmbedding({o.lattice.vertexNodes, o.lattice.vertexWeights}, 3).ok());
  EXPECT_FALSE(tool->setEmbedding({o.lattice.vertexNodes, std::span(o.lattice.vertexWeights).first(2)},
                                  o.lattice.nodeCount())
                   .ok());
}

}  // namespace
}  // namespace tissue::sim
