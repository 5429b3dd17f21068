// Fuzz target: the surface-mesh loader (tissue::mesh::loadMesh) for the extension
// TISSUE_FUZZ_EXTENSION (.obj, .ply, .off, .stl; one executable each). Every input loads or is
// refused in one line naming the file.
#include "fuzz_input.h"
#include "tissue/mesh/load_mesh.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto file = tissue::fuzz::inputFile(data, size, TISSUE_FUZZ_EXTENSION);
  tissue::mesh::LoadReport report;
  auto mesh = tissue::mesh::loadMesh(file, {}, &report);
  if (!mesh) tissue::fuzz::checkRefusal(mesh.error().message, file);
  return 0;
}
