// UV atlas, step 3: one texel density for all charts, shelf packing with a gutter.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>

#include "uv_atlas_steps.h"

namespace tissue::mesh::atlas {
namespace {

struct Box {
  float width = 0.0f, height = 0.0f;  ///< mm, after rotation
};

/// Rotates a chart (about the origin) to the angle, in 2-degree steps over 90 degrees, with the
/// smallest bounding box, then lays it landscape and moves its box corner to the origin.
Box orient(FlatChart& chart) {
  float bestArea = 1e30f, bestAngle = 0.0f;
  for (int step = 0; step < 45; ++step) {
    const float a = float(step) * std::numbers::pi_v<float> / 90.0f, c = std::cos(a), s = std::sin(a);
    float lo[2] = {1e30f, 1e30f}, hi[2] = {-1e30f, -1e30f};
    for (const Float2& w : chart.uv) {
      const float x = c * w.x - s * w.y, y = s * w.x + c * w.y;
      lo[0] = std::min(lo[0], x), lo[1] = std::min(lo[1], y), hi[0] = std::max(hi[0], x),
      hi[1] = std::max(hi[1], y);
    }
    const float area = (hi[0] - lo[0]) * (hi[1] - lo[1]);
    if (area < bestArea) bestArea = area, bestAngle = a;
  }
  const float c = std::cos(bestAngle), s = std::sin(bestAngle);
  float lo[2] = {1e30f, 1e30f}, hi[2] = {-1e30f, -1e30f};
  for (Float2& w : chart.uv) {
    w = {c * w.x - s * w.y, s * w.x + c * w.y};
    lo[0] = std::min(lo[0], w.x), lo[1] = std::min(lo[1], w.y), hi[0] = std::max(hi[0], w.x),
    hi[1] = std::max(hi[1], w.y);
  }
  const bool portrait = hi[1] - lo[1] > hi[0] - lo[0];
  for (Float2& w : chart.uv) {  // a quarter turn keeps the orientation (no mirror)
    w = {w.x - lo[0], w.y - lo[1]};
    if (portrait) w = {hi[1] - lo[1] - w.y, w.x};
  }
  return portrait ? Box{hi[1] - lo[1], hi[0] - lo[0]} : Box{hi[0] - lo[0], hi[1] - lo[1]};
}

/// Shelf packing of boxes (mm) scaled by `scale` (UV units per mm) into [0, 1]^2 with `gutter`
/// (UV units) around each; `order` is by decreasing height. Writes the corners; false if the
/// boxes do not fit.
bool shelfPack(const std::vector<Box>& boxes, const std::vector<std::size_t>& order, float scale,
               float gutter, std::vector<Float2>& corner) {
  const float lo = 0.5f * gutter, hi = 1.0f - 0.5f * gutter;  // a full gutter to the border
  float x = lo, y = lo, shelfHeight = 0.0f;
  for (std::size_t i : order) {
    const float w = boxes[i].width * scale + gutter, h = boxes[i].height * scale + gutter;
    if (x + w > hi) {  // next shelf
      x = lo;
      y += shelfHeight;
      shelfHeight = 0.0f;
    }
    if (x + w > hi || y + h > hi) return false;
    corner[i] = {x + 0.5f * gutter, y + 0.5f * gutter};
    x += w;
    shelfHeight = std::max(shelfHeight, h);
  }
  return true;
}

}  // namespace

float packCharts(std::vector<FlatChart>& charts, int resolution, float gutterTexels) {
  std::vector<Box> boxes(charts.size());
  double area = 0.0;
  for (std::size_t i = 0; i < charts.size(); ++i) {
    boxes[i] = orient(charts[i]);
    area += double(boxes[i].width) * double(boxes[i].height);
  }
  std::vector<std::size_t> order(charts.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return boxes[a].height > boxes[b].height; });
  // Bisection on the common scale (UV units per mm): the boxes' total area bounds it above.
  // 2% over the gutter, so float rounding of the placed UVs never eats into it.
  const float gutter = 1.02f * gutterTexels / float(resolution);
  float fits = 0.0f, fails = float(1.0 / std::sqrt(std::max(area, 1e-30)));
  std::vector<Float2> corner(charts.size()), best(charts.size());
  if (shelfPack(boxes, order, fails, gutter, corner)) fits = fails, best = corner;
  for (int iteration = 0; iteration < 40 && fits < fails; ++iteration) {
    const float mid = 0.5f * (fits + fails);
    if (shelfPack(boxes, order, mid, gutter, corner))
      fits = mid, best = corner;
    else
      fails = mid;
  }
  for (std::size_t i = 0; i < charts.size(); ++i)
    for (Float2& w : charts[i].uv)
      w = {best[i].x + w.x * fits, best[i].y + w.y * fits};
  return fits * float(resolution);
}

}  // namespace tissue::mesh::atlas
