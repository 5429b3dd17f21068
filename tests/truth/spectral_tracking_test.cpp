// Spectral tracking (one path for the three bands, transport.h) against the 1D Monte Carlo of each
// band alone, where the bands' extinctions differ by a factor of four (null collisions in two
// bands) and their g differ (the hero band's lobe with the balance heuristic), and per pass
// determinism of the shared random stream.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "slab_box.h"
#include "tissue/optics/monte_carlo.h"
#include "tissue/truth/path_tracer.h"

namespace tissue::truth {
namespace {

TruthLayer chromaticLayer(Rgb g) {
  TruthLayer l;
  l.sigmaA = Rgb{0.05, 0.4, 1.2};  // mm^-1: red travels far, blue is absorbed near the surface
  l.sigmaS = Rgb{4.0, 8.0, 16.0};  // mm^-1: extinction 4.05 / 8.4 / 17.2, majorant 17.2
  l.g = g;
  l.n = 1.4;
  l.thicknessMm = 6.0;
  return l;
}

// The probe at the centre of a wide slab under an overhead light reads the diffuse reflectance
// of each band; the 1D code (MCML's model) runs each band by itself.
void expectBandsMatch(Rgb g) {
  const test::SlabBox box(60.0f, 6.0f);
  TruthMaterial material;
  material.layers = {chromaticLayer(g)};
  TruthLight light;
  light.type = TruthLightType::Directional;
  light.direction = {0.0f, 0.0f, -1.0f};
  light.radiance = {1.0f, 1.0f, 1.0f};
  TruthCamera probe;
  probe.projection = Projection::CosineProbe;
  probe.target = {0.37f, -0.21f, 0.0f};
  probe.up = {0.0f, 0.0f, 1.0f};
  PathTraceSettings s;
  s.width = 8;
  s.height = 8;
  s.samplesPerPass = 64;
  s.passes = 4;
  s.threads = 2;
  s.seed = 5;
  auto image = renderPathTraced(box.mesh(), material, {&light, 1}, probe, s);
  ASSERT_TRUE(image.ok()) << image.error().message;
  EXPECT_EQ(image->lostPaths, 0);
  EXPECT_EQ(image->cappedPaths, 0);
  for (int band = 0; band < kBands; ++band) {
    double mean = 0.0, var = 0.0;
    const double n = double(image->radiance.size());
    for (std::size_t i = 0; i < image->radiance.size(); ++i) {
      const float m[3] = {image->radiance[i].x, image->radiance[i].y, image->radiance[i].z};
      const float e[3] = {image->stderrs[i].x, image->stderrs[i].y, image->stderrs[i].z};
      mean += double(m[band]) / n;
      var += double(e[band]) * double(e[band]) / (n * n);
    }
    auto r = test::slabMonteCarlo(material, band, 9);
    ASSERT_TRUE(r.ok()) << r.error().message;
    const double sigma = std::sqrt(var + r->rdStderr * r->rdStderr);
    std::printf("  band %d (g %.2f): path tracer %.5f +- %.5f, 1D %.5f +- %.5f (%+.2f sigma)\n", band,
                g[std::size_t(band)], mean, std::sqrt(var), r->rd, r->rdStderr, (mean - r->rd) / sigma);
    EXPECT_NEAR(mean, r->rd, 3.0 * sigma) << "band " << band;
  }
}

TEST(SpectralTracking, ChromaticExtinctionMatchesEachBandAlone) {
  expectBandsMatch({0.8, 0.8, 0.8});
}

TEST(SpectralTracking, ChromaticPhaseFunctionsMatchEachBandAlone) {
  expectBandsMatch({0.9, 0.6, 0.0});
}

}  // namespace
}  // namespace tissue::truth
