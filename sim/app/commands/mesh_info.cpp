// tissue-sim mesh-info FILE: what a mesh file holds, after validation: a surface (OBJ, PLY, OFF,
// STL) or a tetrahedral volume (.vtk, .vtu, .msh) (tissue/studies/mesh_description.h).
#include <iostream>

#include "command.h"
#include "output.h"
#include "tissue/studies/mesh_description.h"

namespace tissue::sim_app {

void registerMeshInfoCommand(CLI::App& app, const GlobalOptions& global, int& exitCode) {
  struct Options {
    std::string file;
    float scale = 1.0f;
    bool strict = false;
  };
  auto opts = std::make_shared<Options>();
  auto* cmd = app.add_subcommand(
      "mesh-info",
      "load and validate a mesh (OBJ, PLY, OFF, STL, or a tet volume: .vtk, .vtu, .msh) and describe it");
  cmd->add_option("file", opts->file, "mesh file")->required();
  cmd->add_option("--scale", opts->scale, "mm per file unit (default 1)");
  cmd->add_flag("--strict", opts->strict,
                "refuse what lenient mode repairs or drops (misoriented faces, non-manifold edges, bow-tie "
                "and unused vertices, zero-area faces, line elements)");
  cmd->callback([opts, &global, &exitCode] {
    auto described =
        studies::describeMeshFile(opts->file, {.scaleToMm = opts->scale, .strict = opts->strict});
    if (!described) return void(exitCode = fail("mesh-info", described.error().message));
    for (const auto& w : described->warnings)
      std::cerr << "tissue-sim mesh-info: warning: " << w << "\n";
    auto out = nlohmann::json::parse(described->json);
    out["file"] = opts->file;
    printResult(global, out);
  });
}

}  // namespace tissue::sim_app
