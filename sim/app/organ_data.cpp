// The project's data folders for the scene module's organ layer (organ_data.h).
#include "organ_data.h"

#include "gl_environment.h"
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

scene::OrganSource organSourceFor(const std::filesystem::path& meshFile, float scaleToMm) {
  return {.mesh = meshFile,
          .material = materialFileFor(meshFile),
          .meshScaleToMm = scaleToMm,
          .materialOptions = dataMaterialOptions()};
}

scene::OrganSource dataOrganNamed(const std::string& name) {
  return organSourceFor(dataDir() / "meshes" / (name + ".obj"));
}

scene::SceneSettings dataSceneSettings() {
  scene::SceneSettings settings;
  settings.materials = dataMaterialOptions();
  settings.materialsDir = dataDir() / "materials";
  settings.sharedMeshesDir = sharedDir() / "meshes";
  settings.renderer.shaders = shaderSettingsFromEnvironment();
  settings.context.eglPlatform = eglPlatformFromEnvironment();
  settings.headless.backend = glContextFromEnvironment();
  return settings;
}

}  // namespace tissue::sim_app
