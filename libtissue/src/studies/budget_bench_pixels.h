#pragma once
// Private to tissue::studies: which organ each pixel of the budget bench shows, so that its
// errors can be split by organ (does one method win everywhere, or each organ its own?) and
// scored away from silhouettes (the truth averages jittered sub-pixel rays, the renderer draws
// one sample per pixel: a pixel on an edge differs by its coverage, whatever the method).
#include <cstdint>
#include <span>
#include <vector>

#include "tissue/core/result.h"
#include "tissue/core/types.h"
#include "tissue/render/scene.h"

namespace tissue::studies::detail {

struct OrganPixels {
  int width = 0, height = 0;
  std::vector<int> organ;              ///< per pixel: the organ its centre ray meets first, or -1
  std::vector<std::uint8_t> interior;  ///< 1 where all 4 x 4 sub-pixel rays meet that organ
};

/// `firstTriangle[i]`: organ i's first triangle in `triangles` (ascending; organ i ends where
/// organ i + 1 begins). World mm; the camera as the renderer's, rows top to bottom.
Result<OrganPixels> organPixels(std::span<const Float3> positionsMm, std::span<const Triangle> triangles,
                                std::span<const std::uint32_t> firstTriangle, const render::Camera& camera,
                                int width, int height);

/// 1 where the pixel shows `organ` (any organ for -1), and only interior pixels when asked.
std::vector<std::uint8_t> organMask(const OrganPixels& pixels, int organ, bool interiorOnly);

}  // namespace tissue::studies::detail
