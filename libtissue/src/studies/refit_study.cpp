// Full versus incremental re-fit of the local planes (François 2009 §2.2).
#include "tissue/studies/refit_study.h"

#include <algorithm>
#include <vector>

#include "tissue/core/statistics.h"
#include "tissue/core/stopwatch.h"
#include "tissue/mesh/vertex_normals.h"

namespace tissue::studies {

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

}  // namespace tissue::studies
