// The atlas's scores against the truth (atlas.h): relative RMS of linear radiance, PSNR of the
// tone-mapped image, the truth's own noise, error images and the Pareto front. GL-free.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "tissue/studies/atlas.h"

namespace tissue::studies {
namespace {

double luminance(Float3 c) {
  return 0.2126 * double(c.x) + 0.7152 * double(c.y) + 0.0722 * double(c.z);
}
double sq(double x) {
  return x * x;
}
float srgb(float c) {
  c = std::clamp(c, 0.0f, 1.0f);
  return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

}  // namespace

Float3 toneMap(Float3 radiance, float exposure) {
  // The renderer's output transform (shaders/common/tonemap.glsl, post/tonemap.frag).
  auto one = [&](float c) {
    const float x = std::max(0.0f, c * exposure);
    return srgb(x / (1.0f + x));
  };
  return {one(radiance.x), one(radiance.y), one(radiance.z)};
}

Image8 toneMapped(std::span<const Float3> linear, int width, int height, float exposure) {
  Image8 img(width, height, 4);
  for (std::size_t i = 0; i < linear.size() && i < std::size_t(width) * std::size_t(height); ++i) {
    const Float3 c = toneMap(linear[i], exposure);
    img.pixels[4 * i + 0] = std::uint8_t(std::lround(255.0f * c.x));
    img.pixels[4 * i + 1] = std::uint8_t(std::lround(255.0f * c.y));
    img.pixels[4 * i + 2] = std::uint8_t(std::lround(255.0f * c.z));
    img.pixels[4 * i + 3] = 255;
  }
  return img;
}

AtlasScore scoreAgainstTruth(std::span<const Float3> truth, std::span<const Float3> method,
                             std::span<const std::uint8_t> mask, float exposure) {
  AtlasScore s;
  s.relRms = std::numeric_limits<double>::quiet_NaN();
  s.psnrDb = std::numeric_limits<double>::quiet_NaN();
  if (truth.size() != method.size() || truth.size() != mask.size() || truth.empty()) return s;
  double err = 0.0, ref = 0.0, mse = 0.0, cross = 0.0;
  for (std::size_t i = 0; i < truth.size(); ++i) {
    if (!mask[i]) continue;
    const Float3 t = truth[i], m = method[i];
    err += sq(double(m.x - t.x)) + sq(double(m.y - t.y)) + sq(double(m.z - t.z));
    ref += sq(double(t.x)) + sq(double(t.y)) + sq(double(t.z));
    cross += double(m.x) * double(t.x) + double(m.y) * double(t.y) + double(m.z) * double(t.z);
    const Float3 a = toneMap(t, exposure), b = toneMap(m, exposure);
    mse += sq(double(a.x - b.x)) + sq(double(a.y - b.y)) + sq(double(a.z - b.z));
    ++s.pixels;
  }
  if (s.pixels == 0) return s;
  s.relRms = ref > 0.0 ? std::sqrt(err / ref) : std::numeric_limits<double>::infinity();
  s.gain = ref > 0.0 ? cross / ref : 0.0;
  s.shapeRelRms = std::numeric_limits<double>::quiet_NaN();
  if (s.gain > 0.0) {
    double shape = 0.0;
    for (std::size_t i = 0; i < truth.size(); ++i)
      if (mask[i]) {
        const Float3 t = truth[i], m = method[i];
        shape += sq(double(m.x) / s.gain - double(t.x)) + sq(double(m.y) / s.gain - double(t.y)) +
                 sq(double(m.z) / s.gain - double(t.z));
      }
    s.shapeRelRms = std::sqrt(shape / ref);
  }
  mse /= 3.0 * s.pixels;
  s.psnrDb = mse > 0.0 ? 10.0 * std::log10(1.0 / mse) : std::numeric_limits<double>::infinity();
  return s;
}

double truthNoiseRelRms(const truth::TruthImage& truth) {
  double noise = 0.0, ref = 0.0;
  for (std::size_t i = 0; i < truth.radiance.size(); ++i) {
    if (!truth.covered[i]) continue;
    const Float3 t = truth.radiance[i], e = truth.stderrs[i];
    noise += sq(double(e.x)) + sq(double(e.y)) + sq(double(e.z));
    ref += sq(double(t.x)) + sq(double(t.y)) + sq(double(t.z));
  }
  return ref > 0.0 ? std::sqrt(noise / ref) : 0.0;
}

double debiasedError(double relRms, double noiseRelRms) {
  return std::sqrt(std::max(0.0, relRms * relRms - noiseRelRms * noiseRelRms));
}

ErrorDifference errorDifference(std::span<const Float3> truth, std::span<const Float3> truthStderr,
                                std::span<const Float3> a, std::span<const Float3> b,
                                std::span<const std::uint8_t> mask) {
  const std::size_t n = truth.size();
  if (truthStderr.size() != n || a.size() != n || b.size() != n || mask.size() != n)
    return {std::nan(""), std::nan("")};
  double diff = 0.0, cross = 0.0, ref = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!mask[i]) continue;
    const double t[3] = {truth[i].x, truth[i].y, truth[i].z},
                 s[3] = {truthStderr[i].x, truthStderr[i].y, truthStderr[i].z},
                 pa[3] = {a[i].x, a[i].y, a[i].z}, pb[3] = {b[i].x, b[i].y, b[i].z};
    for (int c = 0; c < 3; ++c) {
      diff += sq(pa[c] - t[c]) - sq(pb[c] - t[c]);
      cross += sq(s[c]) * sq(pa[c] - pb[c]);
      ref += sq(t[c]);
    }
  }
  if (!(ref > 0.0)) return {std::nan(""), std::nan("")};
  return {diff / ref, 2.0 * std::sqrt(cross) / ref};
}

Image8 errorImage(std::span<const Float3> truth, std::span<const Float3> method,
                  std::span<const std::uint8_t> mask, int width, int height, double scale) {
  Image8 img;
  img.width = width;
  img.height = height;
  img.channels = 4;
  img.pixels.assign(std::size_t(width) * std::size_t(height) * 4, 255);
  double meanLum = 0.0;
  int n = 0;
  for (std::size_t i = 0; i < truth.size() && i < mask.size(); ++i)
    if (mask[i]) meanLum += luminance(truth[i]), ++n;
  meanLum = n ? meanLum / n : 1.0;
  for (std::size_t i = 0; i < std::size_t(width) * std::size_t(height); ++i) {
    std::uint8_t* p = &img.pixels[4 * i];
    if (i >= truth.size() || i >= method.size() || !mask[i]) {
      p[0] = 10, p[1] = 10, p[2] = 40;
      continue;
    }
    // Black -> red -> yellow -> white over 0..scale of the mean luminance.
    const double e = std::abs(luminance(method[i]) - luminance(truth[i])) / (meanLum > 0.0 ? meanLum : 1.0);
    const double x = std::clamp(e / scale, 0.0, 1.0) * 3.0;
    p[0] = std::uint8_t(255.0 * std::min(1.0, x));
    p[1] = std::uint8_t(255.0 * std::clamp(x - 1.0, 0.0, 1.0));
    p[2] = std::uint8_t(255.0 * std::clamp(x - 2.0, 0.0, 1.0));
  }
  return img;
}

std::vector<std::size_t> paretoFront(std::span<const double> cost, std::span<const double> error) {
  std::vector<std::size_t> order(std::min(cost.size(), error.size()));
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::erase_if(order, [&](std::size_t i) { return !std::isfinite(cost[i]) || !std::isfinite(error[i]); });
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return cost[a] != cost[b] ? cost[a] < cost[b] : error[a] < error[b];
  });
  // Sweep by increasing cost: a point is on the front when its error is below every cheaper one's.
  std::vector<std::size_t> front;
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i : order)
    if (error[i] < best) {
      front.push_back(i);
      best = error[i];
    }
  return front;
}

}  // namespace tissue::studies
