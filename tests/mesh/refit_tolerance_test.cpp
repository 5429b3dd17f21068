// The tolerant incremental re-fit of the local planes (issue 11): under a simulated run every
// plane normal stays within PlaneRefitSettings::maxNormalErrorRad of a full re-fit of the
// simulated positions, every frame, and the exact path (bound 0) stays bit-identical to it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <random>

#include "test_meshes.h"
#include "tissue/mesh/deformable_surface.h"
#include "tissue/mesh/local_planes.h"
#include "tissue/mesh/vertex_normals.h"
#include "tissue/scenario/scenario_run.h"

namespace tissue::mesh {
namespace {

constexpr double kTheta = 1e-4;  // rad, the default bound

std::vector<Float3> normalsOf(std::span<const Float3> p, std::span<const Triangle> t) {
  std::vector<Float3> n(p.size());
  computeVertexNormals(p, t, n);
  return n;
}

double angle(Float4 a, Float4 b) {
  return test::angleBetween({a.x, a.y, a.z}, {b.x, b.y, b.z});
}

/// The offset bound of the tolerant path: d = N_S.(c - V) / a with a = N_S.N_V (0.1 floor as in
/// the fit); a tilt theta of N_S changes the numerator by <= theta |c - V| and a by <= theta, so
/// |d - d_full| <= theta R (1 + 1 / a) / a, with R the neighbourhood's extent about V; plus the
/// float rounding of d (1e-5 mm).
double offsetBound(double theta, double extentMm, double along) {
  const double a = std::max(along, 0.1);
  return theta * extentMm * (1.0 + 1.0 / a) / a + 1e-5;
}

/// The largest distance of a neighbour from its vertex, per vertex, mm.
std::vector<double> extents(std::span<const Float3> p, const Neighbourhoods& h) {
  std::vector<double> r(p.size(), 0.0);
  for (std::size_t v = 0; v < p.size(); ++v)
    for (auto k = h.offsets[v]; k < h.offsets[v + 1]; ++k) {
      const Float3 q = p[h.indices[k]];
      const double dx = q.x - p[v].x, dy = q.y - p[v].y, dz = q.z - p[v].z;
      r[v] = std::max(r[v], std::sqrt(dx * dx + dy * dy + dz * dz));
    }
  return r;
}

/// The default scenario, shortened: `frames` frames, its instrument script sped up so that
/// half of it happens in them (contact, push, back-off, grasp on the liver), whatever the
/// scenario's mesh or springs are.
Result<scenario::Scenario> shortScenario(int frames) {
  auto s = scenario::loadScenario(
      std::filesystem::path(TISSUE_TEST_DATA_DIR) / "scenarios" / "liver_poke_grasp.json",
      {.sharedMeshesDir = std::filesystem::path(TISSUE_TEST_SHARED_DIR) / "meshes"});
  if (!s) return s.error();
  s->frames = frames;
  if (s->instrument && !s->instrument->path.empty()) {
    const double end = s->instrument->path.back().time;
    const double factor = std::max(1.0, end / (2.0 * frames * s->frameTime));
    for (auto& key : s->instrument->path)
      key.time /= factor;
    for (auto& action : s->instrument->actions)
      action.time /= factor;
  }
  return s;
}

TEST(RefitTolerance, SimulatedRunKeepsEveryNormalWithinTheBoundAndTheExactPathBitIdentical) {
  auto s = shortScenario(60);
  ASSERT_TRUE(s.ok()) << s.error().message;
  auto run = scenario::ScenarioRun::create(*s);
  ASSERT_TRUE(run.ok()) << run.error().message;
  const SurfaceMesh& surfaceMesh = (*run)->mesh().surface;
  ASSERT_TRUE(surfaceMesh.hasUvs()) << "the scenario's mesh needs UVs for a DeformableSurface";
  const PlaneFitSettings fit{};  // r = 3.07 mm, the liver's first layer
  auto tolerant = DeformableSurface::create(surfaceMesh, fit, 1);
  auto exact = DeformableSurface::create(surfaceMesh, fit, 1, {.maxNormalErrorRad = 0.0});
  ASSERT_TRUE(tolerant.ok() && exact.ok());
  ASSERT_EQ(tolerant->planeRefit().maxNormalErrorRad, kTheta);  // the default is the bound tested
  const std::size_t n = tolerant->geometricRestPositions().size();
  ASSERT_EQ((*run)->positions().size(), n) << "one simulated position per geometric surface vertex";
  const auto tris = tolerant->geometricTriangles();
  // The reference: every plane summed from scratch at the simulated positions, each frame.
  IncrementalPlaneFitter reference(tolerant->geometricRestPositions(), tris, fit);
  const auto rest = tolerant->geometricRestPositions();
  double worstAngle = 0.0, worstOffsetRatio = 0.0, largestMotion = 0.0;
  std::size_t tolerantRefits = 0, exactRefits = 0;
  for (int frame = 0; frame < s->frames; ++frame) {
    auto m = (*run)->advance();
    ASSERT_TRUE(m.ok()) << m.error().message;
    const auto p = (*run)->positions();
    for (std::size_t v = 0; v < n; ++v) {
      const Float3 d = {p[v].x - rest[v].x, p[v].y - rest[v].y, p[v].z - rest[v].z};
      largestMotion = std::max(largestMotion, double(std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z)));
    }
    const auto ut = tolerant->update(p);
    const auto ue = exact->update(p);
    tolerantRefits += ut.refit.refittedPlanes, exactRefits += ue.refit.refittedPlanes;
    const auto normals = normalsOf(p, tris);
    reference.fitAll(p, normals);
    const auto full = reference.planes();
    const auto tp = tolerant->planeFitter().planes(), ep = exact->planeFitter().planes();
    const auto r = extents(p, reference.neighbourhoods());
    for (std::size_t v = 0; v < n; ++v) {
      ASSERT_EQ(ep[v], full[v]) << "exact path, frame " << frame << " vertex " << v;
      const double a = angle(tp[v], full[v]);
      ASSERT_LE(a, kTheta) << "frame " << frame << " vertex " << v;
      worstAngle = std::max(worstAngle, a);
      const double along = full[v].x * normals[v].x + full[v].y * normals[v].y + full[v].z * normals[v].z;
      const double bound = offsetBound(kTheta, r[v], along);
      const double off = std::abs(double(tp[v].w) - double(full[v].w));
      ASSERT_LE(off, bound) << "frame " << frame << " vertex " << v;
      worstOffsetRatio = std::max(worstOffsetRatio, off / bound);
    }
  }
  std::printf(
      "[ refit ] %d frames, largest motion %.2f mm: worst normal %.2e rad (bound %.0e), worst offset "
      "%.2f of its bound, planes re-solved %zu tolerant vs %zu exact\n",
      s->frames, largestMotion, worstAngle, kTheta, worstOffsetRatio, tolerantRefits, exactRefits);
  EXPECT_GT(largestMotion, 1.0) << "the run must deform the surface, or it tests nothing";
  EXPECT_LE(tolerantRefits, exactRefits);  // the tolerant planes are a subset of the exact ones
}

/// A rigid translation changes no plane's shape: nothing is re-solved, the centroid follows the
/// mean displacement, and the planes equal a full re-fit of the translated mesh.
TEST(RefitTolerance, TranslationReSolvesNothing) {
  const auto sphere = test::makeUvSphere(30.0f, 40, 80);
  const auto rest = geometricPositionsOf(sphere);
  const auto tris = geometricTrianglesOf(sphere);
  IncrementalPlaneFitter fitter(rest, tris), reference(rest, tris);
  fitter.fitAll(rest, normalsOf(rest, tris));
  auto p = rest;
  for (auto& q : p)
    q = {q.x + 0.75f, q.y - 0.5f, q.z + 0.25f};
  const auto n = normalsOf(p, tris);
  const auto stats = fitter.update(p, n, PlaneRefitSettings{});
  reference.fitAll(p, n);
  EXPECT_EQ(stats.refittedPlanes, 0u);
  EXPECT_EQ(stats.movedVertices, p.size());
  const auto dev = comparePlanes(fitter.planes(), reference.planes());
  EXPECT_LT(dev.maxAngleRad, kTheta);
  EXPECT_LT(dev.maxOffsetMm, 1e-4);
}

/// Random per-vertex jitter, accumulating frame after frame: every frame within the bound, and
/// a bound of zero or a switch back to the exact path gives the full re-fit bit for bit.
TEST(RefitTolerance, AccumulatingJitterStaysWithinTheBoundAndExactPathIsBitIdentical) {
  const auto sphere = test::makeUvSphere(30.0f, 40, 80);
  const auto rest = geometricPositionsOf(sphere);
  const auto tris = geometricTrianglesOf(sphere);
  IncrementalPlaneFitter fitter(rest, tris), reference(rest, tris);
  fitter.fitAll(rest, normalsOf(rest, tris));
  std::mt19937 rng(11);
  std::normal_distribution<float> jitter(0.0f, 2e-5f);  // mm per frame and axis
  auto p = rest;
  std::size_t refitted = 0;
  for (int frame = 0; frame < 40; ++frame) {
    for (auto& q : p)
      q = {q.x + jitter(rng), q.y + jitter(rng), q.z + jitter(rng)};
    const auto n = normalsOf(p, tris);
    refitted += fitter.update(p, n, PlaneRefitSettings{}).refittedPlanes;
    reference.fitAll(p, n);
    ASSERT_LT(comparePlanes(fitter.planes(), reference.planes()).maxAngleRad, kTheta) << "frame " << frame;
  }
  EXPECT_GT(refitted, 0u);                 // the jitter does add up past the tolerances
  EXPECT_LT(refitted, 40 * p.size() / 2);  // but most frames keep most planes
  // Back to the exact path: bit-identical to a full re-fit, and stays so.
  for (int frame = 0; frame < 3; ++frame) {
    p[std::size_t(frame) * 97].z += 0.3f;
    const auto n = normalsOf(p, tris);
    fitter.update(p, n, 0.0f);
    reference.fitAll(p, n);
    for (std::size_t v = 0; v < p.size(); ++v)
      ASSERT_EQ(fitter.planes()[v], reference.planes()[v]) << "frame " << frame << " vertex " << v;
  }
  const auto n = normalsOf(p, tris);
  fitter.update(p, n, PlaneRefitSettings{.maxNormalErrorRad = 0.0});
  reference.fitAll(p, n);
  for (std::size_t v = 0; v < p.size(); ++v)
    ASSERT_EQ(fitter.planes()[v], reference.planes()[v]) << "vertex " << v;
}

}  // namespace
}  // namespace tissue::mesh
