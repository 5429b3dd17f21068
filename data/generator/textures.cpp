#include "textures.h"

#include <algorithm>
#include <cmath>
#include <thread>
#include <vector>

#include "noise.h"
#include "texture_style.h"

namespace tissue::datagen {
namespace {

/// Everything the per-texel pass needs: the style and the two vessel networks.
struct TextureContext {
  MeshKind kind;
  TextureStyle style;
  VesselField thick;
  VesselField thin;
};

/// Per-texel values kept for the second (normal map) pass.
struct TexelGeometry {
  std::vector<Eigen::Vector3d> point;  ///< pattern-space point, mm
  std::vector<double> height;          ///< surface relief, mm
};

std::uint8_t toByte(double x) {
  return std::uint8_t(std::lround(std::clamp(x, 0.0, 1.0) * 255.0));
}

void putRgb(Image8& image, int x, int y, const Eigen::Vector3d& c) {
  std::uint8_t* p = image.at(x, y);
  for (int k = 0; k < 3; ++k)
    p[k] = toByte(c[k]);
}

/// Evaluates one texel: the subsurface depths, colours, opacity and relief height.
void shadeTexel(const TextureContext& ctx, LayerTextures& out, TexelGeometry& geo, int x, int y) {
  const int size = out.subsurface.width;
  const TextureStyle& s = ctx.style;
  const Eigen::Vector3d p = patternPoint(ctx.kind, (x + 0.5) / size, 1.0 - (y + 0.5) / size);
  // Step 1: procedural fields in pattern space (continuous across UV seams).
  const Eigen::Vector3d q = p / s.fineScaleMm;
  const double fine = fbm(q.x(), q.y(), q.z(), 4, s.seed + 1);
  const double detail = fbm(3.5 * q.x(), 3.5 * q.y(), 3.5 * q.z(), 2, s.seed + 2);
  // Lobules: cellular noise on a domain warped by value noise, so cells are irregular and rounded.
  const Eigen::Vector3d l = p / s.lobuleCellMm;
  const double warpX = 0.35 * fbm(0.6 * l.x(), 0.6 * l.y(), 0.6 * l.z(), 2, s.seed + 6);
  const double warpY = 0.35 * fbm(0.6 * l.x() + 17.0, 0.6 * l.y(), 0.6 * l.z(), 2, s.seed + 7);
  const WorleyDistances w = worley(l.x() + warpX, l.y() + warpY, l.z(), s.seed + 3);
  const double lobule = smoothstep(0.05, 0.6, w.f2 - w.f1) * smoothstep(1.0, 0.35, w.f1);
  const double fatNoise = 0.5 + 0.5 * fbm(p.x() / 22.0, p.y() / 22.0, p.z() / 22.0, 3, s.seed + 4);
  const double fatMask = smoothstep(1.0 - s.fatCoverage - 0.08, 1.0 - s.fatCoverage + 0.08, fatNoise);
  const double fat = lobule * fatMask;
  const double thick = ctx.thick.profile(p), thin = ctx.thin.profile(p);
  const double thickHalo = ctx.thick.halo(p), thinHalo = ctx.thin.halo(p);
  // Step 2: layer boundaries (François §2.1: depth of each layer along the normal). Each structure
  // rises from the deep boundary A; min() keeps them non-decreasing where structures overlap.
  const double a = 0.86 + 0.06 * fbm(p.x() / 8.0, p.y() / 8.0, p.z() / 8.0, 2, s.seed + 5);
  const double b = a - (a - 0.22) * thick;
  const double g = std::min(b, a - (a - 0.12) * thin);
  const double r = std::min(g, a - (a - 0.05) * fat);
  std::uint8_t* sub = out.subsurface.at(x, y);
  sub[0] = toByte(r), sub[1] = toByte(g), sub[2] = toByte(b), sub[3] = toByte(a);
  // Step 3: outer colour with fat and vessels showing through slightly (Norberg Fig. 8(a)).
  Eigen::Vector3d base = s.outerColor * (0.9 + 0.1 * fine + 0.04 * detail);
  base += (s.fatColor - base) * (0.55 * fat);
  base += (s.vesselColor - base) * std::min(1.0, 0.30 * thickHalo + 0.18 * thinHalo);
  putRgb(out.baseColor, x, y, base);
  // Step 4: opacity, lower over vessels so the inner layer shows (Norberg Fig. 8(c)).
  out.opacity.at(x, y)[0] = toByte(0.92 - 0.45 * thick - 0.3 * thin - 0.12 * fat + 0.03 * fine);
  // Step 5: inner layer, deeper red with clearly visible vessels (Norberg Fig. 8(d)).
  Eigen::Vector3d inner = s.innerColor * (0.85 + 0.15 * fine);
  inner += (s.innerVesselColor - inner) *
           std::min(1.0, 0.9 * std::max(thick, 0.85 * thin) + 0.25 * std::max(thickHalo, thinHalo));
  putRgb(out.innerBase, x, y, inner);
  // Step 6: surface relief for the normal map: lobule bulges, vessel ridges and fine wrinkles (mm).
  const std::size_t i = std::size_t(y) * size + x;
  geo.point[i] = p;
  geo.height[i] = 0.25 * fat + 0.15 * thick + 0.06 * thin + 0.1 * fine + 0.02 * detail;
}

/// Tangent-space normal by central differences of the relief; slopes use the pattern-space
/// distance between neighbouring texels, so they are in mm/mm. Green = +v (OpenGL convention).
void normalTexel(const TexelGeometry& geo, Image8& normalMap, int x, int y) {
  const int n = normalMap.width;
  const auto at = [n](int i, int j) {
    return std::size_t(std::clamp(j, 0, n - 1)) * n + std::clamp(i, 0, n - 1);
  };
  const auto slope = [&geo](std::size_t lo, std::size_t hi) {
    const double run = (geo.point[hi] - geo.point[lo]).norm();
    return run > 1e-9 ? (geo.height[hi] - geo.height[lo]) / run : 0.0;
  };
  const double dhdu = slope(at(x - 1, y), at(x + 1, y));
  const double dhdv = slope(at(x, y + 1), at(x, y - 1));  // rows run top to bottom, v runs up
  const Eigen::Vector3d normal = Eigen::Vector3d(-dhdu, -dhdv, 1.0).normalized();
  putRgb(normalMap, x, y, 0.5 * normal + Eigen::Vector3d::Constant(0.5));
}

/// Runs `texel(x, y)` over all texels, rows split into contiguous blocks, one per thread.
template <class F>
void forEachTexel(int size, int threads, const F& texel) {
  const int count = std::clamp(threads, 1, size);
  std::vector<std::thread> workers;
  for (int t = 0; t < count; ++t) {
    workers.emplace_back([&, t] {
      for (int y = size * t / count; y < size * (t + 1) / count; ++y) {
        for (int x = 0; x < size; ++x)
          texel(x, y);
      }
    });
  }
  for (std::thread& w : workers)
    w.join();
}

}  // namespace

LayerTextures generateTextures(MeshKind kind, int size, int threads) {
  const TextureStyle style = textureStyle(kind);
  const TextureContext ctx{kind, style, VesselField(growVessels(style.surface, style.thickVessels), 1.5),
                           VesselField(growVessels(style.surface, style.thinVessels), 0.8)};
  LayerTextures out{Image8(size, size, 4), Image8(size, size, 3), Image8(size, size, 3),
                    Image8(size, size, 1), Image8(size, size, 3)};
  TexelGeometry geo{std::vector<Eigen::Vector3d>(std::size_t(size) * size),
                    std::vector<double>(std::size_t(size) * size)};
  forEachTexel(size, threads, [&](int x, int y) { shadeTexel(ctx, out, geo, x, y); });
  forEachTexel(size, threads, [&](int x, int y) { normalTexel(geo, out.normalMap, x, y); });
  return out;
}

}  // namespace tissue::datagen
