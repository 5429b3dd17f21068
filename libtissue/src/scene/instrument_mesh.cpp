// The instrument's mesh: a latitude-longitude sphere (a capsule stretches its middle) and a
// capped cylinder for the shaft, in a frame whose +z is the shaft direction.
#include "tissue/scene/instrument_mesh.h"

#include <cmath>
#include <numbers>

namespace tissue::scene {
namespace {

struct Frame {
  Float3 u, v, w;  ///< orthonormal, w = shaft direction
};

Float3 scale(Float3 a, float s) {
  return {a.x * s, a.y * s, a.z * s};
}
Float3 add(Float3 a, Float3 b) {
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}

Frame frameAlong(Float3 w) {
  const float n = std::sqrt(w.x * w.x + w.y * w.y + w.z * w.z);
  w = n > 0.0f ? scale(w, 1.0f / n) : Float3{0.0f, 0.0f, 1.0f};
  const Float3 a = std::abs(w.x) < 0.9f ? Float3{1.0f, 0.0f, 0.0f} : Float3{0.0f, 1.0f, 0.0f};
  // u = normalize(a x w), v = w x u.
  Float3 u{a.y * w.z - a.z * w.y, a.z * w.x - a.x * w.z, a.x * w.y - a.y * w.x};
  u = scale(u, 1.0f / std::sqrt(u.x * u.x + u.y * u.y + u.z * u.z));
  const Float3 v{w.y * u.z - w.z * u.y, w.z * u.x - w.x * u.z, w.x * u.y - w.y * u.x};
  return {u, v, w};
}

Float3 inFrame(const Frame& f, float x, float y, float z) {
  return add(add(scale(f.u, x), scale(f.v, y)), scale(f.w, z));
}

/// A grid of (rows + 1) x (segments + 1) vertices from `point(i, j)`, two triangles per cell,
/// oriented so that the normals face out.
template <class PointFn>
void addGrid(InstrumentMesh& m, const Frame& f, int rows, int segments, PointFn point) {
  const auto base = static_cast<std::uint32_t>(m.positions.size());
  for (int i = 0; i <= rows; ++i)
    for (int j = 0; j <= segments; ++j) {
      const float phi = 2.0f * std::numbers::pi_v<float> * float(j) / float(segments);
      auto [p, n] = point(i, phi);
      m.positions.push_back(inFrame(f, p.x, p.y, p.z));
      m.normals.push_back(inFrame(f, n.x, n.y, n.z));
      m.tangents.push_back({-std::sin(phi) * f.u.x + std::cos(phi) * f.v.x,
                            -std::sin(phi) * f.u.y + std::cos(phi) * f.v.y,
                            -std::sin(phi) * f.u.z + std::cos(phi) * f.v.z, 1.0f});
      m.uvs.push_back({float(j) / float(segments), float(i) / float(rows)});
    }
  const auto stride = static_cast<std::uint32_t>(segments + 1);
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < segments; ++j) {
      const std::uint32_t a = base + std::uint32_t(i) * stride + std::uint32_t(j), b = a + 1, c = a + stride,
                          d = c + 1;
      m.triangles.push_back({a, b, d});
      m.triangles.push_back({a, d, c});
    }
}

}  // namespace

InstrumentMesh makeInstrumentMesh(const sim::ToolShape& shape, const InstrumentLook& look) {
  InstrumentMesh m;
  const Frame f = frameAlong(look.shaftDirection);
  const int segments = std::max(look.segments, 8), rows = segments / 2;
  const float r = float(shape.radius);
  const float half = shape.kind == sim::ToolShapeKind::Capsule ? float(shape.length) / 2.0f : 0.0f;
  // Tip: latitude theta from the far pole (-w) to the near pole (+w); a capsule's halves are
  // pushed apart along w by its half length.
  addGrid(m, f, rows + 1, segments, [&](int i, float phi) {
    const int k = i <= rows / 2 ? i : i - 1;  // row rows/2 is repeated to join a capsule's halves
    const float theta = std::numbers::pi_v<float> * float(k) / float(rows);
    const Float3 n{std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), -std::cos(theta)};
    const float offset = i <= rows / 2 ? -half : half;
    return std::pair{Float3{r * n.x, r * n.y, r * n.z + offset}, n};
  });
  // Shaft: a cylinder from inside the tip to the handle end, then a flat cap.
  const float rs = r * float(look.shaftRadiusFraction), z0 = half, z1 = half + float(look.shaftLengthMm);
  addGrid(m, f, 1, segments, [&](int i, float phi) {
    const Float3 n{std::cos(phi), std::sin(phi), 0.0f};
    return std::pair{Float3{rs * n.x, rs * n.y, i == 0 ? z0 : z1}, n};
  });
  addGrid(m, f, 1, segments, [&](int i, float phi) {
    const float s = i == 0 ? 1.0f : 0.0f;
    return std::pair{Float3{s * rs * std::cos(phi), s * rs * std::sin(phi), z1}, Float3{0.0f, 0.0f, 1.0f}};
  });
  return m;
}

}  // namespace tissue::scene
