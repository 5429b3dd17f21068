#pragma once
/// \file
/// tissue-sim's view of the method materials (tissue/materials/method_materials.h), plus the
/// project's data/materials/ lookup.

#include <string>

#include "tissue/materials/method_materials.h"

namespace tissue::sim_app {

using materials::makeSeparableMaterial;
using materials::makeTextureSpaceSettings;
using materials::SeparableMaterial;

/// The first layer of data/materials/<name>.json as an optical material.
Result<optics::ScatteringMaterial> loadDataMaterial(const std::string& name);

}  // namespace tissue::sim_app
