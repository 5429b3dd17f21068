// Springs from a Young's modulus checked on a block (indent_study.h).
#include "tissue/studies/indent_study.h"

#include <array>
#include <cstdio>

#include "json_text.h"
#include "tissue/core/stopwatch.h"

namespace tissue::studies {
namespace {

constexpr std::array<std::pair<std::string_view, sim::TetStiffnessFormula>, 3> kTetFormulas = {
    {{"lloyd-isotropic-projection", sim::TetStiffnessFormula::LloydIsotropicProjection},
     {"lloyd", sim::TetStiffnessFormula::Lloyd2007},
     {"van-gelder", sim::TetStiffnessFormula::VanGelder1998}}};
constexpr std::array<std::pair<std::string_view, sim::LatticeBoundary>, 2> kBoundaries = {
    {{"per-cell", sim::LatticeBoundary::PerCell}, {"interior", sim::LatticeBoundary::InteriorValue}}};

template <class Table, class Value>
std::string_view nameOf(const Table& table, Value value) {
  for (const auto& [name, v] : table)
    if (v == value) return name;
  return "?";
}
template <class Table>
auto parse(const Table& table, std::string_view name)
    -> std::optional<typename Table::value_type::second_type> {
  for (const auto& [n, v] : table)
    if (n == name) return v;
  return std::nullopt;
}

}  // namespace

std::string_view tetFormulaName(sim::TetStiffnessFormula formula) {
  return nameOf(kTetFormulas, formula);
}
std::optional<sim::TetStiffnessFormula> parseTetFormula(std::string_view name) {
  return parse(kTetFormulas, name);
}
std::string_view latticeBoundaryName(sim::LatticeBoundary boundary) {
  return nameOf(kBoundaries, boundary);
}
std::optional<sim::LatticeBoundary> parseLatticeBoundary(std::string_view name) {
  return parse(kBoundaries, name);
}
std::string_view networkName(sim::ElasticNetwork network) {
  return network == sim::ElasticNetwork::Lattice ? "lattice" : "tets";
}

Result<IndentStudy> runIndentStudy(const IndentStudyConfig& config) {
  if (config.cellsPerRadius < 1) return Error{"cells per sphere radius must be >= 1"};
  IndentStudy study{.config = config, .cellSizeMm = config.sphereRadiusMm / config.cellsPerRadius};
  Stopwatch clock;
  for (sim::ElasticNetwork network : config.networks) {
    const sim::ElasticBlockConfig block{.network = network,
                                        .cells = {config.cells, config.cells, config.cells},
                                        .cellSizeMm = study.cellSizeMm,
                                        .material = config.material,
                                        .latticeBoundary = config.latticeBoundary,
                                        .tetFormula = config.tetFormula};
    sim::ElasticBlockConfig cube = block;
    cube.cells = {8, 8, 8};
    auto uniaxial = sim::measureUniaxial(cube);
    if (!uniaxial) return uniaxial.error();
    auto points = sim::indentSphere({.block = block, .sphereRadiusMm = config.sphereRadiusMm});
    if (!points) return points.error();
    study.networks.push_back({network, *uniaxial, std::move(*points)});
  }
  study.ms = clock.elapsedMs();
  return study;
}

std::string indentStudyJson(const IndentStudy& s) {
  const auto& c = s.config;
  nlohmann::json out{{"youngs_modulus_kpa", c.material.youngsModulusKpa},
                     {"poisson_ratio", sim::kEffectivePoissonRatio},
                     {"configured_poisson_ratio", c.material.poissonRatio},
                     {"sphere_radius_mm", c.sphereRadiusMm},
                     {"cell_size_mm", s.cellSizeMm},
                     {"quarter_block_cells", c.cells},
                     {"tet_formula", tetFormulaName(c.tetFormula)},
                     {"lattice_boundary", latticeBoundaryName(c.latticeBoundary)},
                     {"results", nlohmann::json::array()},
                     {"ms", s.ms}};
  for (const auto& n : s.networks) {
    const std::string name(networkName(n.network));
    if (!out.contains("uniaxial_modulus_ratio")) out["uniaxial_modulus_ratio"] = n.uniaxial.modulusRatio;
    out["uniaxial_modulus_ratio_" + name] = n.uniaxial.modulusRatio;
    out["uniaxial_poisson_ratio_" + name] = n.uniaxial.poissonRatio;
    for (const auto& p : n.points)
      out["results"].push_back({{"network", name},
                                {"depth_mm", p.depthMm},
                                {"force_N", p.forceN},
                                {"hertz_N", p.hertzN},
                                {"ratio", p.forceN / p.hertzN},
                                {"contact_nodes", p.contactNodes},
                                {"contact_radius_mm", p.contactRadiusMm}});
  }
  return detail::jsonText(out);
}

std::string indentStudyText(const IndentStudy& s) {
  std::string table = "network  depth_mm  force_N      hertz_N      ratio  contact_nodes\n";
  for (const auto& n : s.networks)
    for (const auto& p : n.points) {
      char line[160];
      std::snprintf(line, sizeof line, "%-8s %8.3f  %.5e  %.5e  %5.3f  %d\n",
                    std::string(networkName(n.network)).c_str(), p.depthMm, p.forceN, p.hertzN,
                    p.forceN / p.hertzN, p.contactNodes);
      table += line;
    }
  return table;
}

}  // namespace tissue::studies
