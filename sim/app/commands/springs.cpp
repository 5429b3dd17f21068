// tissue-sim springs FILE: builds a spring network from a mesh (surface springs, tet edges or an
// embedded lattice) and reports its size, masses and build time
// (tissue/studies/spring_network_report.h).
#include "command.h"
#include "output.h"
#include "tissue/studies/spring_network_report.h"

namespace tissue::sim_app {

void registerSpringsCommand(CLI::App& app, const GlobalOptions& global, int& exitCode) {
  struct Options {
    std::string file;
    std::string source;
    bool perRestLength = false;
    studies::SpringNetworkConfig config;
  };
  auto o = std::make_shared<Options>();
  auto& c = o->config;
  auto* cmd = app.add_subcommand(
      "springs", "build a spring network from a mesh (surface, tet-edges or lattice) and report it");
  cmd->add_option("file", o->file, "surface mesh (OBJ, PLY, OFF, STL) or volume mesh (.vtk, .vtu, .msh)")
      ->required();
  cmd->add_option("--source", o->source,
                  "surface | tet-edges | lattice (default: tet-edges for volumes, lattice for surfaces)");
  cmd->add_option("--cells", c.latticeCells, "lattice cells along the longest side (default 12)");
  cmd->add_option("--cell-size", c.latticeCellSizeMm, "lattice cell size in mm (overrides --cells)");
  cmd->add_option("--scale", c.scaleToMm, "mm per file unit (default 1)");
  cmd->add_option("--stiffness", c.springs.stiffness, "N/mm, or N with --per-rest-length (default 0.1)");
  cmd->add_flag("--per-rest-length", o->perRestLength, "k_i = k / L0_i (SOFA's MeshSpringForceField)");
  cmd->add_option("--repeats", c.repeats, "timed builds; the median is reported (default 5)");
  cmd->callback([o, &global, &exitCode] {
    auto& config = o->config;
    if (!o->source.empty() && !(config.source = studies::parseSpringSource(o->source))) {
      exitCode = fail("springs", "unknown --source '" + o->source + "'; use surface, tet-edges or lattice");
      return;
    }
    if (o->perRestLength) config.springs.law = sim::StiffnessLaw::PerRestLength;
    auto summary = studies::buildSpringNetworkSummary(o->file, config);
    if (!summary) {
      exitCode = fail("springs", summary.error().message);
      return;
    }
    auto out = nlohmann::json::parse(studies::springNetworkJson(*summary));
    out["file"] = o->file;
    printResult(global, out);
  });
}

}  // namespace tissue::sim_app
