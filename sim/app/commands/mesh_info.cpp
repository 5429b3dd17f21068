// tissue-sim mesh-info FILE: what a mesh file holds, after validation.
#include <algorithm>
#include <iostream>
#include <limits>

#include "command.h"
#include "output.h"
#include "tissue/mesh/load_mesh.h"

namespace tissue::sim_app {

void registerMeshInfoCommand(CLI::App& app, const GlobalOptions& global, int& exitCode) {
  struct Options {
    std::string file;
    float scale = 1.0f;
    bool strict = false;
  };
  auto opts = std::make_shared<Options>();
  auto* cmd =
      app.add_subcommand("mesh-info", "load and validate a mesh (OBJ, PLY, OFF, STL) and describe it");
  cmd->add_option("file", opts->file, "mesh file")->required();
  cmd->add_option("--scale", opts->scale, "mm per file unit (default 1)");
  cmd->add_flag("--strict", opts->strict,
                "zero-area faces and line elements are errors instead of being dropped");
  cmd->callback([opts, &global, &exitCode] {
    mesh::LoadReport report;
    auto mesh = mesh::loadMesh(
        opts->file, {.requireUvs = false, .scaleToMm = opts->scale, .strict = opts->strict}, &report);
    if (!mesh) {
      exitCode = fail("mesh-info", mesh.error().message);
      return;
    }
    Float3 lo{std::numeric_limits<float>::max(), std::numeric_limits<float>::max(),
              std::numeric_limits<float>::max()};
    Float3 hi{-lo.x, -lo.y, -lo.z};
    for (const auto& p : mesh->positions) {
      lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
      hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
    }
    nlohmann::json out;
    out["file"] = opts->file;
    out["vertices"] = mesh->geometricVertexCount;
    out["render_vertices"] = mesh->positions.size();
    out["faces"] = mesh->triangles.size();
    out["has_uvs"] = mesh->hasUvs();
    out["bbox_min"] = {lo.x, lo.y, lo.z};
    out["bbox_max"] = {hi.x, hi.y, hi.z};
    out["units"] = "mm";
    out["dropped_zero_area_faces"] = report.droppedZeroAreaFaces;
    out["dropped_line_elements"] = report.droppedLineElements;
    out["warnings"] = report.warnings;
    for (const auto& w : report.warnings)
      std::cerr << "tissue-sim mesh-info: warning: " << w << "\n";
    printResult(global, out);
  });
}

}  // namespace tissue::sim_app
