#pragma once
/// \file
/// The linear radiance of the renderer's last frame as the truth scores it: the radiance target
/// plus the separable and texture-space objects' diffuse after their blur (render::FrameView),
/// rows top to bottom. The atlas and the inspection's truth_error view read it the same way.

#include <vector>

#include "tissue/core/result.h"
#include "tissue/core/types.h"
#include "tissue/render/renderer.h"

namespace tissue::studies {

/// Reads both targets back (the caller's context current; a read-back stall, so never on a
/// host's frame path).
Result<std::vector<Float3>> lastFrameRadiance(render::Renderer& renderer);

}  // namespace tissue::studies
