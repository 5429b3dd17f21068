// The automatic UV atlas: segmentation, LSCM per chart with splits of folding or non-disk
// charts, packing; and the distortion measures reported for it.
#include "tissue/mesh/uv_atlas.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "uv_atlas_steps.h"
#include "vec3.h"

namespace tissue::mesh {

using namespace detail;

namespace {

Result<void> checkInput(std::span<const Float3> positions, std::span<const Triangle> triangles,
                        const AtlasSettings& settings) {
  if (positions.empty() || triangles.empty()) return Error{"uv atlas: the mesh has no triangles"};
  for (std::size_t v = 0; v < positions.size(); ++v)
    if (!isFinite(positions[v]))
      return Error{"uv atlas: vertex " + std::to_string(v + 1) + " has a non-finite position; fix the mesh"};
  for (std::size_t t = 0; t < triangles.size(); ++t)
    for (std::uint32_t v : triangles[t])
      if (v >= positions.size())
        return Error{"uv atlas: triangle " + std::to_string(t + 1) + " indexes vertex " +
                     std::to_string(v + 1) + " of " + std::to_string(positions.size())};
  if (settings.resolution < 16 || !(settings.gutterTexels >= 0.0f) ||
      !(settings.maxChartNormalDeviationDeg > 0.0f && settings.maxChartNormalDeviationDeg < 90.0f))
    return Error{"uv atlas: settings need resolution >= 16, gutter >= 0 and 0 < deviation < 90 degrees"};
  return {};
}

/// Flattens each chart; a chart that is not disk-like or whose map folds is split and retried.
Result<std::vector<atlas::FlatChart>> flattenAll(std::span<const Float3> positions,
                                                 std::span<const Triangle> triangles,
                                                 std::vector<std::vector<std::uint32_t>> work,
                                                 std::span<const std::int32_t> adjacency, int maxDepth) {
  std::vector<atlas::FlatChart> done;
  std::vector<std::pair<std::vector<std::uint32_t>, int>> stack;
  for (auto& chart : work)
    stack.emplace_back(std::move(chart), 0);
  while (!stack.empty()) {
    auto [chart, depth] = std::move(stack.back());
    stack.pop_back();
    if (chart.size() > 1 && !atlas::isDiskLike(triangles, chart, adjacency)) {
      if (depth >= maxDepth) return Error{"uv atlas: a chart stays non-disk after maxSplitDepth splits"};
      for (auto& part : atlas::splitChart(positions, triangles, chart, adjacency))
        stack.emplace_back(std::move(part), depth + 1);
      continue;
    }
    auto flat = atlas::flattenChart(positions, triangles, chart);
    if (flat && (chart.size() == 1 || atlas::isValidFlattening(*flat))) {
      done.push_back(std::move(*flat));
      continue;
    }
    if (chart.size() == 1)
      return Error{"uv atlas: triangle " + std::to_string(chart[0] + 1) + " has no area"};
    if (depth >= maxDepth) return Error{"uv atlas: a chart still folds after maxSplitDepth splits"};
    for (auto& part : atlas::splitChart(positions, triangles, chart, adjacency))
      stack.emplace_back(std::move(part), depth + 1);
  }
  return done;
}

}  // namespace

Result<UvAtlas> computeUvAtlas(std::span<const Float3> positions, std::span<const Triangle> triangles,
                               const AtlasSettings& settings) {
  if (auto r = checkInput(positions, triangles, settings); !r) return r.error();
  // Step 1: segmentation by region growing in a normal cone.
  std::vector<Float3> faceNormals(triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const Float3 p0 = positions[triangles[t][0]];
    faceNormals[t] =
        normalizeOr(cross(positions[triangles[t][1]] - p0, positions[triangles[t][2]] - p0), Float3{});
  }
  const auto adjacency = atlas::triangleAdjacency(triangles, positions.size());
  const auto chartOf = atlas::growCharts(faceNormals, adjacency, settings.maxChartNormalDeviationDeg);
  const std::uint32_t grown = chartOf.empty() ? 0 : *std::max_element(chartOf.begin(), chartOf.end()) + 1;
  std::vector<std::vector<std::uint32_t>> charts(grown);
  for (std::uint32_t t = 0; t < chartOf.size(); ++t)
    charts[chartOf[t]].push_back(t);
  // Step 2: LSCM per chart, splitting what is not a disk or folds.
  auto flat = flattenAll(positions, triangles, std::move(charts), adjacency, settings.maxSplitDepth);
  if (!flat) return flat.error();
  // Step 3: packing at one texel density.
  UvAtlas out;
  out.texelsPerMm = atlas::packCharts(*flat, settings.resolution, settings.gutterTexels);
  if (!(out.texelsPerMm > 0.0f))
    return Error{"uv atlas: " + std::to_string(flat->size()) + " charts do not fit a " +
                 std::to_string(settings.resolution) + " map with the gutter; raise the resolution"};
  // Step 4: render vertices per (chart, vertex); triangles keep their input order.
  out.triangles.resize(triangles.size());
  out.chartOfTriangle.resize(triangles.size());
  out.chartCount = std::uint32_t(flat->size());
  for (std::uint32_t c = 0; c < flat->size(); ++c) {
    const atlas::FlatChart& chart = (*flat)[c];
    const auto base = std::uint32_t(out.uvs.size());
    out.uvs.insert(out.uvs.end(), chart.uv.begin(), chart.uv.end());
    out.originalVertex.insert(out.originalVertex.end(), chart.vertices.begin(), chart.vertices.end());
    for (std::size_t i = 0; i < chart.triangles.size(); ++i) {
      const Triangle& lt = chart.localTriangles[i];
      out.triangles[chart.triangles[i]] = {base + lt[0], base + lt[1], base + lt[2]};
      out.chartOfTriangle[chart.triangles[i]] = c;
    }
  }
  return out;
}

AtlasDistortion measureAtlasDistortion(std::span<const Float3> positions, std::span<const Float2> uvs,
                                       std::span<const Triangle> triangles) {
  AtlasDistortion d;
  // Areas first: the UV map is scaled so that its total area equals the surface's.
  double area3d = 0.0, areaUv = 0.0;
  for (const Triangle& t : triangles) {
    area3d +=
        0.5 * double(length(cross(positions[t[1]] - positions[t[0]], positions[t[2]] - positions[t[0]])));
    const Float2 p = uvs[t[0]], q = uvs[t[1]], r = uvs[t[2]];
    const double signedUv = 0.5 * atlas::uvCross(p, q, r);
    areaUv += std::abs(signedUv);
    if (signedUv <= 0.0) ++d.flippedTriangles;
  }
  d.coverage = areaUv;
  if (!(area3d > 0.0 && areaUv > 0.0)) return d;
  const double norm = std::sqrt(area3d / areaUv);
  double l2 = 0.0, angle = 0.0, areaRatio = 0.0;
  for (const Triangle& t : triangles) {
    // 3D triangle in its plane (q), UV triangle (w); J = W Q^-1 maps q to w.
    const Float3 e1 = positions[t[1]] - positions[t[0]], e2 = positions[t[2]] - positions[t[0]];
    const double a = 0.5 * double(length(cross(e1, e2)));
    if (!(a > 0.0)) continue;
    const Float3 ax = normalizeOr(e1, Float3{}), ay = normalizeOr(cross(cross(e1, e2), e1), Float3{});
    const double q11 = dot(e1, ax), q12 = dot(e2, ax), q22 = dot(e2, ay);  // Q = [[q11, q12], [0, q22]]
    const Float2 p = uvs[t[0]];
    const double w11 = double(uvs[t[1]].x - p.x) * norm, w12 = double(uvs[t[2]].x - p.x) * norm;
    const double w21 = double(uvs[t[1]].y - p.y) * norm, w22 = double(uvs[t[2]].y - p.y) * norm;
    const double j11 = w11 / q11, j12 = (w12 - j11 * q12) / q22, j21 = w21 / q11,
                 j22 = (w22 - j21 * q12) / q22;
    // Singular values of the 2x2 Jacobian, closed form.
    const double e = 0.5 * (j11 + j22), f = 0.5 * (j11 - j22), g = 0.5 * (j21 + j12), h = 0.5 * (j21 - j12);
    const double qq = std::hypot(e, h), rr = std::hypot(f, g);
    const double s1 = qq + rr, s2 = std::abs(qq - rr);
    if (!(s2 > 0.0)) continue;
    // Sander et al. 2001 measure the texture-to-surface map: its singular values are 1/s2, 1/s1.
    l2 += a * 0.5 * (1.0 / (s1 * s1) + 1.0 / (s2 * s2));
    const double ratio = s1 / s2, areaScale = std::max(s1 * s2, 1.0 / (s1 * s2));
    angle += a * ratio;
    areaRatio += a * areaScale;
    d.maxAngleRatio = std::max(d.maxAngleRatio, ratio);
    d.maxAreaRatio = std::max(d.maxAreaRatio, areaScale);
  }
  d.l2Stretch = std::sqrt(l2 / area3d);
  d.meanAngleRatio = angle / area3d;
  d.meanAreaRatio = areaRatio / area3d;
  return d;
}

}  // namespace tissue::mesh
