// tissue-sim springs FILE: builds a spring network from a mesh (surface springs, tet edges or an
// embedded lattice) and reports its size, masses and build time.
#include <algorithm>
#include <cmath>
#include <numeric>

#include "command.h"
#include "output.h"
#include "tissue/core/statistics.h"
#include "tissue/core/stopwatch.h"
#include "tissue/mesh/deformable_surface.h"
#include "tissue/mesh/load_mesh.h"
#include "tissue/sim/lattice.h"
#include "tissue/sim/mass.h"
#include "tissue/sim/tet_springs.h"
#include "tissue/volume/tet_mesh.h"

namespace tissue::sim_app {
namespace {

struct SpringsOptions {
  std::string file;
  std::string source;  // surface | tet-edges | lattice; empty: tet-edges for volumes, lattice else
  int cells = 12;
  double cellSize = 0.0;
  float scale = 1.0f;
  double stiffness = 0.1;
  bool perRestLength = false;
  int repeats = 5;
};

/// Runs `build` o.repeats times; the median wall time in ms goes to out["build_ms"].
template <class Build>
auto timed(const SpringsOptions& o, nlohmann::json& out, Build build) {
  std::vector<double> ms;
  auto result = build();
  for (int r = 0; r < std::max(1, o.repeats) && result; ++r) {
    Stopwatch watch;
    result = build();
    ms.push_back(watch.elapsedMs());
  }
  if (!ms.empty()) out["build_ms"] = summarizeSamples(ms).median;
  return result;
}

int run(const GlobalOptions& global, const SpringsOptions& o) {
  const bool volumeFile = volume::isTetMeshPath(o.file);
  const std::string source = o.source.empty() ? (volumeFile ? "tet-edges" : "lattice") : o.source;
  const sim::SpringConfig springs{
      .stiffness = o.stiffness,
      .law = o.perRestLength ? sim::StiffnessLaw::PerRestLength : sim::StiffnessLaw::Constant};
  nlohmann::json out;
  out["file"] = o.file;
  out["source"] = source;
  if (source == "tet-edges") {
    if (!volumeFile) return fail("springs", o.file + ": tet-edges needs a volume mesh (.vtk, .vtu, .msh)");
    auto mesh = volume::loadTetMesh(o.file, {.scaleToMm = o.scale});
    if (!mesh) return fail("springs", mesh.error().message);
    auto net = timed(o, out, [&] { return sim::buildTetEdgeSprings(mesh->positions, mesh->tets, springs); });
    if (!net) return fail("springs", net.error().message);
    auto masses = sim::computeTetMasses(mesh->positions, mesh->tets, {});
    if (!masses) return fail("springs", masses.error().message);
    out["tets"] = mesh->tets.size();
    out["sim_vertices"] = mesh->positions.size();
    out["springs"] = net->size();
    out["volume_mm3"] = volume::totalVolume(*mesh);
    out["mass_g"] = std::accumulate(masses->begin(), masses->end(), 0.0);
  } else if (source == "surface" || source == "lattice") {
    if (volumeFile) return fail("springs", o.file + ": " + source + " springs need a surface mesh");
    auto surface = mesh::loadMesh(o.file, {.scaleToMm = o.scale});
    if (!surface) return fail("springs", surface.error().message);
    // Geometric vertices (merged across UV seams), as the lattice needs.
    const auto positions = mesh::geometricPositionsOf(*surface);
    const auto triangles = mesh::geometricTrianglesOf(*surface);
    out["surface_vertices"] = positions.size();
    out["surface_triangles"] = triangles.size();
    if (source == "surface") {
      auto net = timed(o, out, [&] { return sim::buildSurfaceSprings(positions, triangles, springs); });
      if (!net) return fail("springs", net.error().message);
      out["sim_vertices"] = positions.size();
      out["springs"] = net->size();
    } else {
      const sim::LatticeConfig config{
          .cellSize = o.cellSize, .cellsAlongLongestAxis = o.cells, .springs = springs};
      auto lattice = timed(o, out, [&] { return sim::buildEmbeddedLattice(positions, triangles, config); });
      if (!lattice) return fail("springs", lattice.error().message);
      out["cell_size_mm"] = lattice->cellSize;
      out["grid_cells"] = lattice->gridCells;
      out["cells"] = lattice->cells.size();
      out["inside_cells"] = lattice->insideCells;
      out["vertex_cells"] = lattice->vertexCells;
      out["filled_volume_mm3"] = lattice->filledVolume;
      out["sim_vertices"] = lattice->nodeCount();
      out["springs"] = lattice->springs.size();
      out["mass_g"] = std::accumulate(lattice->masses.begin(), lattice->masses.end(), 0.0);
    }
  } else {
    return fail("springs", "unknown --source '" + source + "'; use surface, tet-edges or lattice");
  }
  out["units"] = "mm, g, ms";
  printResult(global, out);
  return 0;
}

}  // namespace

void registerSpringsCommand(CLI::App& app, const GlobalOptions& global, int& exitCode) {
  auto opts = std::make_shared<SpringsOptions>();
  auto* cmd = app.add_subcommand(
      "springs", "build a spring network from a mesh (surface, tet-edges or lattice) and report it");
  cmd->add_option("file", opts->file, "surface mesh (OBJ, PLY, OFF, STL) or volume mesh (.vtk, .vtu, .msh)")
      ->required();
  cmd->add_option("--source", opts->source,
                  "surface | tet-edges | lattice (default: tet-edges for volumes, lattice for surfaces)");
  cmd->add_option("--cells", opts->cells, "lattice cells along the longest side (default 12)");
  cmd->add_option("--cell-size", opts->cellSize, "lattice cell size in mm (overrides --cells)");
  cmd->add_option("--scale", opts->scale, "mm per file unit (default 1)");
  cmd->add_option("--stiffness", opts->stiffness, "N/mm, or N with --per-rest-length (default 0.1)");
  cmd->add_flag("--per-rest-length", opts->perRestLength, "k_i = k / L0_i (SOFA's MeshSpringForceField)");
  cmd->add_option("--repeats", opts->repeats, "timed builds; the median is reported (default 5)");
  cmd->callback([opts, &global, &exitCode] { exitCode = run(global, *opts); });
}

}  // namespace tissue::sim_app
