#include "tissue/mesh/deformable_surface.h"

#include <algorithm>
#include <type_traits>
#include <unordered_map>

#include "tissue/core/stopwatch.h"
#include "tissue/mesh/load_mesh.h"
#include "tissue/mesh/tangent_frames.h"
#include "tissue/mesh/vertex_normals.h"
#include "tissue/mesh/worker_pool.h"

namespace tissue::mesh {

std::vector<Float3> geometricPositionsOf(const SurfaceMesh& mesh) {
  std::vector<Float3> geo(mesh.geometricVertexCount);
  for (std::size_t i = 0; i < mesh.positions.size(); ++i)
    geo[mesh.geometricIndex[i]] = mesh.positions[i];
  return geo;
}

std::vector<Triangle> geometricTrianglesOf(const SurfaceMesh& mesh) {
  std::vector<Triangle> tris(mesh.triangles.size());
  for (std::size_t t = 0; t < tris.size(); ++t)
    for (int k = 0; k < 3; ++k)
      tris[t][k] = mesh.geometricIndex[mesh.triangles[t][k]];
  return tris;
}

namespace {

// Below these counts a second thread costs more than it saves.
constexpr std::size_t kMinTrianglesPerThread = 4096;
constexpr std::size_t kMinVerticesPerThread = 2048;

/// Vertices on an edge used by exactly one triangle (an open border).
std::vector<std::uint32_t> findBoundary(std::span<const Triangle> tris, std::size_t vertexCount) {
  std::unordered_map<std::uint64_t, int> uses;
  for (const auto& t : tris)
    for (int k = 0; k < 3; ++k) {
      const auto a = std::min(t[k], t[(k + 1) % 3]), b = std::max(t[k], t[(k + 1) % 3]);
      ++uses[(std::uint64_t(a) << 32) | b];
    }
  std::vector<char> onBorder(vertexCount, 0);
  for (const auto& [key, count] : uses)
    if (count == 1) onBorder[key >> 32] = onBorder[key & 0xFFFFFFFFu] = 1;
  std::vector<std::uint32_t> border;
  for (std::uint32_t v = 0; v < vertexCount; ++v)
    if (onBorder[v]) border.push_back(v);
  return border;
}

}  // namespace

Result<DeformableSurface> DeformableSurface::create(SurfaceMesh mesh, const PlaneFitSettings& planeSettings,
                                                    unsigned threadCount, const PlaneRefitSettings& refit) {
  if (auto ok = validateMesh(mesh, "deformable surface"); !ok) return ok.error();
  if (!mesh.hasUvs()) {
    return Error{
        "deformable surface: the mesh has no texture coordinates; tangent frames need UVs "
        "(load it with LoadOptions::requireUvs, or give it an atlas)"};
  }
  if (!(planeSettings.sigma_t > 0.0f) || !(planeSettings.epsilon > 0.0f && planeSettings.epsilon < 1.0f)) {
    return Error{
        "deformable surface: plane fit needs sigma_t > 0 mm^-1 and 0 < epsilon < 1; fix the material"};
  }
  auto geoRest = geometricPositionsOf(mesh);
  auto geoTris = geometricTrianglesOf(mesh);
  if (!(refit.maxNormalErrorRad >= 0.0)) {
    return Error{
        "deformable surface: plane re-fit needs maxNormalErrorRad >= 0 rad (0: exact); fix the setting"};
  }
  return DeformableSurface(std::move(mesh), std::move(geoRest), std::move(geoTris), planeSettings,
                           threadCount, refit);
}

DeformableSurface::DeformableSurface(SurfaceMesh mesh, std::vector<Float3> geoRest,
                                     std::vector<Triangle> geoTriangles, const PlaneFitSettings& settings,
                                     unsigned threadCount, const PlaneRefitSettings& refit)
    : m_mesh(std::move(mesh)),
      m_geoRest(std::move(geoRest)),
      m_geoPositions(m_geoRest),
      m_geoTriangles(std::move(geoTriangles)),
      m_boundary(findBoundary(m_geoTriangles, m_geoRest.size())),
      m_geoNormals(m_geoRest.size()),
      m_fitter(m_geoRest, m_geoTriangles, settings),
      m_refit(refit),
      m_normals(m_mesh.positions.size()),
      m_tangents(m_mesh.positions.size()),
      m_planes(m_mesh.positions.size()),
      m_geoCorners(buildVertexCorners(m_geoTriangles, m_geoRest.size())),
      m_tangentTopology(buildTangentTopology(m_mesh.uvs, m_mesh.triangles, m_mesh.geometricIndex)),
      m_triangleGeometry(m_mesh.triangles.size()),
      m_pool(std::make_unique<WorkerPool>(threadCount)) {
  computeNormals();
  m_fitter.fitAll(m_geoPositions, m_geoNormals);
  copyPlanes();
  // Render copies of one geometric vertex normally share its position; where a mesh came in
  // with split copies apart, tangents follow the render positions as given.
  const auto& gi = m_mesh.geometricIndex;
  for (std::size_t i = 0; i < m_mesh.positions.size(); ++i)
    if (!(m_mesh.positions[i] == m_geoPositions[gi[i]])) {
      computeTriangleGeometry(m_mesh.positions, m_mesh.triangles, m_tangentTopology.uvBases, 0,
                              m_mesh.triangles.size(), m_triangleGeometry);
      break;
    }
  computeTangents();
}

DeformableSurface::~DeformableSurface() = default;
DeformableSurface::DeformableSurface(DeformableSurface&&) noexcept = default;
DeformableSurface& DeformableSurface::operator=(DeformableSurface&&) noexcept = default;

unsigned DeformableSurface::threadCount() const {
  return m_pool->threadCount();
}

template <class Refit>
SurfaceUpdateStats DeformableSurface::updateWith(std::span<const Float3> geometricPositions,
                                                 const Refit& refit) {
  SurfaceUpdateStats stats;
  Stopwatch clock;
  // Phase: positions in (geometric -> render vertices).
  std::copy(geometricPositions.begin(), geometricPositions.end(), m_geoPositions.begin());
  for (std::size_t i = 0; i < m_mesh.positions.size(); ++i)
    m_mesh.positions[i] = m_geoPositions[m_mesh.geometricIndex[i]];
  stats.gatherMs = clock.elapsedMs();
  // Phase: normals, per geometric vertex so they agree across UV seams.
  clock.restart();
  computeNormals();
  stats.normalsMs = clock.elapsedMs();
  // Phase: local planes, re-fitted only where a neighbourhood moved enough to matter (and only
  // when the renderer reads them: setWork).
  clock.restart();
  if (m_work.planes) {
    if constexpr (std::is_same_v<Refit, PlaneRefitSettings>) {
      stats.refit = m_fitter.update(m_geoPositions, m_geoNormals, refit, m_pool.get());
    } else {
      stats.refit = m_fitter.update(m_geoPositions, m_geoNormals, refit);
    }
    copyPlanes();
    stats.planes = true;
  }
  m_planesCurrent = m_work.planes;
  stats.planesMs = clock.elapsedMs();
  // Phase: tangent frames, per render vertex from each chart's own UVs.
  clock.restart();
  if (m_work.tangents) computeTangents();
  stats.tangents = m_tangentsCurrent = m_work.tangents;
  stats.tangentsMs = clock.elapsedMs();
  return stats;
}

SurfaceUpdateStats DeformableSurface::update(std::span<const Float3> geometricPositions) {
  return updateWith(geometricPositions, m_refit);
}

SurfaceUpdateStats DeformableSurface::update(std::span<const Float3> geometricPositions, float toleranceMm) {
  return updateWith(geometricPositions, toleranceMm);
}

void DeformableSurface::refitAllPlanes() {
  m_fitter.fitAll(m_geoPositions, m_geoNormals);
  copyPlanes();
  m_planesCurrent = true;
}

void DeformableSurface::refitPlanes() {
  // The fitter compares the positions with those of its last fit (exact mode) or each plane's
  // last solve (tolerant mode), so one update covers every frame it missed.
  m_fitter.update(m_geoPositions, m_geoNormals, m_refit, m_pool.get());
  copyPlanes();
  m_planesCurrent = true;
}

SurfaceWork DeformableSurface::setWork(const SurfaceWork& work) {
  SurfaceWork refreshed{.planes = false, .tangents = false};
  m_work = work;
  // The normals and the triangles' shading geometry are current after every update.
  if (work.planes && !m_planesCurrent) {
    refitPlanes();
    refreshed.planes = true;
  }
  if (work.tangents && !m_tangentsCurrent) {
    computeTangents();
    m_tangentsCurrent = refreshed.tangents = true;
  }
  return refreshed;
}

void DeformableSurface::computeNormals() {
  // Per triangle, once: face normal, corner angles and (for the tangent phase) UV gradients.
  // Render triangle t is geometric triangle t re-indexed, so one pass serves both.
  m_pool->parallelFor(m_geoTriangles.size(), kMinTrianglesPerThread, [&](std::size_t b, std::size_t e) {
    computeTriangleGeometry(m_geoPositions, m_geoTriangles, m_tangentTopology.uvBases, b, e,
                            m_triangleGeometry);
  });
  // Per geometric vertex: gather its corners, then hand the normal to its render copies.
  const std::size_t groups = std::min(m_geoNormals.size(), m_tangentTopology.groupCount());
  const std::uint32_t* offsets = m_tangentTopology.copyOffsets.data();
  const std::uint32_t* copies = m_tangentTopology.copies.data();
  m_pool->parallelFor(m_geoNormals.size(), kMinVerticesPerThread, [&](std::size_t b, std::size_t e) {
    gatherVertexNormals(m_triangleGeometry, m_geoCorners, b, e, m_geoNormals);
    for (std::size_t g = b; g < std::min(e, groups); ++g)
      for (std::uint32_t j = offsets[g]; j < offsets[g + 1]; ++j)
        m_normals[copies[j]] = m_geoNormals[g];
  });
}

void DeformableSurface::computeTangents() {
  computeTangentFrames(m_triangleGeometry, m_tangentTopology, m_normals, m_tangents, m_pool.get());
}

void DeformableSurface::copyPlanes() {
  const auto planes = m_fitter.planes();
  for (std::size_t i = 0; i < m_planes.size(); ++i)
    m_planes[i] = planes[m_mesh.geometricIndex[i]];
}

}  // namespace tissue::mesh
