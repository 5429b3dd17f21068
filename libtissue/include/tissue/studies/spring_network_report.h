#pragma once
/// \file
/// `tissue-sim springs`: a spring network built from a mesh file (surface springs, tet edges or
/// an embedded lattice), its size, mass and build time (the median of repeated builds, loading
/// excluded). Lengths in mm, masses in g, times in ms.

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "tissue/core/result.h"
#include "tissue/sim/lattice.h"
#include "tissue/sim/spring_network.h"

namespace tissue::studies {

enum class SpringSource { Surface, TetEdges, Lattice };

/// "surface", "tet-edges" or "lattice".
std::string_view springSourceName(SpringSource source);
std::optional<SpringSource> parseSpringSource(std::string_view name);

struct SpringNetworkConfig {
  std::optional<SpringSource> source;  ///< none: tet-edges for a volume mesh, lattice for a surface
  float scaleToMm = 1.0f;              ///< mm per file unit
  sim::SpringConfig springs{};
  double latticeCellSizeMm = 0.0;  ///< 0: latticeCells along the longest side
  int latticeCells = 12;
  int repeats = 5;  ///< timed builds after an untimed one
};

struct SpringNetworkSummary {
  SpringSource source = SpringSource::Lattice;
  double buildMs = 0.0;  ///< ms, median of the timed builds
  std::size_t simVertices = 0, springs = 0;
  std::optional<double> massG;                            ///< g: tet edges and lattice
  std::size_t tets = 0;                                   ///< tet edges
  double volumeMm3 = 0.0;                                 ///< tet edges: the tets' volume
  std::size_t surfaceVertices = 0, surfaceTriangles = 0;  ///< surface and lattice (geometric vertices)
  std::optional<sim::EmbeddedLattice> lattice;            ///< lattice
};

/// Loads `file` (a surface: OBJ, PLY, OFF, STL; a volume: .vtk, .vtu, .msh) and builds its network.
Result<SpringNetworkSummary> buildSpringNetworkSummary(const std::filesystem::path& file,
                                                       const SpringNetworkConfig& config);

/// As JSON text: source, build_ms, sim_vertices, springs; tet edges: tets, volume_mm3, mass_g;
/// surface and lattice: surface_vertices, surface_triangles; lattice: cell_size_mm, grid_cells,
/// cells, inside_cells, vertex_cells, filled_volume_mm3, mass_g; units.
std::string springNetworkJson(const SpringNetworkSummary& summary);

}  // namespace tissue::studies
