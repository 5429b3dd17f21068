// What a mesh file holds (mesh_description.h).
#include "tissue/studies/mesh_description.h"

#include <nlohmann/json.hpp>

#include "tissue/core/vec_math.h"
#include "tissue/mesh/load_mesh.h"
#include "tissue/volume/tet_mesh.h"

namespace tissue::studies {
namespace {

nlohmann::json boxJson(std::span<const Float3> positions) {
  const Bounds3 box = boundsOf(positions);
  return {{"bbox_min", {box.lo.x, box.lo.y, box.lo.z}}, {"bbox_max", {box.hi.x, box.hi.y, box.hi.z}}};
}

Result<MeshDescription> describeVolume(const std::filesystem::path& file, float scale) {
  volume::TetLoadReport report;
  auto mesh = volume::loadTetMesh(file, {.scaleToMm = scale}, &report);
  if (!mesh) return mesh.error();
  nlohmann::json out = boxJson(mesh->positions);
  out.update({{"kind", "tetrahedral volume"},
              {"vertices", mesh->positions.size()},
              {"tets", mesh->tets.size()},
              {"volume_mm3", volume::totalVolume(*mesh)},
              {"boundary_triangles", volume::boundaryTriangles(*mesh).size()},
              {"units", "mm"},
              {"ignored_cells", report.ignoredCells},
              {"reoriented_tets", report.reorientedTets},
              {"unreferenced_vertices", report.unreferencedVertices},
              {"warnings", report.warnings}});
  return MeshDescription{.json = out.dump(), .warnings = report.warnings};
}

}  // namespace

Result<MeshDescription> describeMeshFile(const std::filesystem::path& file,
                                         const MeshDescriptionOptions& options) {
  if (volume::isTetMeshPath(file)) return describeVolume(file, options.scaleToMm);
  mesh::LoadReport report;
  auto mesh = mesh::loadMesh(
      file, {.requireUvs = false, .scaleToMm = options.scaleToMm, .strict = options.strict}, &report);
  if (!mesh) return mesh.error();
  nlohmann::json out = boxJson(mesh->positions);
  out.update({{"vertices", mesh->geometricVertexCount},
              {"render_vertices", mesh->positions.size()},
              {"faces", mesh->triangles.size()},
              {"has_uvs", mesh->hasUvs()},
              {"units", "mm"},
              {"dropped_zero_area_faces", report.droppedZeroAreaFaces},
              {"dropped_line_elements", report.droppedLineElements},
              {"warnings", report.warnings}});
  return MeshDescription{.json = out.dump(), .warnings = report.warnings};
}

}  // namespace tissue::studies
