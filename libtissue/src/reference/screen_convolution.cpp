// The exact screen-space convolution with a radial profile (see the header), and image RMS.
#include "tissue/reference/screen_convolution.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

namespace tissue::reference {
namespace {

constexpr float kTwoPi = 2.0f * std::numbers::pi_v<float>;

Float3 sub(Float3 a, Float3 b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
float length(Float3 a) {
  return std::sqrt(a.x * a.x + a.y * a.y + a.z * a.z);
}
Float3 xyz(const Float4& v) {
  return {v.x, v.y, v.z};
}

// R(r) resampled on a uniform grid for fast lookups, linear between samples, 0 beyond rMax.
class ProfileTable {
 public:
  explicit ProfileTable(const RadialProfile& p) : m_rMax(p.radiusMm.back()) {
    m_values.resize(kSize + 1);
    std::size_t k = 0;
    for (int i = 0; i <= kSize; ++i) {
      const float r = m_rMax * static_cast<float>(i) / kSize;
      while (k + 2 < p.radiusMm.size() && p.radiusMm[k + 1] < r)
        ++k;
      const float r0 = p.radiusMm[k], r1 = p.radiusMm[std::min(k + 1, p.radiusMm.size() - 1)];
      const float t = r1 > r0 ? std::clamp((r - r0) / (r1 - r0), 0.0f, 1.0f) : 0.0f;
      const Float3 a = p.value[k], b = p.value[std::min(k + 1, p.value.size() - 1)];
      m_values[static_cast<std::size_t>(i)] = {a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t,
                                               a.z + (b.z - a.z) * t};
    }
  }
  Float3 operator()(float r) const {
    if (r >= m_rMax) return {};
    const float x = r / m_rMax * kSize;
    const int i = std::min(static_cast<int>(x), kSize - 1);
    const float t = x - static_cast<float>(i);
    const Float3 a = m_values[static_cast<std::size_t>(i)], b = m_values[static_cast<std::size_t>(i) + 1];
    return {a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t, a.z + (b.z - a.z) * t};
  }
  float rMax() const { return m_rMax; }

 private:
  static constexpr int kSize = 4096;
  float m_rMax;
  std::vector<Float3> m_values;
};

// Per pixel: the world-space edge vectors of its footprint (central differences to neighbours
// of the same object, one-sided at an edge) and its area, mm^2; 0 when a direction has none.
struct Footprint {
  Float3 dx, dy;
  float area = 0.0f;
};

std::vector<Footprint> footprints(const ScreenBuffers& f) {
  std::vector<Footprint> out(static_cast<std::size_t>(f.width) * f.height);
  auto id = [&](int x, int y) { return static_cast<int>(std::lround(f.radiance[y * f.width + x].w)); };
  auto edge = [&](int x, int y, int sx, int sy, Float3& e) {
    const int i = id(x, y);
    const bool back = x - sx >= 0 && y - sy >= 0 && id(x - sx, y - sy) == i;
    const bool fwd = x + sx < f.width && y + sy < f.height && id(x + sx, y + sy) == i;
    if (!back && !fwd) return false;
    const Float3 a = xyz(f.position[(y - (back ? sy : 0)) * f.width + x - (back ? sx : 0)]);
    const Float3 b = xyz(f.position[(y + (fwd ? sy : 0)) * f.width + x + (fwd ? sx : 0)]);
    const float span = (back && fwd) ? 0.5f : 1.0f;
    const Float3 d = sub(b, a);
    e = {d.x * span, d.y * span, d.z * span};
    return true;
  };
  for (int y = 0; y < f.height; ++y) {
    for (int x = 0; x < f.width; ++x) {
      Footprint& fp = out[static_cast<std::size_t>(y) * f.width + x];
      if (id(x, y) == 0 || !edge(x, y, 1, 0, fp.dx) || !edge(x, y, 0, 1, fp.dy)) continue;
      const Float3 c{fp.dx.y * fp.dy.z - fp.dx.z * fp.dy.y, fp.dx.z * fp.dy.x - fp.dx.x * fp.dy.z,
                     fp.dx.x * fp.dy.y - fp.dx.y * fp.dy.x};
      fp.area = length(c);
    }
  }
  return out;
}

}  // namespace

Float3 profileIntegral(const RadialProfile& p, float rMm) {
  // R = a + b r on each segment: int R 2 pi r dr = 2 pi [a r^2 / 2 + b r^3 / 3].
  Float3 sum{};
  for (std::size_t i = 0; i + 1 < p.radiusMm.size(); ++i) {
    const float r0 = p.radiusMm[i], r1 = std::min(p.radiusMm[i + 1], rMm);
    if (r1 <= r0) break;
    const float full = p.radiusMm[i + 1] - r0;
    auto part = [&](float v0, float v1) {
      const float b = full > 0.0f ? (v1 - v0) / full : 0.0f, a = v0 - b * r0;
      auto F = [&](float r) { return a * r * r / 2.0f + b * r * r * r / 3.0f; };
      return kTwoPi * (F(r1) - F(r0));
    };
    sum.x += part(p.value[i].x, p.value[i + 1].x);
    sum.y += part(p.value[i].y, p.value[i + 1].y);
    sum.z += part(p.value[i].z, p.value[i + 1].z);
  }
  return sum;
}

RadialProfile normalizedProfile(const RadialProfile& profile) {
  RadialProfile out = profile;
  if (profile.empty()) return out;
  const Float3 total = profileIntegral(profile, profile.radiusMm.back());
  for (Float3& v : out.value)
    v = {total.x > 0 ? v.x / total.x : 0.0f, total.y > 0 ? v.y / total.y : 0.0f,
         total.z > 0 ? v.z / total.z : 0.0f};
  return out;
}

Result<std::vector<Float3>> convolveScreen(const ScreenBuffers& f, std::span<const RadialProfile> profiles) {
  const std::size_t n =
      static_cast<std::size_t>(std::max(f.width, 0)) * static_cast<std::size_t>(std::max(f.height, 0));
  if (n == 0 || f.radiance.size() != n || f.position.size() != n) {
    return Error{"reference: the frame's radiance and position need width x height = " + std::to_string(n) +
                 " pixels each (got " + std::to_string(f.radiance.size()) + " and " +
                 std::to_string(f.position.size()) + ")"};
  }
  for (std::size_t i = 0; i < profiles.size(); ++i) {
    const RadialProfile& p = profiles[i];
    if (!p.empty() && (p.radiusMm.size() != p.value.size() || p.radiusMm.size() < 2 ||
                       p.radiusMm[0] != 0.0f || !std::is_sorted(p.radiusMm.begin(), p.radiusMm.end()))) {
      return Error{"reference: profile " + std::to_string(i) +
                   " needs >= 2 increasing radii from 0 mm with one RGB value each"};
    }
  }
  std::vector<ProfileTable> tables;
  for (const RadialProfile& p : profiles)
    tables.emplace_back(p.empty() ? RadialProfile{{0.0f, 1.0f}, {Float3{}, Float3{}}} : p);
  const std::vector<Footprint> fp = footprints(f);
  std::vector<Float3> out(n);
  for (int y = 0; y < f.height; ++y) {
    for (int x = 0; x < f.width; ++x) {
      const std::size_t p = static_cast<std::size_t>(y) * f.width + x;
      const int id = static_cast<int>(std::lround(f.radiance[p].w));
      if (id == 0) continue;
      if (id >= static_cast<int>(profiles.size()) || profiles[static_cast<std::size_t>(id)].empty() ||
          fp[p].area <= 0.0f) {
        out[p] = xyz(f.radiance[p]);
        continue;
      }
      const ProfileTable& R = tables[static_cast<std::size_t>(id)];
      const Float3 xp = xyz(f.position[p]);
      const int half = std::min(static_cast<int>(std::ceil(R.rMax() / std::sqrt(fp[p].area))) + 2, 256);
      Float3 sum{};
      for (int qy = std::max(0, y - half); qy <= std::min(f.height - 1, y + half); ++qy) {
        for (int qx = std::max(0, x - half); qx <= std::min(f.width - 1, x + half); ++qx) {
          const std::size_t q = static_cast<std::size_t>(qy) * f.width + qx;
          if (std::lround(f.radiance[q].w) != id || fp[q].area <= 0.0f) continue;
          Float3 w{};
          if (q == p) {  // the own pixel: R over the disc of its area
            w = profileIntegral(profiles[static_cast<std::size_t>(id)],
                                std::sqrt(fp[p].area / std::numbers::pi_v<float>));
          } else if (std::max(std::abs(qx - x), std::abs(qy - y)) <= 2) {  // near: 4 x 4 over the footprint
            const Float3 xq = xyz(f.position[q]);
            for (int j = 0; j < 4; ++j) {
              for (int i = 0; i < 4; ++i) {
                const float s = (static_cast<float>(i) + 0.5f) / 4.0f - 0.5f,
                            t = (static_cast<float>(j) + 0.5f) / 4.0f - 0.5f;
                const Float3 xs{xq.x + s * fp[q].dx.x + t * fp[q].dy.x,
                                xq.y + s * fp[q].dx.y + t * fp[q].dy.y,
                                xq.z + s * fp[q].dx.z + t * fp[q].dy.z};
                const Float3 r = R(length(sub(xp, xs)));
                const float a = fp[q].area / 16.0f;
                w = {w.x + r.x * a, w.y + r.y * a, w.z + r.z * a};
              }
            }
          } else {
            const Float3 r = R(length(sub(xp, xyz(f.position[q]))));
            w = {r.x * fp[q].area, r.y * fp[q].area, r.z * fp[q].area};
          }
          sum = {sum.x + w.x * f.radiance[q].x, sum.y + w.y * f.radiance[q].y, sum.z + w.z * f.radiance[q].z};
        }
      }
      out[p] = sum;
    }
  }
  return out;
}

ImageError compareWithReference(const ScreenBuffers& f, std::span<const Float4> actual,
                                std::span<const Float3> reference, std::span<const RadialProfile> profiles) {
  ImageError e;
  double sq = 0.0, ref = 0.0;
  for (std::size_t p = 0; p < reference.size() && p < actual.size() && p < f.radiance.size(); ++p) {
    const long id = std::lround(f.radiance[p].w);
    if (id <= 0 || id >= static_cast<long>(profiles.size()) || profiles[static_cast<std::size_t>(id)].empty())
      continue;
    const double d[3] = {static_cast<double>(actual[p].x) - static_cast<double>(reference[p].x),
                         static_cast<double>(actual[p].y) - static_cast<double>(reference[p].y),
                         static_cast<double>(actual[p].z) - static_cast<double>(reference[p].z)};
    sq += d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    ref += static_cast<double>(reference[p].x) + static_cast<double>(reference[p].y) +
           static_cast<double>(reference[p].z);
    ++e.pixels;
  }
  if (e.pixels == 0) return e;
  e.rms = std::sqrt(sq / (3.0 * static_cast<double>(e.pixels)));
  e.meanReference = ref / (3.0 * static_cast<double>(e.pixels));
  e.relativeRms = e.meanReference > 0.0 ? e.rms / e.meanReference : 0.0;
  return e;
}

}  // namespace tissue::reference
