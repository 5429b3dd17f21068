#pragma once
/// \file
/// `tissue-sim indent`: springs from a Young's modulus (tissue/sim/elastic_springs.h) checked on a
/// block, for the embedded lattice and for tets of the same grid: uniaxial compression (E_eff / E)
/// and a rigid sphere pressed in against Hertz (tissue/sim/indentation.h). Moduli in kPa,
/// lengths in mm, forces in N.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "tissue/core/result.h"
#include "tissue/sim/indentation.h"

namespace tissue::studies {

/// "lloyd-isotropic-projection", "lloyd" (Lloyd et al. 2007) or "van-gelder" (1998).
std::string_view tetFormulaName(sim::TetStiffnessFormula formula);
std::optional<sim::TetStiffnessFormula> parseTetFormula(std::string_view name);
/// "per-cell" or "interior".
std::string_view latticeBoundaryName(sim::LatticeBoundary boundary);
std::optional<sim::LatticeBoundary> parseLatticeBoundary(std::string_view name);
/// "lattice" or "tets".
std::string_view networkName(sim::ElasticNetwork network);

struct IndentStudyConfig {
  sim::ElasticMaterial material{};
  double sphereRadiusMm = 10.0;  ///< R, mm; depths 0.05 to 0.2 R
  int cells = 20;                ///< cells along each side of the quarter block
  int cellsPerRadius = 8;        ///< cells per sphere radius (the cell size: R / this)
  std::vector<sim::ElasticNetwork> networks{sim::ElasticNetwork::Lattice, sim::ElasticNetwork::Tets};
  sim::LatticeBoundary latticeBoundary = sim::LatticeBoundary::PerCell;
  sim::TetStiffnessFormula tetFormula = sim::TetStiffnessFormula::LloydIsotropicProjection;
};

struct IndentNetworkResult {
  sim::ElasticNetwork network{};
  sim::UniaxialResult uniaxial;  ///< on an 8^3-cell cube of the same cells
  std::vector<sim::IndentationPoint> points;
};

struct IndentStudy {
  IndentStudyConfig config;
  double cellSizeMm = 0.0;  ///< mm
  std::vector<IndentNetworkResult> networks{};
  double ms = 0.0;  ///< ms, wall time of the study
};

Result<IndentStudy> runIndentStudy(const IndentStudyConfig& config);

/// As JSON text: youngs_modulus_kpa, poisson_ratio (the networks' 0.25), configured_poisson_ratio,
/// sphere_radius_mm, cell_size_mm, quarter_block_cells, tet_formula, lattice_boundary,
/// uniaxial_modulus_ratio (the first network's), uniaxial_modulus_ratio_NET,
/// uniaxial_poisson_ratio_NET, results (network, depth_mm, force_N, hertz_N, ratio,
/// contact_nodes, contact_radius_mm) and ms.
std::string indentStudyJson(const IndentStudy& study);
/// The indentation points as a text table (network, depth, force, Hertz, ratio, contact nodes).
std::string indentStudyText(const IndentStudy& study);

}  // namespace tissue::studies
