// tissue-sim indent: springs from a Young's modulus (tissue/sim/elastic_springs.h) checked on a
// block: uniaxial compression (E_eff / E) and a rigid sphere pressed in (Hertz), for the embedded
// lattice and for tets of the same grid (tissue/sim/indentation.h). Prints a table, or one JSON
// object with --json (docs/RESULTS.md, "Springs from material constants (indent)").
#include <cstdio>
#include <iostream>
#include <memory>
#include <string>

#include "command.h"
#include "output.h"
#include "tissue/core/stopwatch.h"
#include "tissue/sim/indentation.h"

namespace tissue::sim_app {
namespace {

struct IndentOptions {
  double youngsModulusKpa = 5.0;
  double poissonRatio = sim::kEffectivePoissonRatio;
  double radiusMm = 10.0;
  std::string network = "both";
  int cells = 20;
  int cellsPerRadius = 8;
  std::string tetFormula = "lloyd-isotropic-projection";
  std::string latticeBoundary = "per-cell";
};

std::string networkName(sim::ElasticNetwork n) {
  return n == sim::ElasticNetwork::Lattice ? "lattice" : "tets";
}

int runIndent(const IndentOptions& o, const GlobalOptions& global) {
  const sim::ElasticMaterial material{.youngsModulusKpa = o.youngsModulusKpa, .poissonRatio = o.poissonRatio};
  if (auto ok = sim::validateMaterial(material); !ok) {
    // "youngs_modulus_kpa: ..." -> "--youngs-modulus-kpa: ...", the option's name.
    std::string message = ok.error().message;
    for (std::size_t c = 0; c < message.find(':'); ++c)
      if (message[c] == '_') message[c] = '-';
    return fail("indent", "--" + message);
  }
  if (!(o.radiusMm > 0.0) || !std::isfinite(o.radiusMm))
    return fail("indent", "--radius-mm: expected a positive sphere radius in mm");
  if (o.cells < 4 || o.cells > 40)
    return fail("indent", "--cells: expected 4 to 40 cells along each side of the quarter block");
  if (o.cellsPerRadius < 2 || o.cellsPerRadius > o.cells)
    return fail("indent", "--cells-per-radius: expected 2 to --cells lattice cells per sphere radius");
  if (o.network != "both" && o.network != "lattice" && o.network != "tets")
    return fail("indent", "--network: expected lattice, tets or both, got " + o.network);
  sim::TetStiffnessFormula formula = sim::TetStiffnessFormula::LloydIsotropicProjection;
  if (o.tetFormula == "lloyd")
    formula = sim::TetStiffnessFormula::Lloyd2007;
  else if (o.tetFormula == "van-gelder")
    formula = sim::TetStiffnessFormula::VanGelder1998;
  else if (o.tetFormula != "lloyd-isotropic-projection")
    return fail("indent", "--tet-formula: expected lloyd-isotropic-projection, lloyd or van-gelder, got " +
                              o.tetFormula);
  if (o.latticeBoundary != "per-cell" && o.latticeBoundary != "interior")
    return fail("indent", "--lattice-boundary: expected per-cell or interior, got " + o.latticeBoundary);
  const auto boundary =
      o.latticeBoundary == "per-cell" ? sim::LatticeBoundary::PerCell : sim::LatticeBoundary::InteriorValue;
  if (o.poissonRatio != sim::kEffectivePoissonRatio)
    std::cerr << "tissue-sim indent: warning: --poisson-ratio " << o.poissonRatio
              << " is not the networks' effective 0.25 (central springs); Hertz uses 0.25\n";

  std::vector<sim::ElasticNetwork> networks;
  if (o.network != "tets") networks.push_back(sim::ElasticNetwork::Lattice);
  if (o.network != "lattice") networks.push_back(sim::ElasticNetwork::Tets);
  const double h = o.radiusMm / o.cellsPerRadius;
  Stopwatch clock;
  nlohmann::json result{{"youngs_modulus_kpa", o.youngsModulusKpa},
                        {"poisson_ratio", sim::kEffectivePoissonRatio},
                        {"configured_poisson_ratio", o.poissonRatio},
                        {"sphere_radius_mm", o.radiusMm},
                        {"cell_size_mm", h},
                        {"quarter_block_cells", o.cells},
                        {"tet_formula", o.tetFormula},
                        {"lattice_boundary", o.latticeBoundary}};
  result["results"] = nlohmann::json::array();
  std::string table = "network  depth_mm  force_N      hertz_N      ratio  contact_nodes\n";
  for (sim::ElasticNetwork network : networks) {
    const sim::ElasticBlockConfig block{.network = network,
                                        .cells = {o.cells, o.cells, o.cells},
                                        .cellSizeMm = h,
                                        .material = material,
                                        .latticeBoundary = boundary,
                                        .tetFormula = formula};
    sim::ElasticBlockConfig cube = block;
    cube.cells = {8, 8, 8};
    auto uniaxial = sim::measureUniaxial(cube);
    if (!uniaxial) return fail("indent", uniaxial.error().message);
    const std::string name = networkName(network);
    if (!result.contains("uniaxial_modulus_ratio")) result["uniaxial_modulus_ratio"] = uniaxial->modulusRatio;
    result["uniaxial_modulus_ratio_" + name] = uniaxial->modulusRatio;
    result["uniaxial_poisson_ratio_" + name] = uniaxial->poissonRatio;
    auto points = sim::indentSphere({.block = block, .sphereRadiusMm = o.radiusMm});
    if (!points) return fail("indent", points.error().message);
    for (const sim::IndentationPoint& p : *points) {
      result["results"].push_back({{"network", name},
                                   {"depth_mm", p.depthMm},
                                   {"force_N", p.forceN},
                                   {"hertz_N", p.hertzN},
                                   {"ratio", p.forceN / p.hertzN},
                                   {"contact_nodes", p.contactNodes},
                                   {"contact_radius_mm", p.contactRadiusMm}});
      char line[160];
      std::snprintf(line, sizeof line, "%-8s %8.3f  %.5e  %.5e  %5.3f  %d\n", name.c_str(), p.depthMm,
                    p.forceN, p.hertzN, p.forceN / p.hertzN, p.contactNodes);
      table += line;
    }
  }
  result["ms"] = clock.elapsedMs();
  if (global.json) {
    printResult(global, result);
    return 0;
  }
  std::cout << table;
  nlohmann::json summary = result;
  summary.erase("results");
  printResult(global, summary);
  return 0;
}

}  // namespace

void registerIndentCommand(CLI::App& app, const GlobalOptions& global, int& exitCode) {
  auto o = std::make_shared<IndentOptions>();
  auto* cmd = app.add_subcommand(
      "indent",
      "springs from E (kPa): uniaxial modulus and Hertz sphere indentation of lattice and tet blocks");
  cmd->add_option("--youngs-modulus-kpa", o->youngsModulusKpa, "Young's modulus E in kPa (default 5)");
  cmd->add_option(
      "--poisson-ratio", o->poissonRatio,
      "configured Poisson's ratio in (0, 0.5), reported; the springs realise 0.25 (default 0.25)");
  cmd->add_option("--radius-mm", o->radiusMm, "sphere radius R in mm (default 10); depths 0.05 to 0.2 R");
  cmd->add_option("--network", o->network, "lattice, tets or both (default both)");
  cmd->add_option("--cells", o->cells, "cells along each side of the quarter block (default 20)");
  cmd->add_option("--cells-per-radius", o->cellsPerRadius, "cells per sphere radius (default 8)");
  cmd->add_option("--tet-formula", o->tetFormula,
                  "lloyd-isotropic-projection (default), lloyd (Lloyd et al. 2007) or van-gelder (1998)");
  cmd->add_option("--lattice-boundary", o->latticeBoundary,
                  "per-cell (default: boundary springs scaled by their cells) or interior");
  cmd->callback([o, &global, &exitCode] { exitCode = runIndent(*o, global); });
}

}  // namespace tissue::sim_app
