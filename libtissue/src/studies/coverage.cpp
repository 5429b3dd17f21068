// Silhouette pixels of MSAA frames for the screen-space references.
#include "tissue/studies/coverage.h"

namespace tissue::studies {

void dropPartialCoverage(std::vector<Float4>& diffuse, const render::FloatImage& radiance) {
  for (std::size_t i = 0; i < diffuse.size() && i < radiance.pixels.size(); ++i)
    if (radiance.pixels[i].w < 0.999f) diffuse[i].w = 0.0f;
}

void removeCoverageWeight(std::vector<Float4>& blurred, const render::FloatImage& radiance) {
  for (std::size_t i = 0; i < blurred.size() && i < radiance.pixels.size(); ++i) {
    const float a = radiance.pixels[i].w;
    if (a > 0.0f && a < 1.0f)
      blurred[i] = {blurred[i].x / a, blurred[i].y / a, blurred[i].z / a, blurred[i].w};
  }
}

}  // namespace tissue::studies
