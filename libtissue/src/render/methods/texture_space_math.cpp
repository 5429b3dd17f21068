// GL-free maths of texture-space diffusion and of Jimenez et al.'s three optimisations.
#include "tissue/render/texture_space_math.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace tissue::render {

float irradianceMapScale(float nearestDistanceMm, float referenceDistanceMm) {
  if (!(nearestDistanceMm > 0.0f)) return 1.0f;                    // the eye touches the box: full size
  return std::min(referenceDistanceMm / nearestDistanceMm, 1.0f);  // eq. 3
}

int irradianceMapSize(float scale, int maxSize, int minSize) {
  const int size = int(std::ceil(double(scale) * maxSize));  // eq. 4
  return std::clamp(size, std::min(minSize, maxSize), maxSize);
}

float nearestBoxCornerDistance(Float3 eye, Float3 lo, Float3 hi) {
  float best = 1e30f;
  for (int c = 0; c < 8; ++c) {
    const float x = (c & 1) ? hi.x : lo.x, y = (c & 2) ? hi.y : lo.y, z = (c & 4) ? hi.z : lo.z;
    best = std::min(best, std::hypot(x - eye.x, y - eye.y, z - eye.z));
  }
  return best;
}

std::array<Float4, 6> eyeSpaceFrustumPlanes(const Mat4& p, float clipD) {
  // Eq. 5: the clip-space planes; eq. 6: Pi_eye = P^T Pi_clip, i.e. component j of Pi_eye is
  // column j of P dotted with Pi_clip (column-major: column j is p[4j .. 4j+3]).
  const float clip[6][4] = {{1, 0, 0, clipD},  {-1, 0, 0, clipD}, {0, 1, 0, clipD},
                            {0, -1, 0, clipD}, {0, 0, 1, clipD},  {0, 0, -1, clipD}};
  std::array<Float4, 6> planes;
  for (int i = 0; i < 6; ++i) {
    float e[4];
    for (int j = 0; j < 4; ++j)
      e[j] = p[std::size_t(4 * j + 0)] * clip[i][0] + p[std::size_t(4 * j + 1)] * clip[i][1] +
             p[std::size_t(4 * j + 2)] * clip[i][2] + p[std::size_t(4 * j + 3)] * clip[i][3];
    planes[std::size_t(i)] = {e[0], e[1], e[2], e[3]};
  }
  return planes;
}

bool insideFrustum(const std::array<Float4, 6>& planes, Float3 p) {
  return std::all_of(planes.begin(), planes.end(),
                     [p](Float4 n) { return n.x * p.x + n.y * p.y + n.z * p.z + n.w >= 0.0f; });
}

Float2 uvStretch(const std::array<Float3, 3>& p, const std::array<Float2, 3>& uv) {
  // Solve [dP/du dP/dv] [du1 du2; dv1 dv2] = [e1 e2] for the two tangent vectors.
  const double du1 = uv[1].x - uv[0].x, dv1 = uv[1].y - uv[0].y;
  const double du2 = uv[2].x - uv[0].x, dv2 = uv[2].y - uv[0].y;
  const double det = du1 * dv2 - du2 * dv1;
  if (det == 0.0) return {0.0f, 0.0f};
  const double e1[3] = {p[1].x - p[0].x, p[1].y - p[0].y, p[1].z - p[0].z};
  const double e2[3] = {p[2].x - p[0].x, p[2].y - p[0].y, p[2].z - p[0].z};
  double pu[3], pv[3];
  for (int k = 0; k < 3; ++k) {
    pu[k] = (e1[k] * dv2 - e2[k] * dv1) / det;
    pv[k] = (e2[k] * du1 - e1[k] * du2) / det;
  }
  return {float(std::hypot(pu[0], pu[1], pu[2])), float(std::hypot(pv[0], pv[1], pv[2]))};
}

Float3 evaluateGaussianSum(const std::vector<ProfileGaussian>& gaussians, float rMm) {
  double sum[3] = {0.0, 0.0, 0.0};
  for (const ProfileGaussian& g : gaussians) {
    const double v = double(g.varianceMm2);
    const double r = double(rMm);
    const double value = std::exp(-r * r / (2.0 * v)) / (2.0 * std::numbers::pi * v);
    sum[0] += double(g.weight.x) * value, sum[1] += double(g.weight.y) * value,
        sum[2] += double(g.weight.z) * value;
  }
  return {float(sum[0]), float(sum[1]), float(sum[2])};
}

std::vector<float> incrementalVariances(const std::vector<ProfileGaussian>& gaussians) {
  std::vector<float> steps;
  float previous = 0.0f;
  for (const ProfileGaussian& g : gaussians) {
    steps.push_back(std::max(g.varianceMm2 - previous, 0.0f));
    previous = std::max(previous, g.varianceMm2);
  }
  return steps;
}

std::vector<BlurTap> gaussianBlurTaps(int halfTaps) {
  std::vector<BlurTap> taps;
  if (halfTaps <= 0) return {{0.0f, 1.0f}};
  double total = 0.0;
  for (int k = -halfTaps; k <= halfTaps; ++k) {
    const double x = 3.0 * k / halfTaps;
    taps.push_back({float(x), float(std::exp(-0.5 * x * x))});
    total += std::exp(-0.5 * x * x);
  }
  for (BlurTap& t : taps)
    t.weight = float(double(t.weight) / total);
  return taps;
}

float uvDensity(std::span<const Float3> positionsMm, std::span<const Float2> uvs,
                std::span<const Triangle> triangles) {
  double uv = 0.0, area = 0.0;
  for (const Triangle& t : triangles) {
    const Float2 a = uvs[t[0]], b = uvs[t[1]], c = uvs[t[2]];
    uv += 0.5 * std::abs(double(b.x - a.x) * double(c.y - a.y) - double(b.y - a.y) * double(c.x - a.x));
    const Float3 p = positionsMm[t[0]], q = positionsMm[t[1]], r = positionsMm[t[2]];
    const double ex = double(q.x - p.x), ey = double(q.y - p.y), ez = double(q.z - p.z);
    const double fx = double(r.x - p.x), fy = double(r.y - p.y), fz = double(r.z - p.z);
    area += 0.5 * std::hypot(ey * fz - ez * fy, ez * fx - ex * fz, ex * fy - ey * fx);
  }
  return area > 0.0 ? float(std::sqrt(uv / area)) : 0.0f;
}

}  // namespace tissue::render
