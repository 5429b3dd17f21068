// Fuzz target: the tetrahedral-mesh loader (tissue::volume::loadTetMesh) for the extension
// TISSUE_FUZZ_EXTENSION (.vtk legacy, .vtu XML, .msh Gmsh; one executable each).
#include "fuzz_input.h"
#include "tissue/volume/tet_mesh.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto file = tissue::fuzz::inputFile(data, size, TISSUE_FUZZ_EXTENSION);
  tissue::volume::TetLoadReport report;
  auto mesh = tissue::volume::loadTetMesh(file, {}, &report);
  if (!mesh) tissue::fuzz::checkRefusal(mesh.error().message, file);
  return 0;
}
