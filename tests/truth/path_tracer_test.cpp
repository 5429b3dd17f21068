// The path-traced truth against its references: the 1D Monte Carlo (tissue::optics, MCML's model)
// on a wide flat slab, the closed-form single scattering of a layered half-space, and energy
// conservation without absorption; its determinism, progress and error messages.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "slab_box.h"
#include "tissue/optics/fresnel.h"
#include "tissue/optics/monte_carlo.h"
#include "tissue/truth/path_tracer.h"
#include "tissue/truth/slab_reference.h"

namespace tissue::truth {
namespace {

// Mean over the image's pixels and its standard error (the pixels are independent estimates).
struct Estimate {
  Rgb mean{}, stderrs{};
};
Estimate imageMean(const TruthImage& image) {
  Estimate e;
  const double n = double(image.radiance.size());
  for (std::size_t i = 0; i < image.radiance.size(); ++i) {
    const Float3 m = image.radiance[i], s = image.stderrs[i];
    const double mean[3] = {m.x, m.y, m.z}, se[3] = {s.x, s.y, s.z};
    for (std::size_t c = 0; c < 3; ++c) {
      e.mean[c] += mean[c] / n;
      e.stderrs[c] += se[c] * se[c];
    }
  }
  for (double& s : e.stderrs)
    s = std::sqrt(s) / n;
  return e;
}

// |value - reference| within 3 combined standard errors.
void expectWithin3Sigma(const char* what, double value, double se, double reference, double seRef) {
  const double sigma = std::sqrt(se * se + seRef * seRef);
  std::printf("  %-26s %.5f +- %.5f   reference %.5f +- %.5f   (%+.2f sigma)\n", what, value, se, reference,
              seRef, (value - reference) / sigma);
  EXPECT_NEAR(value, reference, 3.0 * sigma) << what;
}

TruthLayer layer(Rgb sigmaA, Rgb sigmaS, Rgb g, double n, double thicknessMm = kUnboundedMm) {
  TruthLayer l;
  l.sigmaA = sigmaA;
  l.sigmaS = sigmaS;
  l.g = g;
  l.n = n;
  l.thicknessMm = thicknessMm;
  return l;
}

// A directional light along -z with unit radiance: the irradiance on the slab is pi, so a probe
// pixel (radiosity / pi) reads the reflectance directly.
TruthLight overheadLight() {
  TruthLight l;
  l.type = TruthLightType::Directional;
  l.direction = {0.0f, 0.0f, -1.0f};
  l.radiance = {1.0f, 1.0f, 1.0f};
  return l;
}

// The probe's point is kept off the box's face diagonals: every probe ray aims at it, and the BVH's
// triangle test is not watertight on a shared edge (Embree's robust mode is).
TruthCamera probe(Float3 point, Float3 normal) {
  TruthCamera c;
  c.projection = Projection::CosineProbe;
  c.target = point;
  c.up = normal;
  return c;
}

PathTraceSettings probeSettings(int samplesPerPass, int passes) {
  PathTraceSettings s;
  s.width = 8;
  s.height = 8;
  s.samplesPerPass = samplesPerPass;
  s.passes = passes;
  s.threads = 2;
  s.seed = 11;
  return s;
}

TruthImage render(const test::SlabBox& box, const TruthMaterial& material, const TruthCamera& camera,
                  const PathTraceSettings& settings, std::span<const TruthLight> lights) {
  auto image = renderPathTraced(box.mesh(), material, lights, camera, settings);
  EXPECT_TRUE(image.ok()) << (image.ok() ? "" : image.error().message);
  if (!image.ok()) return {};
  std::printf("  [%s] %d spp x %d px, %.2f s, %.0f paths/s, %lld collisions, capped %lld, lost %lld\n",
              intersectorName(image->intersector), image->samplesPerPixel, image->width * image->height,
              image->seconds, double(image->paths) / image->seconds,
              static_cast<long long>(image->interactions), static_cast<long long>(image->cappedPaths),
              static_cast<long long>(image->lostPaths));
  return *image;
}

// 1. A wide slab lit along its normal: the diffuse reflectance read by a probe at its centre is
// MCML's Rd (reciprocity: uniform illumination read at a point = a narrow beam's total). The three
// bands are three media: case B's coefficients (monte_carlo_validation.md, in mm^-1), case A's,
// and a forward-scattering one; n = 1.4, 3 mm thick (optical depth >= 30: the unscattered beam
// never reaches the bottom, which the estimator's one-refraction light connection relies on).
TEST(PathTracer, SlabDiffuseReflectanceMatches1dMonteCarlo) {
  const test::SlabBox box(50.0f, 3.0f);
  TruthMaterial material;
  material.layers = {layer({1.0, 1.0, 2.0}, {9.0, 9.0, 8.0}, {0.0, 0.75, 0.9}, 1.4, 3.0)};
  const TruthLight light = overheadLight();
  const TruthImage image =
      render(box, material, probe({0.37f, -0.21f, 0}, {0, 0, 1}), probeSettings(64, 4), {&light, 1});
  const Estimate pt = imageMean(image);
  EXPECT_EQ(image.cappedPaths, 0);
  EXPECT_EQ(image.lostPaths, 0);
  for (int band = 0; band < kBands; ++band) {
    auto r = test::slabMonteCarlo(material, band, 3);
    ASSERT_TRUE(r.ok()) << r.error().message;
    const char* names[] = {"Rd red (g 0)", "Rd green (g 0.75)", "Rd blue (g 0.9)"};
    expectWithin3Sigma(names[band], pt.mean[std::size_t(band)], pt.stderrs[std::size_t(band)], r->rd,
                       r->rdStderr);
  }
}

// 1b. Local majorants (transport.h): a blood-like layer (extinction ~10x the tissue's) between two
// layers of equal coefficients, so that segments above and below it track against the tissue's
// majorant with exact transmittance and those that may meet it against the blood's. The diffuse
// reflectance stays MCML's in both trackers.
TEST(PathTracer, LocalMajorantsMatch1dMonteCarloThroughABloodLayer) {
  const test::SlabBox box(50.0f, 5.0f);
  TruthMaterial material;
  const TruthLayer tissue = layer({0.2, 1.0, 0.8}, {5.0, 6.0, 7.0}, {0.8, 0.8, 0.8}, 1.4, 0.15);
  TruthLayer deep = tissue;
  deep.thicknessMm = 4.6;
  material.layers = {tissue, layer({0.6, 20.0, 15.0}, {40.0, 60.0, 80.0}, {0.9, 0.9, 0.9}, 1.4, 0.25), deep};
  const TruthLight light = overheadLight();
  PathTraceSettings s = probeSettings(32, 4);
  const TruthImage local = render(box, material, probe({0.37f, -0.21f, 0}, {0, 0, 1}), s, {&light, 1});
  s.localMajorants = false;
  const TruthImage global = render(box, material, probe({0.37f, -0.21f, 0}, {0, 0, 1}), s, {&light, 1});
  const Estimate a = imageMean(local), b = imageMean(global);
  EXPECT_EQ(local.lostPaths + local.cappedPaths, 0);
  for (int band = 0; band < kBands; ++band) {
    auto r = test::slabMonteCarlo(material, band, 4);
    ASSERT_TRUE(r.ok()) << r.error().message;
    const auto c = std::size_t(band);
    expectWithin3Sigma("Rd, local majorants", a.mean[c], a.stderrs[c], r->rd, r->rdStderr);
    expectWithin3Sigma("Rd, one majorant", b.mean[c], b.stderrs[c], r->rd, r->rdStderr);
  }
  std::printf("  depth queries: local %lld, one majorant %lld\n", static_cast<long long>(local.depthQueries),
              static_cast<long long>(global.depthQueries));
}

// 1c. The next collision's next event by MIS (transport.h): forward-peaked tissue (g = 0.9 in every
// band, so the MIS applies) keeps MCML's diffuse reflectance, and seen by a pinhole under an oblique
// light, where the path must turn up the light's refracted beam to collect it, the MIS image agrees
// with the path's own next events within noise at a clearly lower variance for the same samples.
TEST(PathTracer, NextEventMisIsUnbiasedAndLowersTheVarianceOfForwardScattering) {
  const test::SlabBox box(50.0f, 4.0f);
  TruthMaterial material;
  material.layers = {layer({0.05, 0.3, 1.0}, {7.7, 8.5, 9.5}, {0.9, 0.9, 0.9}, 1.38, 4.0)};
  const TruthLight overhead = overheadLight();
  const TruthImage probed =
      render(box, material, probe({0.37f, -0.21f, 0}, {0, 0, 1}), probeSettings(64, 4), {&overhead, 1});
  const Estimate rd = imageMean(probed);
  EXPECT_GT(probed.guidedNextEvents, 0);
  for (int band = 0; band < kBands; ++band) {
    auto r = test::slabMonteCarlo(material, band, 5);
    ASSERT_TRUE(r.ok()) << r.error().message;
    expectWithin3Sigma("Rd, next-event MIS", rd.mean[std::size_t(band)], rd.stderrs[std::size_t(band)], r->rd,
                       r->rdStderr);
  }
  TruthLight oblique;
  oblique.type = TruthLightType::Directional;
  oblique.direction = {0.8f, 0.0f, -0.6f};
  oblique.radiance = {1.0f, 1.0f, 1.0f};
  TruthCamera camera;
  camera.eye = {300.0f, 0.0f, 400.0f};
  camera.target = {0.0f, 0.0f, 0.0f};
  camera.up = {0.0f, 0.0f, 1.0f};
  camera.verticalFovDeg = 0.5f;
  PathTraceSettings s = probeSettings(128, 2);
  const TruthImage mis = render(box, material, camera, s, {&oblique, 1});
  s.nextEventMis = false;
  const TruthImage own = render(box, material, camera, s, {&oblique, 1});
  EXPECT_EQ(own.guidedNextEvents, 0);
  const Estimate a = imageMean(mis), b = imageMean(own);
  for (int band = 0; band < kBands; ++band) {
    const auto c = std::size_t(band);
    expectWithin3Sigma("pinhole, MIS vs own", a.mean[c], a.stderrs[c], b.mean[c], b.stderrs[c]);
  }
  // Red (the least absorbed, longest walks) gains most; the variance ratio is asserted well inside
  // what this scene measures.
  std::printf("  red stderr: MIS %.5f, own %.5f (variance ratio %.2f)\n", a.stderrs[0], b.stderrs[0],
              b.stderrs[0] * b.stderrs[0] / (a.stderrs[0] * a.stderrs[0]));
  EXPECT_LT(a.stderrs[0] * a.stderrs[0], 0.8 * b.stderrs[0] * b.stderrs[0]);
}

// 2. Single scattering only: a two-layer half-space (0.3 mm over a deep layer, different per band)
// seen obliquely under an oblique light reproduces the closed form of slab_reference.h pixel by pixel
// (averaged over a small far-away image whose rays are parallel to within 0.2 degrees).
TEST(PathTracer, SingleScatteringMatchesLayeredSlabClosedForm) {
  const test::SlabBox box(50.0f, 20.0f);
  TruthMaterial material;
  material.layers = {layer({0.2, 0.5, 1.0}, {2.0, 1.5, 3.0}, {0.3, 0.6, 0.8}, 1.4, 0.3),
                     layer({1.0, 0.1, 0.5}, {1.0, 3.0, 0.5}, {0.8, 0.0, -0.3}, 1.4)};
  TruthLight light;
  light.type = TruthLightType::Directional;
  light.direction = {-0.5f, 0.0f, -1.0f};
  light.radiance = {1.0f, 0.8f, 0.6f};
  TruthCamera camera;
  camera.eye = {-300.0f, 200.0f, 1000.0f};
  camera.target = {0.0f, 0.0f, 0.0f};
  camera.up = {0.0f, 0.0f, 1.0f};
  camera.verticalFovDeg = 0.4f;
  PathTraceSettings s = probeSettings(100, 2);
  s.estimator = Estimator::SingleScattering;
  s.jitter = false;
  s.intersector = Intersector::Bvh;  // the BVH here, the best back end (Embree where built) in the others
  const TruthImage image = render(box, material, camera, s, {&light, 1});
  const Estimate pt = imageMean(image);
  Rgb analytic{};
  for (int y = 0; y < s.height; ++y)
    for (int x = 0; x < s.width; ++x) {
      const Float3 d = pinholeRayDirection(camera, s.width, s.height, x + 0.5, y + 0.5);
      const Rgb a =
          layeredSlabSingleScattering(material, {-d.x, -d.y, -d.z}, {0.5f, 0.0f, 1.0f}, {1.0, 0.8, 0.6});
      for (int c = 0; c < kBands; ++c)
        analytic[std::size_t(c)] += a[std::size_t(c)] / double(s.width * s.height);
    }
  const char* names[] = {"single scattering red", "single scattering green", "single scattering blue"};
  for (int band = 0; band < kBands; ++band)
    expectWithin3Sigma(names[band], pt.mean[std::size_t(band)], pt.stderrs[std::size_t(band)],
                       analytic[std::size_t(band)], 0.0);
  // The closed form itself, index-matched at normal incidence: one layer of optical depth
  // sigma_s d returns sigma_s p (1 - exp(-2 sigma_s d)) / (2 sigma_s) of the irradiance pi.
  TruthMaterial thin;
  thin.ambientN = 1.0;
  thin.layers = {layer({0.0, 0.0, 0.0}, {1e-3, 1e-3, 1e-3}, {0.0, 0.0, 0.0}, 1.0, 1.0)};
  const Rgb a = layeredSlabSingleScattering(thin, {0.0f, 0.0f, 1.0f}, {0.0f, 0.0f, 1.0f}, {1.0, 1.0, 1.0});
  const double pi = std::acos(-1.0);
  EXPECT_NEAR(a[0], pi / (4.0 * pi) * (1.0 - std::exp(-2e-3)) / 2.0, 1e-12);
}

// 3. No absorption: what enters leaves. Specular (Fresnel at normal incidence) + diffuse
// reflectance (probe on top) + diffuse transmittance (probe underneath, looking up) + the
// unscattered beam (closed form) = 1, and every path ends on its own (none reaches the cap).
TEST(PathTracer, EnergyIsConservedWithoutAbsorption) {
  const double thickness = 2.0, n = 1.4;
  const test::SlabBox box(50.0f, float(thickness));
  TruthMaterial material;
  const Rgb sigmaS{5.0, 10.0, 3.0};
  material.layers = {layer({0.0, 0.0, 0.0}, sigmaS, {0.8, 0.0, 0.5}, n, thickness)};
  const TruthLight light = overheadLight();
  const PathTraceSettings s = probeSettings(64, 4);
  const TruthImage top = render(box, material, probe({0.37f, -0.21f, 0}, {0, 0, 1}), s, {&light, 1});
  const TruthImage bottom =
      render(box, material, probe({0.37f, -0.21f, float(-thickness)}, {0, 0, -1}), s, {&light, 1});
  const Estimate r = imageMean(top), t = imageMean(bottom);
  const double rs = optics::fresnelReflectance(1.0, n, 1.0).reflectance;
  for (int band = 0; band < kBands; ++band) {
    const auto b = std::size_t(band);
    const double e = std::exp(-sigmaS[b] * thickness);
    const double unscattered = (1.0 - rs) * (1.0 - rs) * e / (1.0 - rs * rs * e * e);
    const double total = rs + r.mean[b] + t.mean[b] + unscattered;
    std::printf("  band %d: specular %.5f + Rd %.5f + Td %.5f + unscattered %.5f\n", band, rs, r.mean[b],
                t.mean[b], unscattered);
    expectWithin3Sigma("R + T", total, std::hypot(r.stderrs[b], t.stderrs[b]), 1.0, 0.0);
  }
  EXPECT_EQ(top.cappedPaths + bottom.cappedPaths, 0);
  EXPECT_EQ(top.lostPaths + bottom.lostPaths, 0);
  // The cap does end paths, and they are counted.
  PathTraceSettings capped = s;
  capped.maxInteractions = 3;
  capped.passes = 1;
  const TruthImage c = render(box, material, probe({0.37f, -0.21f, 0}, {0, 0, 1}), capped, {&light, 1});
  EXPECT_GT(c.cappedPaths, 0);
  EXPECT_LE(c.cappedPaths, c.paths);
}

// Per-texel layering: one subsurface map whose boundaries are at depth 0 on the left quarter of the
// texture (u <= 0.25: the top layer vanishes) and at 0.25 mm on the right quarter. A probe on the
// left reads the deep layer alone, one on the right the two-layer stack with constant depths.
TEST(PathTracer, PerTexelLayersFollowTheSubsurfaceMaps) {
  const test::SlabBox box(50.0f, 4.0f);
  const TruthLayer top = layer({2.0, 0.1, 0.5}, {8.0, 1.0, 6.0}, {0.5, 0.5, 0.5}, 1.4, 0.25);
  const TruthLayer deep = layer({0.5, 1.0, 0.3}, {2.0, 5.0, 1.0}, {0.8, 0.8, 0.8}, 1.4);
  TruthMaterial maps;
  maps.layers = {top, top, top, top, deep};
  maps.maps = {.width = 2, .height = 1, .mapCount = 1, .depths = {0, 0, 0, 0, 0.25f, 0.25f, 0.25f, 0.25f}};
  maps.depthScaleMm = 1.0f;
  TruthMaterial twoLayers, deepOnly;
  twoLayers.layers = {top, deep};
  deepOnly.layers = {deep};
  const TruthLight light = overheadLight();
  const PathTraceSettings s = probeSettings(32, 1);
  const TruthCamera left = probe({-40, 0, 0}, {0, 0, 1}), right = probe({40, 0, 0}, {0, 0, 1});
  const Estimate mapsLeft = imageMean(render(box, maps, left, s, {&light, 1}));
  const Estimate mapsRight = imageMean(render(box, maps, right, s, {&light, 1}));
  const Estimate refLeft = imageMean(render(box, deepOnly, left, s, {&light, 1}));
  const Estimate refRight = imageMean(render(box, twoLayers, right, s, {&light, 1}));
  bool distinguishable = false;
  for (std::size_t b = 0; b < 3; ++b) {
    expectWithin3Sigma("left: deep layer only", mapsLeft.mean[b], mapsLeft.stderrs[b], refLeft.mean[b],
                       refLeft.stderrs[b]);
    expectWithin3Sigma("right: 0.25 mm over deep", mapsRight.mean[b], mapsRight.stderrs[b], refRight.mean[b],
                       refRight.stderrs[b]);
    distinguishable |= std::abs(refLeft.mean[b] - refRight.mean[b]) >
                       10.0 * std::hypot(refLeft.stderrs[b], refRight.stderrs[b]);
  }
  EXPECT_TRUE(distinguishable) << "the two stacks must differ for the test to see the maps";
  // Without UVs per-texel layering is refused.
  auto r = renderPathTraced({box.positions, box.triangles, {}}, maps, {&light, 1}, left, s);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().message.find("needs the mesh's UVs"), std::string::npos);
}

// Deterministic for a seed whatever the thread count; progressive passes reported and stoppable.
TEST(PathTracer, DeterministicAcrossThreadCountsAndProgressive) {
  const test::SlabBox box(50.0f, 2.0f);
  TruthMaterial material;
  material.layers = {layer({0.5, 1.0, 2.0}, {5.0, 4.0, 3.0}, {0.5, 0.7, 0.0}, 1.4, 0.5),
                     layer({0.1, 0.2, 0.3}, {2.0, 2.0, 2.0}, {0.9, 0.9, 0.9}, 1.4)};
  TruthLight lights[2] = {overheadLight(), TruthLight{}};
  lights[1].positionMm = {40.0f, 30.0f, 100.0f};
  TruthCamera camera;
  camera.eye = {0.0f, -60.0f, 80.0f};
  camera.verticalFovDeg = 50.0f;
  PathTraceSettings s;
  s.width = 12;
  s.height = 9;
  s.samplesPerPass = 2;
  s.passes = 3;
  s.surfaceRoughness = 0.2;
  s.threads = 1;
  auto one = renderPathTraced(box.mesh(), material, lights, camera, s);
  s.threads = 3;
  int reports = 0;
  s.onPass = [&](const PathTraceProgress& p) {
    ++reports;
    EXPECT_EQ(p.passesDone, reports);
    EXPECT_EQ(p.samplesPerPixel, 2 * reports);
    EXPECT_NE(p.image, nullptr);
    return true;
  };
  auto three = renderPathTraced(box.mesh(), material, lights, camera, s);
  ASSERT_TRUE(one.ok() && three.ok());
  EXPECT_EQ(reports, 3);
  EXPECT_EQ(one->radiance, three->radiance);
  EXPECT_EQ(one->stderrs, three->stderrs);
  EXPECT_EQ(one->interactions, three->interactions);
  double sum = 0.0;
  for (const Float3& p : one->radiance)
    sum += double(p.x + p.y + p.z);
  EXPECT_GT(sum, 0.0);
  // Stop after the first pass.
  s.onPass = [](const PathTraceProgress&) { return false; };
  auto stopped = renderPathTraced(box.mesh(), material, lights, camera, s);
  ASSERT_TRUE(stopped.ok());
  EXPECT_EQ(stopped->passes, 1);
  EXPECT_EQ(stopped->samplesPerPixel, 2);
}

// A point light far away along the normal is the directional light (the renderer's lamp has no
// falloff): the connection through the boundary converges to the same refracted direction.
TEST(PathTracer, FarPointLightIsTheDirectionalLight) {
  const test::SlabBox box(50.0f, 3.0f);
  TruthMaterial material;
  material.layers = {layer({0.5, 1.0, 2.0}, {5.0, 4.0, 3.0}, {0.8, 0.5, 0.0}, 1.4)};
  const TruthLight directional = overheadLight();
  TruthLight point = directional;
  point.type = TruthLightType::Point;
  point.positionMm = {0.0f, 0.0f, 1e6f};
  const PathTraceSettings s = probeSettings(8, 1);
  const TruthImage a = render(box, material, probe({0.37f, -0.21f, 0}, {0, 0, 1}), s, {&directional, 1});
  const TruthImage b = render(box, material, probe({0.37f, -0.21f, 0}, {0, 0, 1}), s, {&point, 1});
  const Estimate ea = imageMean(a), eb = imageMean(b);
  for (std::size_t c = 0; c < 3; ++c) {
    EXPECT_GT(ea.mean[c], 0.0);
    EXPECT_NEAR(eb.mean[c], ea.mean[c], 1e-4 * ea.mean[c]);  // same paths, directions within 1e-4 rad
  }
}

// Bad input: one Error that names what is wrong and how to fix it.
TEST(PathTracer, BadInputGetsOneClearError) {
  const test::SlabBox box(10.0f, 1.0f);
  const TruthLight light = overheadLight();
  const TruthCamera camera;
  PathTraceSettings s;
  s.width = 2;
  s.height = 2;
  auto expectError = [&](const TruthMesh& mesh, const TruthMaterial& m, const char* needle) {
    auto r = renderPathTraced(mesh, m, {&light, 1}, camera, s);
    ASSERT_FALSE(r.ok()) << needle;
    EXPECT_NE(r.error().message.find(needle), std::string::npos) << r.error().message;
  };
  TruthMaterial good;
  good.layers = {layer({0.1, 0.1, 0.1}, {1.0, 1.0, 1.0}, {0.9, 0.9, 0.9}, 1.4)};
  TruthMaterial noCoefficients = good;
  TruthLayer capsule;  // no coefficients
  capsule.thicknessMm = 0.2;
  capsule.name = "capsule";
  noCoefficients.layers.insert(noCoefficients.layers.begin(), capsule);
  expectError(box.mesh(), noCoefficients, "layer 0 (\"capsule\") has no sigma_a");
  TruthMaterial negative = good;
  negative.layers[0].sigmaS = Rgb{1.0, -1.0, 1.0};
  expectError(box.mesh(), negative, "sigma_s (green)");
  TruthMaterial notFinite = good;
  notFinite.layers[0].sigmaA = Rgb{1.0, 1.0, std::nan("")};
  expectError(box.mesh(), notFinite, "sigma_a (blue)");
  TruthMaterial zeroDepth = good;
  zeroDepth.layers.insert(zeroDepth.layers.begin(),
                          layer({0.1, 0.1, 0.1}, {1.0, 1.0, 1.0}, {0, 0, 0}, 1.4, 0.0));
  expectError(box.mesh(), zeroDepth, "thickness 0.000000 mm must be > 0");
  TruthMaterial unboundedFirst = good;
  unboundedFirst.layers.push_back(good.layers[0]);
  expectError(box.mesh(), unboundedFirst, "unbounded but not the last layer");
  expectError(box.mesh(), TruthMaterial{}, "no layers");
  expectError(TruthMesh{}, good, "the mesh is empty");
  EXPECT_FALSE(makeRayMesh({}, {}).ok());
  TruthMaterial maps = good;
  maps.maps.mapCount = 1;
  expectError(box.mesh(), maps, "give 4N + 1 layers");
}

// Both back ends answer the same nearest hits and nearest surface points on the slab.
TEST(PathTracer, RayBackEndsAgree) {
  const test::SlabBox box(50.0f, 3.0f);
  auto bvh = makeRayMesh(box.positions, box.triangles, Intersector::Bvh);
  ASSERT_TRUE(bvh.ok());
  EXPECT_EQ((*bvh)->kind(), Intersector::Bvh);
  auto embree = makeRayMesh(box.positions, box.triangles, Intersector::Embree);
  if (!embreeAvailable()) {
    ASSERT_FALSE(embree.ok());
    EXPECT_NE(embree.error().message.find("libembree-dev"), std::string::npos);
    return;
  }
  ASSERT_TRUE(embree.ok()) << embree.error().message;
  for (int i = 0; i < 200; ++i) {
    const double a = 0.1 * i, z = std::cos(0.37 * i);
    const std::array<double, 3> o{10.0 * std::sin(0.3 * i), 7.0 * std::cos(0.7 * i), -1.5};
    const double r = std::sqrt(1.0 - z * z);
    const std::array<double, 3> d{r * std::cos(a), r * std::sin(a), z};
    const auto hb = (*bvh)->intersect(o, d, 0.0, 1e9);
    const auto he = (*embree)->intersect(o, d, 0.0, 1e9);
    ASSERT_TRUE(hb && he);  // from inside a closed box every ray meets it
    EXPECT_NEAR(hb->t, he->t, 1e-4 * hb->t + 1e-5);
  }
  // Nearest surface points: the depth below the nearer of top (z = 0) and bottom (z = -3), or
  // nothing within the bound.
  for (int i = 0; i < 100; ++i) {
    const std::array<double, 3> p{20.0 * std::sin(0.9 * i), 20.0 * std::cos(0.4 * i),
                                  -3.0 * (i + 0.5) / 100.0};
    const double depth = std::min(-p[2], 3.0 + p[2]);
    const auto nb = (*bvh)->nearest(p, 10.0), ne = (*embree)->nearest(p, 10.0);
    ASSERT_TRUE(nb && ne);
    EXPECT_NEAR(nb->distanceMm, depth, 1e-9);
    EXPECT_NEAR(ne->distanceMm, depth, 1e-9);
    EXPECT_FALSE((*bvh)->nearest(p, 0.9 * depth).has_value());
    EXPECT_FALSE((*embree)->nearest(p, 0.9 * depth).has_value());
  }
}

}  // namespace
}  // namespace tissue::truth
