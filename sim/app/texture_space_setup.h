#pragma once
/// \file
/// tissue-sim's texture-space set-up: the organ and the skin profile are the library's
/// (tissue/studies/texture_space_organ.h); the skin table is ../shared/reference's.

#include <vector>

#include "tissue/core/result.h"
#include "tissue/studies/texture_space_organ.h"

namespace tissue::sim_app {

using studies::loadRenderMesh;
using studies::loadTsdOrgan;
using studies::TsdOrgan;

/// d'Eon & Luebke's skin profile as `count` Gaussians (2, 4 or 6) from
/// ../shared/reference/deon_skin_gaussians.tsv (studies::skinGaussians); the errors name the
/// option and the environment variable.
Result<std::vector<render::ProfileGaussian>> skinGaussians(int count);

}  // namespace tissue::sim_app
