// Which organ each pixel of the budget bench shows (budget_bench_pixels.h). GL-free: the truth's
// ray mesh and pinhole rays.
#include "budget_bench_pixels.h"

#include <algorithm>
#include <limits>

#include "tissue/scene/truth_view.h"
#include "tissue/truth/path_tracer.h"
#include "tissue/truth/ray_mesh.h"

namespace tissue::studies::detail {

Result<OrganPixels> organPixels(std::span<const Float3> positionsMm, std::span<const Triangle> triangles,
                                std::span<const std::uint32_t> firstTriangle, const render::Camera& camera,
                                int width, int height) {
  auto rays = truth::makeRayMesh(positionsMm, triangles);
  if (!rays) return rays.error();
  const truth::TruthCamera cam = scene::truthCameraOf(camera);
  const std::array<double, 3> eye{cam.eye.x, cam.eye.y, cam.eye.z};
  const auto organAt = [&](double px, double py) {
    const Float3 d = truth::pinholeRayDirection(cam, width, height, px, py);
    const auto hit = (*rays)->intersect(eye, {d.x, d.y, d.z}, 0.0, std::numeric_limits<double>::infinity());
    if (!hit) return -1;
    const auto it = std::upper_bound(firstTriangle.begin(), firstTriangle.end(), hit->triangle);
    return int(it - firstTriangle.begin()) - 1;
  };
  OrganPixels out;
  out.width = width;
  out.height = height;
  out.organ.assign(std::size_t(width) * std::size_t(height), -1);
  out.interior.assign(out.organ.size(), 0);
  constexpr int kSub = 4;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const std::size_t i = std::size_t(y) * std::size_t(width) + std::size_t(x);
      out.organ[i] = organAt(x + 0.5, y + 0.5);
      if (out.organ[i] < 0) continue;
      bool all = true;
      for (int s = 0; s < kSub * kSub && all; ++s)
        all = organAt(x + (s % kSub + 0.5) / kSub, y + (s / kSub + 0.5) / kSub) == out.organ[i];
      out.interior[i] = all ? 1 : 0;
    }
  return out;
}

std::vector<std::uint8_t> organMask(const OrganPixels& pixels, int organ, bool interiorOnly) {
  std::vector<std::uint8_t> mask(pixels.organ.size(), 0);
  for (std::size_t i = 0; i < mask.size(); ++i)
    mask[i] = pixels.organ[i] >= 0 && (organ < 0 || pixels.organ[i] == organ) &&
              (!interiorOnly || pixels.interior[i]);
  return mask;
}

}  // namespace tissue::studies::detail
