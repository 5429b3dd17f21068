// A spring network built from a mesh file, summarised (spring_network_report.h).
#include "tissue/studies/spring_network_report.h"

#include <algorithm>
#include <numeric>

#include "json_text.h"
#include "tissue/core/statistics.h"
#include "tissue/core/stopwatch.h"
#include "tissue/mesh/deformable_surface.h"
#include "tissue/mesh/load_mesh.h"
#include "tissue/sim/mass.h"
#include "tissue/sim/tet_springs.h"
#include "tissue/volume/tet_mesh.h"

namespace tissue::studies {
namespace {

/// Builds once untimed, then `repeats` times timed; the median wall time in ms to `ms`.
template <class Build>
auto timed(int repeats, double& ms, Build build) {
  std::vector<double> times;
  auto result = build();
  for (int r = 0; r < std::max(1, repeats) && result; ++r) {
    Stopwatch watch;
    result = build();
    times.push_back(watch.elapsedMs());
  }
  ms = summarizeSamples(times).median;
  return result;
}

double sum(const std::vector<double>& v) {
  return std::accumulate(v.begin(), v.end(), 0.0);
}

}  // namespace

std::string_view springSourceName(SpringSource source) {
  switch (source) {
    case SpringSource::Surface:
      return "surface";
    case SpringSource::TetEdges:
      return "tet-edges";
    case SpringSource::Lattice:
      return "lattice";
  }
  return "?";
}

std::optional<SpringSource> parseSpringSource(std::string_view name) {
  for (SpringSource s : {SpringSource::Surface, SpringSource::TetEdges, SpringSource::Lattice})
    if (springSourceName(s) == name) return s;
  return std::nullopt;
}

Result<SpringNetworkSummary> buildSpringNetworkSummary(const std::filesystem::path& file,
                                                       const SpringNetworkConfig& config) {
  const bool volumeFile = volume::isTetMeshPath(file);
  SpringNetworkSummary s;
  s.source = config.source.value_or(volumeFile ? SpringSource::TetEdges : SpringSource::Lattice);
  if (s.source == SpringSource::TetEdges) {
    if (!volumeFile) return Error{file.string() + ": tet-edges needs a volume mesh (.vtk, .vtu, .msh)"};
    auto mesh = volume::loadTetMesh(file, {.scaleToMm = config.scaleToMm});
    if (!mesh) return mesh.error();
    auto net = timed(config.repeats, s.buildMs,
                     [&] { return sim::buildTetEdgeSprings(mesh->positions, mesh->tets, config.springs); });
    if (!net) return net.error();
    auto masses = sim::computeTetMasses(mesh->positions, mesh->tets, {});
    if (!masses) return masses.error();
    s.tets = mesh->tets.size();
    s.simVertices = mesh->positions.size();
    s.springs = net->size();
    s.volumeMm3 = volume::totalVolume(*mesh);
    s.massG = sum(*masses);
    return s;
  }
  if (volumeFile)
    return Error{file.string() + ": " + std::string(springSourceName(s.source)) +
                 " springs need a surface mesh"};
  auto surface = mesh::loadMesh(file, {.scaleToMm = config.scaleToMm});
  if (!surface) return surface.error();
  // Geometric vertices (merged across UV seams), as the lattice needs.
  const auto positions = mesh::geometricPositionsOf(*surface);
  const auto triangles = mesh::geometricTrianglesOf(*surface);
  s.surfaceVertices = positions.size();
  s.surfaceTriangles = triangles.size();
  if (s.source == SpringSource::Surface) {
    auto net = timed(config.repeats, s.buildMs,
                     [&] { return sim::buildSurfaceSprings(positions, triangles, config.springs); });
    if (!net) return net.error();
    s.simVertices = positions.size();
    s.springs = net->size();
    return s;
  }
  const sim::LatticeConfig lattice{.cellSize = config.latticeCellSizeMm,
                                   .cellsAlongLongestAxis = config.latticeCells,
                                   .springs = config.springs};
  auto built = timed(config.repeats, s.buildMs,
                     [&] { return sim::buildEmbeddedLattice(positions, triangles, lattice); });
  if (!built) return built.error();
  s.simVertices = built->nodeCount();
  s.springs = built->springs.size();
  s.massG = sum(built->masses);
  s.lattice = std::move(*built);
  return s;
}

std::string springNetworkJson(const SpringNetworkSummary& s) {
  nlohmann::json out{{"source", springSourceName(s.source)},
                     {"build_ms", s.buildMs},
                     {"sim_vertices", s.simVertices},
                     {"springs", s.springs},
                     {"units", "mm, g, ms"}};
  if (s.massG) out["mass_g"] = *s.massG;
  if (s.source == SpringSource::TetEdges) {
    out.update({{"tets", s.tets}, {"volume_mm3", s.volumeMm3}});
  } else {
    out.update({{"surface_vertices", s.surfaceVertices}, {"surface_triangles", s.surfaceTriangles}});
  }
  if (const auto& l = s.lattice)
    out.update({{"cell_size_mm", l->cellSize},
                {"grid_cells", l->gridCells},
                {"cells", l->cells.size()},
                {"inside_cells", l->insideCells},
                {"vertex_cells", l->vertexCells},
                {"filled_volume_mm3", l->filledVolume}});
  return detail::jsonText(out);
}

}  // namespace tissue::studies
