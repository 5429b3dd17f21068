// Full versus incremental re-fit of the local planes (François 2009 §2.2).
#include "tissue/studies/refit_study.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "json_text.h"
#include "tissue/core/statistics.h"
#include "tissue/core/stopwatch.h"
#include "tissue/core/vec_math.h"
#include "tissue/mesh/deformable_surface.h"
#include "tissue/mesh/vertex_normals.h"
#include "tissue/scenario/scenario_run.h"
#include "tissue/studies/deformations.h"

namespace tissue::studies {
namespace {

/// Per-frame figures of one DeformableSurface under the simulator.
struct SeriesStats {
  std::vector<double> planesMs;
  double refitted = 0.0;  // sum of per-frame fractions
  double maxAngle = 0.0, maxOffset = 0.0;
  void add(const mesh::SurfaceUpdateStats& u, std::size_t vertices, const mesh::PlaneDeviation& d) {
    planesMs.push_back(u.planesMs);
    refitted += double(u.refit.refittedPlanes) / double(vertices);
    maxAngle = std::max(maxAngle, d.maxAngleRad), maxOffset = std::max(maxOffset, d.maxOffsetMm);
  }
  RefitSeries result(double refitRad) const {
    RefitSeries r;
    r.maxNormalErrorRad = refitRad;
    r.meanRefittedFraction = refitted / double(std::max<std::size_t>(planesMs.size(), 1));
    r.planesMsMedian = quantile(planesMs, 0.5);
    r.planesMsP99 = quantile(planesMs, 0.99);
    r.planesMsMax = quantile(planesMs, 1.0);
    r.maxNormalDeviationRad = maxAngle;
    r.maxOffsetDeviationMm = maxOffset;
    return r;
  }
};

}  // namespace

RefitComparison compareRefits(std::span<const Float3> rest, std::span<const Float3> deformed,
                              std::span<const Triangle> tris, const mesh::PlaneFitSettings& settings,
                              int repeats, const mesh::PlaneRefitSettings& refit) {
  std::vector<Float3> restNormals(rest.size()), defNormals(rest.size());
  mesh::computeVertexNormals(rest, tris, restNormals);
  mesh::computeVertexNormals(deformed, tris, defNormals);
  mesh::IncrementalPlaneFitter fitter(rest, tris, settings), tolerant(rest, tris, settings);
  fitter.fitAll(rest, restNormals);
  tolerant.fitAll(rest, restNormals);
  std::vector<Float4> full(rest.size());
  std::vector<double> fullMs, incMs, tolMs;
  mesh::RefitStats stats, tolStats;
  RefitComparison out;
  for (int r = 0; r < repeats; ++r) {
    Stopwatch clock;
    mesh::fitVertexPlanes(deformed, defNormals, fitter.neighbourhoods(), full);
    fullMs.push_back(clock.elapsedMs());
    clock.restart();
    stats = fitter.update(deformed, defNormals);
    incMs.push_back(clock.elapsedMs());
    clock.restart();
    tolStats = tolerant.update(deformed, defNormals, refit);
    tolMs.push_back(clock.elapsedMs());
    const auto dev = mesh::comparePlanes(fitter.planes(), full);
    out.exact.maxNormalDeviationRad = std::max(out.exact.maxNormalDeviationRad, dev.maxAngleRad);
    out.exact.maxOffsetDeviationMm = std::max(out.exact.maxOffsetDeviationMm, dev.maxOffsetMm);
    const auto tdev = mesh::comparePlanes(tolerant.planes(), full);
    out.tolerant.maxNormalDeviationRad = std::max(out.tolerant.maxNormalDeviationRad, tdev.maxAngleRad);
    out.tolerant.maxOffsetDeviationMm = std::max(out.tolerant.maxOffsetDeviationMm, tdev.maxOffsetMm);
    fitter.update(rest, restNormals);  // back to rest (same vertices move), untimed
    tolerant.update(rest, restNormals, refit);
  }
  const double n = double(std::max<std::size_t>(rest.size(), 1));
  out.movedFraction = double(stats.movedVertices) / n;
  out.fullRefitMs = fullMs.empty() ? 0.0 : quantile(fullMs, 0.5);
  out.exact.refittedFraction = double(stats.refittedPlanes) / n;
  out.exact.refitMs = incMs.empty() ? 0.0 : quantile(incMs, 0.5);
  out.tolerant.refittedFraction = double(tolStats.refittedPlanes) / n;
  out.tolerant.refitMs = tolMs.empty() ? 0.0 : quantile(tolMs, 0.5);
  return out;
}

Result<ScenarioRefitStudy> studyRefitUnderScenario(const scenario::Scenario& scenarioSpec,
                                                   const SurfaceMesh& surfaceMesh,
                                                   const mesh::PlaneFitSettings& settings,
                                                   double maxNormalErrorRad, int frameCount) {
  auto exact = mesh::DeformableSurface::create(surfaceMesh, settings, 0, {.maxNormalErrorRad = 0.0});
  if (!exact) return exact.error();
  auto tolerant =
      mesh::DeformableSurface::create(surfaceMesh, settings, 0, {.maxNormalErrorRad = maxNormalErrorRad});
  if (!tolerant) return tolerant.error();
  auto run = scenario::ScenarioRun::create(scenarioSpec);
  if (!run) return run.error();
  const std::size_t n = exact->geometricRestPositions().size();
  if ((*run)->mesh().positions.size() != n)
    return Error{"the simulated mesh has " + std::to_string((*run)->mesh().positions.size()) +
                 " vertices but the shaded one " + std::to_string(n)};
  const auto tris = exact->geometricTriangles();
  std::vector<Float3> previous(exact->geometricRestPositions().begin(),
                               exact->geometricRestPositions().end());
  std::vector<Float3> normals(n);
  std::vector<Float4> full(n);
  SeriesStats before, after;
  std::vector<double> normalsMs, tangentsMs, fullMs;
  ScenarioRefitStudy out;
  double changed = 0.0;  // vertices whose position changed at all, summed fractions
  // How far vertices move per frame: the fraction beyond each step (mm), summed over frames.
  std::array<double, kRefitMotionStepsMm.size()> stepAbove{};
  for (int frame = 0; frame < frameCount; ++frame) {
    auto metrics = (*run)->advance();
    if (!metrics) return metrics.error();
    const std::vector<Float3> positions = (*run)->positions();
    std::size_t moved = 0;
    for (std::size_t v = 0; v < n; ++v) {
      moved += positions[v] == previous[v] ? 0 : 1;
      const Float3 d{positions[v].x - previous[v].x, positions[v].y - previous[v].y,
                     positions[v].z - previous[v].z};
      const float len = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
      for (std::size_t k = 0; k < kRefitMotionStepsMm.size(); ++k)
        stepAbove[k] += len > kRefitMotionStepsMm[k] ? 1.0 / double(n) : 0.0;
    }
    changed += double(moved) / double(n);
    previous = positions;
    const auto ue = exact->update(positions);
    const auto ut = tolerant->update(positions);
    normalsMs.push_back(ut.normalsMs), tangentsMs.push_back(ut.tangentsMs);
    // The reference: a full re-fit of the simulated positions with their normals.
    Stopwatch clock;
    mesh::computeVertexNormals(positions, tris, normals);
    mesh::fitVertexPlanes(positions, normals, exact->planeFitter().neighbourhoods(), full);
    fullMs.push_back(clock.elapsedMs());
    before.add(ue, n, mesh::comparePlanes(exact->planeFitter().planes(), full));
    after.add(ut, n, mesh::comparePlanes(tolerant->planeFitter().planes(), full));
  }
  const double frames = std::max(frameCount, 1);
  out.vertices = n;
  out.frames = frameCount;
  out.meanChangedVertexFraction = changed / frames;
  for (std::size_t k = 0; k < kRefitMotionStepsMm.size(); ++k)
    out.meanFractionBeyond[k] = stepAbove[k] / frames;
  std::vector<double> tol;
  for (float t : tolerant->planeFitter().toleranceMmPerRad())
    tol.push_back(maxNormalErrorRad * double(t));
  out.toleranceMmP10 = quantile(tol, 0.1);
  out.toleranceMmMedian = quantile(tol, 0.5);
  out.toleranceMmP90 = quantile(tol, 0.9);
  out.normalsMsMedian = quantile(normalsMs, 0.5);
  out.tangentsMsMedian = quantile(tangentsMs, 0.5);
  out.fullRefitMsMedian = quantile(fullMs, 0.5);
  out.exact = before.result(0.0);
  out.tolerant = after.result(maxNormalErrorRad);
  return out;
}

namespace {

nlohmann::json comparisonJson(const RefitComparison& c, double maxNormalErrorRad) {
  return {{"moved_fraction", c.movedFraction},
          {"refitted_fraction", c.exact.refittedFraction},
          {"full_refit_ms", c.fullRefitMs},
          {"incremental_refit_ms", c.exact.refitMs},
          {"speedup", c.speedup()},
          {"max_normal_deviation_rad", c.exact.maxNormalDeviationRad},
          {"max_offset_deviation_mm", c.exact.maxOffsetDeviationMm},
          {"tolerant",
           {{"max_normal_error_rad", maxNormalErrorRad},
            {"refitted_fraction", c.tolerant.refittedFraction},
            {"refit_ms", c.tolerant.refitMs},
            {"max_normal_deviation_rad", c.tolerant.maxNormalDeviationRad},
            {"max_offset_deviation_mm", c.tolerant.maxOffsetDeviationMm}}}};
}

nlohmann::json seriesJson(const RefitSeries& r) {
  return {{"max_normal_error_rad", r.maxNormalErrorRad},
          {"mean_refitted_fraction", r.meanRefittedFraction},
          {"planes_ms_median", r.planesMsMedian},
          {"planes_ms_p99", r.planesMsP99},
          {"planes_ms_max", r.planesMsMax},
          {"max_normal_deviation_rad", r.maxNormalDeviationRad},
          {"max_offset_deviation_mm", r.maxOffsetDeviationMm}};
}

}  // namespace

MeshRefitBench benchRefitOnMesh(std::span<const Float3> rest, std::span<const Triangle> tris,
                                const mesh::PlaneFitSettings& settings, double pokeFraction, int repeats,
                                const mesh::PlaneRefitSettings& refit) {
  std::vector<Float3> normals(rest.size());
  mesh::computeVertexNormals(rest, tris, normals);
  // A poke as deep as 3% of the mesh's extent, at the top of the mesh.
  const Bounds3 box = boundsOf(rest);
  const float size = std::max({box.hi.x - box.lo.x, box.hi.y - box.lo.y, box.hi.z - box.lo.z});
  std::vector<Float3> poked(rest.size()), bent(rest.size());
  applyPoke(rest, normals, topVertex(rest), pokeFraction, 0.03f * size, poked);
  applyGlobalBend(rest, 0.05f * size, bent);
  MeshRefitBench b{
      .vertices = rest.size(), .settings = settings, .maxNormalErrorRad = refit.maxNormalErrorRad};
  b.repeats = repeats > 0 ? repeats : int(std::clamp<std::size_t>(2000000 / rest.size(), 5, 200));
  b.meanNeighbourhood =
      double(mesh::IncrementalPlaneFitter(rest, tris, settings).neighbourhoods().indices.size()) /
      double(rest.size());
  b.poke = compareRefits(rest, poked, tris, settings, b.repeats, refit);
  b.bend = compareRefits(rest, bent, tris, settings, std::max(3, b.repeats / 4), refit);
  return b;
}

std::string meshRefitBenchJson(const MeshRefitBench& b) {
  nlohmann::json out = comparisonJson(b.poke, b.maxNormalErrorRad);
  out.update({{"vertices", b.vertices},
              {"radius_mm", b.settings.radiusMm()},
              {"sigma_t_per_mm", b.settings.sigma_t},
              {"epsilon", b.settings.epsilon},
              {"mean_neighbourhood", b.meanNeighbourhood},
              {"repeats", b.repeats},
              {"global", comparisonJson(b.bend, b.maxNormalErrorRad)}});
  return detail::jsonText(out);
}

std::string scenarioRefitJson(const ScenarioRefitStudy& s) {
  nlohmann::json steps = nlohmann::json::object();
  for (std::size_t k = 0; k < kRefitMotionStepsMm.size(); ++k)
    steps[std::to_string(kRefitMotionStepsMm[k]) + "_mm"] = s.meanFractionBeyond[k];
  return detail::jsonText(
      {{"vertices", s.vertices},
       {"frames", s.frames},
       {"mean_changed_vertex_fraction", s.meanChangedVertexFraction},
       {"mean_fraction_moving_per_frame_beyond", steps},
       {"plane_tolerance_mm",
        {{"p10", s.toleranceMmP10}, {"median", s.toleranceMmMedian}, {"p90", s.toleranceMmP90}}},
       {"normals_ms_median", s.normalsMsMedian},
       {"tangents_ms_median", s.tangentsMsMedian},
       {"full_refit_ms_median", s.fullRefitMsMedian},
       {"exact", seriesJson(s.exact)},
       {"tolerant", seriesJson(s.tolerant)}});
}

}  // namespace tissue::studies
