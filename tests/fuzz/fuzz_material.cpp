// Fuzz target: material files (tissue::scene::readMaterialFile, the one reader of
// data/materials/*.json), their layer stack and optical material.
#include "fuzz_input.h"
#include "tissue/scene/material_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto file = tissue::fuzz::inputFile(data, size, ".json");
  auto material = tissue::scene::readMaterialFile(file, {.textureRoots = {file.parent_path()}});
  if (!material) {
    tissue::fuzz::checkRefusal(material.error().message, file);
    return 0;
  }
  (void)tissue::scene::opticalMaterial(*material);
  return 0;
}
