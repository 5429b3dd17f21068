#pragma once
/// \file
/// Looking up a scattering material by name for the optics commands (profile, kernel,
/// kernel-report): Jensen 2001's table in shared/reference, then data/materials/*.json.

#include <string>

#include "tissue/core/result.h"
#include "tissue/optics/materials.h"

namespace tissue::sim_app {

/// `name` (case-insensitive) from Jensen's table (shared/reference/jensen2001_materials.tsv), else
/// data/materials/NAME.json by stem. The error lists the known names.
Result<optics::ScatteringMaterial> findNamedMaterial(const std::string& name);

}  // namespace tissue::sim_app
