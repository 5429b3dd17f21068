// tissue-sim's lookup of the project's optical materials.
#include "sss_material.h"

#include "output.h"

namespace tissue::sim_app {

Result<optics::ScatteringMaterial> loadDataMaterial(const std::string& name) {
  return optics::loadTissueMaterial(dataDir() / "materials" / (name + ".json"));
}

}  // namespace tissue::sim_app
