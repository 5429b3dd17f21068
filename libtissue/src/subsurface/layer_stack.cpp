// Layered material of subsurface texture mapping (François et al. 2006 §2.1; Norberg 2010 §2.1.2).
#include "tissue/subsurface/layer_stack.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace tissue::subsurface {

Result<SubsurfaceMaps> subsurfaceMapsFromImages(std::span<const Image8> images) {
  SubsurfaceMaps maps;
  if (images.empty()) return maps;
  if (images.size() * 4 > kMaxBoundaries)
    return Error{"subsurface maps: " + std::to_string(images.size()) + " maps given, at most " +
                 std::to_string(kMaxBoundaries / 4) + " are supported; merge layers"};
  maps.width = images[0].width;
  maps.height = images[0].height;
  maps.mapCount = int(images.size());
  const int stride = 4 * maps.mapCount;
  maps.depths.assign(std::size_t(maps.width) * maps.height * stride, 0.0f);
  for (int m = 0; m < maps.mapCount; ++m) {
    const Image8& image = images[m];
    if (image.width != maps.width || image.height != maps.height || image.channels != 4)
      return Error{"subsurface map " + std::to_string(m) + ": " + std::to_string(image.width) + "x" +
                   std::to_string(image.height) + " with " + std::to_string(image.channels) +
                   " channels; every map must be RGBA of the first map's size"};
    for (int y = 0; y < maps.height; ++y)
      for (int x = 0; x < maps.width; ++x)
        for (int c = 0; c < 4; ++c)
          maps.depths[(std::size_t(y) * maps.width + x) * stride + m * 4 + c] = image.at(x, y)[c] / 255.0f;
  }
  return maps;
}

Result<void> validateLayerStack(const LayerStack& stack) {
  const std::size_t want = std::size_t(stack.boundaryCount()) + 1;
  if (stack.layers.size() != want)
    return Error{"layer stack: " + std::to_string(stack.layers.size()) + " layers for " +
                 std::to_string(stack.boundaryCount()) + " boundaries; give 4N + 1 layers for N RGBA maps"};
  for (std::size_t i = 0; i < stack.layers.size(); ++i) {
    const LayerCoefficients& l = stack.layers[i];
    const float s[3] = {l.sigma_s.x, l.sigma_s.y, l.sigma_s.z};
    const float t[3] = {l.sigma_t.x, l.sigma_t.y, l.sigma_t.z};
    for (int c = 0; c < 3; ++c)
      if (!(s[c] >= 0.0f && t[c] > 0.0f && t[c] >= s[c]))
        return Error{"layer " + std::to_string(i) + ": need sigma_t > 0 and 0 <= sigma_s <= sigma_t (mm^-1)"};
    if (!(std::abs(l.g) < 1.0f)) return Error{"layer " + std::to_string(i) + ": g must lie in (-1, 1)"};
  }
  if (!(stack.depthScaleMm > 0.0f)) return Error{"layer stack: depth_scale_mm must be positive"};
  return {};
}

Boundaries sampleBoundaries(const LayerStack& stack, Float2 uv) {
  Boundaries b;
  const SubsurfaceMaps& maps = stack.maps;
  b.count = maps.mapCount * 4;
  if (b.count == 0 || maps.width == 0) return b;
  // GL_LINEAR, CLAMP_TO_EDGE; the texture is uploaded bottom row first, so v = 1 is file row 0.
  const float fx = std::clamp(uv.x * maps.width - 0.5f, 0.0f, float(maps.width - 1));
  const float fy = std::clamp((1.0f - uv.y) * maps.height - 0.5f, 0.0f, float(maps.height - 1));
  const int x0 = int(fx), y0 = int(fy);
  const int x1 = std::min(x0 + 1, maps.width - 1), y1 = std::min(y0 + 1, maps.height - 1);
  const float ax = fx - x0, ay = fy - y0;
  const int stride = b.count;
  auto at = [&](int x, int y, int c) { return maps.depths[(std::size_t(y) * maps.width + x) * stride + c]; };
  for (int c = 0; c < b.count; ++c) {
    const float top = at(x0, y0, c) * (1 - ax) + at(x1, y0, c) * ax;
    const float bottom = at(x0, y1, c) * (1 - ax) + at(x1, y1, c) * ax;
    b.depthMm[c] = (top * (1 - ay) + bottom * ay) * stack.depthScaleMm;
  }
  // Bilinear weights keep the channels ordered where the texels are; enforce it for safety.
  for (int c = 1; c < b.count; ++c)
    b.depthMm[c] = std::max(b.depthMm[c], b.depthMm[c - 1]);
  return b;
}

int findLayer(const Boundaries& boundaries, float depthMm) {
  int layer = 0;
  while (layer < boundaries.count && boundaries.depthMm[layer] <= depthMm)
    ++layer;
  return layer;
}

float layerThicknessMm(const Boundaries& boundaries, int i) {
  if (i >= boundaries.count) return std::numeric_limits<float>::infinity();
  return boundaries.depthMm[i] - (i == 0 ? 0.0f : boundaries.depthMm[i - 1]);
}

}  // namespace tissue::subsurface
