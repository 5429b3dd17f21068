// tissue-sim indent: springs from a Young's modulus (tissue/sim/elastic_springs.h) checked on a
// block: uniaxial compression (E_eff / E) and a rigid sphere pressed in (Hertz), for the embedded
// lattice and for tets of the same grid (tissue/studies/indent_study.h). Prints a table, or one
// JSON object with --json (docs/RESULTS.md, "Springs from material constants (indent)").
#include <cmath>
#include <iostream>
#include <memory>
#include <string>

#include "command.h"
#include "output.h"
#include "tissue/studies/indent_study.h"

namespace tissue::sim_app {
namespace {

struct IndentOptions {
  studies::IndentStudyConfig config;
  std::string network = "both";
  std::string tetFormula = "lloyd-isotropic-projection";
  std::string latticeBoundary = "per-cell";
};

int runIndent(IndentOptions o, const GlobalOptions& global) {
  auto& c = o.config;
  if (auto ok = sim::validateMaterial(c.material); !ok) {
    // "youngs_modulus_kpa: ..." -> "--youngs-modulus-kpa: ...", the option's name.
    std::string message = ok.error().message;
    for (std::size_t i = 0; i < message.find(':'); ++i)
      if (message[i] == '_') message[i] = '-';
    return fail("indent", "--" + message);
  }
  if (!(c.sphereRadiusMm > 0.0) || !std::isfinite(c.sphereRadiusMm))
    return fail("indent", "--radius-mm: expected a positive sphere radius in mm");
  if (c.cells < 4 || c.cells > 40)
    return fail("indent", "--cells: expected 4 to 40 cells along each side of the quarter block");
  if (c.cellsPerRadius < 2 || c.cellsPerRadius > c.cells)
    return fail("indent", "--cells-per-radius: expected 2 to --cells lattice cells per sphere radius");
  if (o.network != "both" && o.network != "lattice" && o.network != "tets")
    return fail("indent", "--network: expected lattice, tets or both, got " + o.network);
  if (o.network != "both")
    c.networks = {o.network == "tets" ? sim::ElasticNetwork::Tets : sim::ElasticNetwork::Lattice};
  const auto formula = studies::parseTetFormula(o.tetFormula);
  if (!formula)
    return fail("indent", "--tet-formula: expected lloyd-isotropic-projection, lloyd or van-gelder, got " +
                              o.tetFormula);
  const auto boundary = studies::parseLatticeBoundary(o.latticeBoundary);
  if (!boundary)
    return fail("indent", "--lattice-boundary: expected per-cell or interior, got " + o.latticeBoundary);
  c.tetFormula = *formula;
  c.latticeBoundary = *boundary;
  if (c.material.poissonRatio != sim::kEffectivePoissonRatio)
    std::cerr << "tissue-sim indent: warning: --poisson-ratio " << c.material.poissonRatio
              << " is not the networks' effective 0.25 (central springs); Hertz uses 0.25\n";
  auto study = studies::runIndentStudy(c);
  if (!study) return fail("indent", study.error().message);
  if (global.json) {
    printJsonText(global, studies::indentStudyJson(*study));
    return 0;
  }
  std::cout << studies::indentStudyText(*study);
  auto summary = nlohmann::json::parse(studies::indentStudyJson(*study));
  summary.erase("results");
  printResult(global, summary);
  return 0;
}

}  // namespace

void registerIndentCommand(CLI::App& app, const GlobalOptions& global, int& exitCode) {
  auto o = std::make_shared<IndentOptions>();
  auto& c = o->config;
  auto* cmd = app.add_subcommand(
      "indent",
      "springs from E (kPa): uniaxial modulus and Hertz sphere indentation of lattice and tet blocks");
  cmd->add_option("--youngs-modulus-kpa", c.material.youngsModulusKpa,
                  "Young's modulus E in kPa (default 5)");
  cmd->add_option(
      "--poisson-ratio", c.material.poissonRatio,
      "configured Poisson's ratio in (0, 0.5), reported; the springs realise 0.25 (default 0.25)");
  cmd->add_option("--radius-mm", c.sphereRadiusMm,
                  "sphere radius R in mm (default 10); depths 0.05 to 0.2 R");
  cmd->add_option("--network", o->network, "lattice, tets or both (default both)");
  cmd->add_option("--cells", c.cells, "cells along each side of the quarter block (default 20)");
  cmd->add_option("--cells-per-radius", c.cellsPerRadius, "cells per sphere radius (default 8)");
  cmd->add_option("--tet-formula", o->tetFormula,
                  "lloyd-isotropic-projection (default), lloyd (Lloyd et al. 2007) or van-gelder (1998)");
  cmd->add_option("--lattice-boundary", o->latticeBoundary,
                  "per-cell (default: boundary springs scaled by their cells) or interior");
  cmd->callback([o, &global, &exitCode] { exitCode = runIndent(*o, global); });
}

}  // namespace tissue::sim_app
