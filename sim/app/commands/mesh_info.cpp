// tissue-sim mesh-info FILE: what a mesh file holds, after validation: a surface (OBJ, PLY, OFF,
// STL) or a tetrahedral volume (.vtk, .vtu, .msh).
#include <algorithm>
#include <iostream>
#include <limits>

#include "command.h"
#include "output.h"
#include "tissue/core/vec_math.h"
#include "tissue/mesh/load_mesh.h"
#include "tissue/volume/tet_mesh.h"

namespace tissue::sim_app {
namespace {

/// Describes a tetrahedral volume mesh: vertices, tets, total volume (mm^3), bounding box (mm).
int describeVolume(const GlobalOptions& global, const std::string& file, float scale) {
  volume::TetLoadReport report;
  auto mesh = volume::loadTetMesh(file, {.scaleToMm = scale}, &report);
  if (!mesh) return fail("mesh-info", mesh.error().message);
  const Bounds3 box = boundsOf(mesh->positions);
  const Float3 lo = box.lo, hi = box.hi;
  nlohmann::json out;
  out["file"] = file;
  out["kind"] = "tetrahedral volume";
  out["vertices"] = mesh->positions.size();
  out["tets"] = mesh->tets.size();
  out["volume_mm3"] = volume::totalVolume(*mesh);
  out["boundary_triangles"] = volume::boundaryTriangles(*mesh).size();
  out["bbox_min"] = {lo.x, lo.y, lo.z};
  out["bbox_max"] = {hi.x, hi.y, hi.z};
  out["units"] = "mm";
  out["ignored_cells"] = report.ignoredCells;
  out["reoriented_tets"] = report.reorientedTets;
  out["unreferenced_vertices"] = report.unreferencedVertices;
  out["warnings"] = report.warnings;
  for (const auto& w : report.warnings)
    std::cerr << "tissue-sim mesh-info: warning: " << w << "\n";
  printResult(global, out);
  return 0;
}

}  // namespace

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
    if (volume::isTetMeshPath(opts->file)) {
      exitCode = describeVolume(global, opts->file, opts->scale);
      return;
    }
    mesh::LoadReport report;
    auto mesh = mesh::loadMesh(
        opts->file, {.requireUvs = false, .scaleToMm = opts->scale, .strict = opts->strict}, &report);
    if (!mesh) {
      exitCode = fail("mesh-info", mesh.error().message);
      return;
    }
    const Bounds3 box = boundsOf(mesh->positions);
    const Float3 lo = box.lo, hi = box.hi;
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
