// The tsd-bench error measure on hand-made maps: the stretch map's areas add up to the surface's,
// a diffused map equal to the reference has no error, and one 10 % too bright has a relative
// error of at least 0.1 (exactly 0.1 where the reference is grey and uniform; Cauchy-Schwarz).
#include "tissue/studies/tsd_error.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tissue::studies {
namespace {

// A flat L x L mm square mapped onto the whole T x T map, every texel drawn and covered.
render::TextureSpaceMaps squareMaps(int t, float sideMm) {
  render::TextureSpaceMaps m;
  m.size = m.maxSize = t;
  for (render::FloatImage* image : {&m.irradiance, &m.stretch, &m.position, &m.diffused}) {
    image->width = image->height = t;
    image->pixels.resize(std::size_t(t) * std::size_t(t));
  }
  for (int y = 0; y < t; ++y)
    for (int x = 0; x < t; ++x) {
      const std::size_t i = std::size_t(y) * std::size_t(t) + std::size_t(x);
      m.irradiance.pixels[i] = {1.0f, 1.0f, 1.0f, 1.0f};
      m.stretch.pixels[i] = {sideMm, sideMm, sideMm, 1.0f};  // |dP/du| = |dP/dv| = L per UV unit
      m.position.pixels[i] = {(float(x) + 0.5f) * sideMm / float(t), (float(y) + 0.5f) * sideMm / float(t),
                              0.0f, 1.0f};
    }
  return m;
}

render::RadialProfileTable gaussianProfile(float sigmaMm) {
  render::RadialProfileTable p;
  for (int i = 0; i <= 64; ++i) {
    const float r = 4.0f * sigmaMm * float(i) / 64.0f;
    const float v = std::exp(-r * r / (2.0f * sigmaMm * sigmaMm)) / (2.0f * 3.14159265f * sigmaMm * sigmaMm);
    p.radiusMm.push_back(r);
    p.value.push_back({v, 0.8f * v, 0.6f * v});
  }
  return p;
}

TEST(TsdError, SampleAreasAddUpToTheSurface) {
  const auto maps = squareMaps(32, 20.0f);
  const auto samples = surfaceSamplesOf(maps);
  ASSERT_EQ(samples.positionMm.size(), 32u * 32u);
  double area = 0.0;
  for (float a : samples.areaMm2)
    area += double(a);
  EXPECT_NEAR(area, 400.0, 1e-3);
}

TEST(TsdError, ZeroForTheReferenceAndRelativeForAScaledMap) {
  auto maps = squareMaps(24, 12.0f);
  const auto samples = surfaceSamplesOf(maps);
  const auto profile = gaussianProfile(1.0f);
  std::vector<Float3> queries;
  for (const Float4& p : maps.position.pixels)
    queries.push_back({p.x, p.y, p.z});
  const auto reference = render::convolveOverSurface(samples, queries, profile, 4.0f);
  for (std::size_t i = 0; i < reference.size(); ++i)
    maps.diffused.pixels[i] = {reference[i].x, reference[i].y, reference[i].z, 1.0f};
  const TexelError exact = diffusedMapError(maps, samples, profile, 4.0f);
  EXPECT_LT(exact.rms, 1e-7);
  EXPECT_LT(exact.relative, 1e-5);
  for (std::size_t i = 0; i < reference.size(); ++i)
    maps.diffused.pixels[i] = {1.1f * reference[i].x, 1.1f * reference[i].y, 1.1f * reference[i].z, 1.0f};
  const TexelError bright = diffusedMapError(maps, samples, profile, 4.0f);
  double squares = 0.0;
  for (const Float3& r : reference)
    squares += double(r.x * r.x + r.y * r.y + r.z * r.z);
  EXPECT_NEAR(bright.rms, 0.1 * std::sqrt(squares / (3.0 * double(reference.size()))), 1e-3 * bright.rms);
  EXPECT_GE(bright.relative, 0.1 - 1e-5);
  EXPECT_LT(bright.relative, 0.2);  // the channels differ by 0.8 and 0.6 only
  // The interior (away from the square's edges, where the convolution loses light) is brighter
  // but errs by the same 10 %.
  EXPECT_GE(bright.interiorRelative, 0.1 - 1e-5);
  EXPECT_LT(bright.interiorRelative, 0.2);
}

}  // namespace
}  // namespace tissue::studies
