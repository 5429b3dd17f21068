// The volume module built without VTK (TISSUE_WITH_VTK=OFF): the .vtk/.vtu readers are not
// compiled in, and asking for them is one Error that names the file and the way out. Gmsh .msh
// files are read by hand (gmsh_reader.cpp) and need no VTK.
#include <string>

#include "raw_volume.h"

namespace tissue::volume::detail {
namespace {

Error builtWithoutVtk(const std::filesystem::path& path) {
  return Error{path.string() +
               ": built without VTK (TISSUE_WITH_VTK=OFF); convert to Gmsh .msh (e.g. `meshio convert " +
               path.filename().string() + " mesh.msh`) or rebuild with VTK"};
}

}  // namespace

Result<RawVolume> readLegacyVtk(const std::filesystem::path& path) {
  return builtWithoutVtk(path);
}

Result<RawVolume> readVtu(const std::filesystem::path& path) {
  return builtWithoutVtk(path);
}

Result<VtkSurface> readVtkPolyData(const std::filesystem::path& path, bool) {
  return Error{path.string() +
               ": built without VTK (TISSUE_WITH_VTK=OFF); convert the surface to .ply or .obj (e.g. `meshio "
               "convert " +
               path.filename().string() + " mesh.ply`) or rebuild with VTK"};
}

}  // namespace tissue::volume::detail
