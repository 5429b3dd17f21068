// The project's data folders for the scene module's organ layer (organ_data.h).
#include "organ_data.h"

#include "output.h"

namespace tissue::sim_app {

scene::MaterialFileOptions dataMaterialOptions() {
  scene::MaterialFileOptions options;
  options.textureRoots = {generatedDataDir(), dataDir()};  // the build's 1024^2 textures win
  return options;
}

std::filesystem::path materialFileFor(const std::filesystem::path& meshFile) {
  return dataDir() / "materials" / (meshFile.stem().string() + ".json");
}

Result<scene::MaterialFile> readDataMaterial(const std::filesystem::path& file) {
  return scene::readMaterialFile(file, dataMaterialOptions());
}

Result<optics::ScatteringMaterial> loadDataMaterial(const std::string& name) {
  auto material = readDataMaterial(dataDir() / "materials" / (name + ".json"));
  if (!material) return material.error();
  return scene::opticalMaterial(*material);
}

scene::OrganSource organSourceFor(const std::filesystem::path& meshFile, float scaleToMm) {
  scene::OrganSource source;
  source.mesh = meshFile;
  source.material = materialFileFor(meshFile);
  source.meshScaleToMm = scaleToMm;
  source.materialOptions = dataMaterialOptions();
  return source;
}

}  // namespace tissue::sim_app
