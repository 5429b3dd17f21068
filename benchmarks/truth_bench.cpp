// Ray rates of the path-traced truth's two ray-mesh back ends (Embree 3 and the subsurface BVH)
// on the data liver (data/meshes/liver.obj, 27.6k triangles, mm), single-threaded, and the path
// tracer's sample rate on that liver with each. Prints median, p99 and worst rates over batches:
//   tissue_truth_bench [--batches N] [--rays N] [--threads N] [--spp N] [--roulette W] [--tracer-only 1]
//                      [--liver-material 1] [--bvh 0] [--spectral 0] [--local-majorants 0]
//                      [--roughness A] (the outer surface's Beckmann roughness; 0: no glossy term)
//                      [--next-event-mis 0] (the path's own next events alone)
//                      [--pixel-samples N] (then only: N samples of the centre pixel, one per pass,
//                      and how their variance is shared: quantiles, the top 0.1 % and 1 %)
// The random-walk rays start just inside the surface (a random point of a random triangle, 0.01 mm
// in) with a random inward direction, as the walk's queries do; camera rays come from a pinhole
// camera framing the liver. "nearest 1.1" is the layer-depth query: the nearest surface point
// within 1.1 mm of those origins (0.01 mm deep; rates in M queries/s).

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "cpu_time.h"
#include "tissue/core/statistics.h"
#include "tissue/core/vec_math.h"
#include "tissue/mesh/load_mesh.h"
#include "tissue/scene/organ_assets.h"
#include "tissue/scene/truth_view.h"
#include "tissue/truth/path_tracer.h"

namespace {

using namespace tissue;
using Ray = std::pair<std::array<double, 3>, std::array<double, 3>>;

// A small deterministic generator for the ray set (the bench needs no statistical quality).
struct Lcg {
  std::uint64_t s = 0x2545F4914F6CDD1Dull;
  double next() {
    s = s * 6364136223846793005ull + 1442695040888963407ull;
    return double(s >> 11) * 0x1.0p-53;
  }
};

std::vector<Ray> walkRays(const SurfaceMesh& mesh, std::size_t count) {
  Lcg rng;
  std::vector<Ray> rays;
  rays.reserve(count);
  while (rays.size() < count) {
    const Triangle& t = mesh.triangles[std::size_t(rng.next() * double(mesh.triangles.size()))];
    const Float3 a = mesh.positions[t[0]], b = mesh.positions[t[1]], c = mesh.positions[t[2]];
    double u = rng.next(), v = rng.next();
    if (u + v > 1.0) u = 1.0 - u, v = 1.0 - v;
    const Float3 p = a + float(u) * (b - a) + float(v) * (c - a);
    const Float3 n = normalize(cross(b - a, c - a));
    // A uniform direction, flipped into the inward hemisphere.
    const double z = 2.0 * rng.next() - 1.0, phi = 6.283185307179586 * rng.next(), r = std::sqrt(1.0 - z * z);
    std::array<double, 3> d{r * std::cos(phi), r * std::sin(phi), z};
    const double dn = d[0] * double(n.x) + d[1] * double(n.y) + d[2] * double(n.z);
    if (dn > 0.0)
      for (int k = 0; k < 3; ++k)
        d[std::size_t(k)] -= 2.0 * dn * double((&n.x)[k]);
    const Float3 o = p - 0.01f * n;
    rays.push_back({{o.x, o.y, o.z}, d});
  }
  return rays;
}

std::vector<Ray> cameraRays(const truth::TruthCamera& camera, int width, int height) {
  std::vector<Ray> rays;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const Float3 d = truth::pinholeRayDirection(camera, width, height, x + 0.5, y + 0.5);
      rays.push_back({{camera.eye.x, camera.eye.y, camera.eye.z}, {d.x, d.y, d.z}});
    }
  return rays;
}

// Rays per second of each batch over the whole set.
std::vector<double> rayRates(const truth::RayMesh& mesh, const std::vector<Ray>& rays, int batches,
                             int& hits) {
  std::vector<double> rates;
  for (int b = 0; b < batches; ++b) {
    hits = 0;
    const auto start = std::chrono::steady_clock::now();
    for (const Ray& r : rays)
      hits += mesh.intersect(r.first, r.second, 0.0, 1e30).has_value() ? 1 : 0;
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    rates.push_back(double(rays.size()) / s);
  }
  return rates;
}

// Nearest-point queries per second (the layer depth), within `radiusMm` of each walk ray's origin.
std::vector<double> pointRates(const truth::RayMesh& mesh, const std::vector<Ray>& rays, int batches,
                               double radiusMm, int& found) {
  std::vector<double> rates;
  for (int b = 0; b < batches; ++b) {
    found = 0;
    const auto start = std::chrono::steady_clock::now();
    for (const Ray& r : rays)
      found += mesh.nearest(r.first, radiusMm).has_value() ? 1 : 0;
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    rates.push_back(double(rays.size()) / s);
  }
  return rates;
}

void printRates(const char* what, const char* backend, const std::vector<double>& rates, int hits,
                std::size_t rays) {
  // The p99 and worst of a rate are its low tail: the 1st percentile and the minimum.
  const SampleSummary s = summarizeSamples(rates);
  const double worst = *std::min_element(rates.begin(), rates.end());
  std::printf(
      "%-12s %-7s median %6.2f Mrays/s   p99 (slow tail) %6.2f   worst %6.2f   best %6.2f   hits %d/%zu\n",
      what, backend, s.median * 1e-6, quantile(rates, 0.01) * 1e-6, worst * 1e-6, s.max * 1e-6, hits, rays);
}

// The centre pixel of the 80 x 60 view alone (a 1 x 1 image of the same pixel footprint), one
// sample per pass: each sample's red value from the running means, and how the sum of squares
// (the variance) is shared among the largest samples. A heavy tail shows as a large share of the
// top 0.1 %.
void printPixelSamples(const truth::TruthMesh& mesh, const truth::TruthMaterial& material,
                       std::span<const truth::TruthLight> lights, truth::TruthCamera camera,
                       truth::PathTraceSettings s, int samples) {
  camera.verticalFovDeg /= float(s.height);
  s.width = s.height = 1;
  s.samplesPerPass = 1;
  s.passes = samples;
  std::vector<double> values;
  double previousSum = 0.0;
  s.onPass = [&](const truth::PathTraceProgress& p) {
    const double sum = double(p.image->radiance[0].x) * p.samplesPerPixel;
    values.push_back(sum - previousSum);
    previousSum = sum;
    return true;
  };
  auto image = truth::renderPathTraced(mesh, material, lights, camera, s);
  if (!image || values.empty()) {
    std::printf("pixel samples: %s\n", image ? "none" : image.error().message.c_str());
    return;
  }
  double mean = 0.0, sq = 0.0;
  for (double v : values) {
    mean += v;
    sq += v * v;
  }
  mean /= double(values.size());
  sq /= double(values.size());
  std::vector<double> sorted = values;
  std::sort(sorted.begin(), sorted.end());
  auto share = [&](double fraction) {  // of the second moment, from the largest samples
    const std::size_t k = std::max<std::size_t>(1, std::size_t(fraction * double(sorted.size())));
    double top = 0.0;
    for (std::size_t i = sorted.size() - k; i < sorted.size(); ++i)
      top += sorted[i] * sorted[i];
    return top / (sq * double(sorted.size()));
  };
  std::printf(
      "centre pixel, red, %zu samples (MIS %d): mean %.4g, rel variance %.2f; quantiles / mean: "
      "p50 %.3g p90 %.3g p99 %.3g p99.9 %.3g max %.3g; second moment from the top 0.1%% %.2f, "
      "top 1%% %.2f, zero samples %.2f\n",
      values.size(), s.nextEventMis ? 1 : 0, mean, (sq - mean * mean) / (mean * mean),
      quantile(sorted, 0.5) / mean, quantile(sorted, 0.9) / mean, quantile(sorted, 0.99) / mean,
      quantile(sorted, 0.999) / mean, sorted.back() / mean, share(0.001), share(0.01),
      double(std::count(sorted.begin(), sorted.end(), 0.0)) / double(sorted.size()));
}

}  // namespace

int main(int argc, char** argv) {
  int batches = 30, threads = 1, spp = 16;
  double roulette = -1.0;  // < 0: the default
  double roughness = 0.17;
  bool tracerOnly = false, liverMaterial = false, withBvh = true, spectral = true, localMajorants = true;
  bool nextEventMis = true;
  int centreSamples = 0;
  std::size_t rayCount = 200000;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--batches")) batches = std::atoi(argv[i + 1]);
    if (!std::strcmp(argv[i], "--rays")) rayCount = std::size_t(std::atol(argv[i + 1]));
    if (!std::strcmp(argv[i], "--threads")) threads = std::atoi(argv[i + 1]);
    if (!std::strcmp(argv[i], "--spp")) spp = std::max(2, std::atoi(argv[i + 1]));
    if (!std::strcmp(argv[i], "--roulette")) roulette = std::atof(argv[i + 1]);
    if (!std::strcmp(argv[i], "--tracer-only")) tracerOnly = std::atoi(argv[i + 1]) != 0;
    if (!std::strcmp(argv[i], "--liver-material")) liverMaterial = std::atoi(argv[i + 1]) != 0;
    if (!std::strcmp(argv[i], "--bvh")) withBvh = std::atoi(argv[i + 1]) != 0;
    if (!std::strcmp(argv[i], "--spectral")) spectral = std::atoi(argv[i + 1]) != 0;
    if (!std::strcmp(argv[i], "--local-majorants")) localMajorants = std::atoi(argv[i + 1]) != 0;
    if (!std::strcmp(argv[i], "--roughness")) roughness = std::atof(argv[i + 1]);
    if (!std::strcmp(argv[i], "--next-event-mis")) nextEventMis = std::atoi(argv[i + 1]) != 0;
    if (!std::strcmp(argv[i], "--pixel-samples")) centreSamples = std::atoi(argv[i + 1]);
  }
  const std::string path = std::string(TISSUE_BENCH_DATA_DIR) + "/meshes/liver.obj";
  auto mesh = mesh::loadMesh(path);
  if (!mesh) {
    std::printf("%s\n", mesh.error().message.c_str());
    return 1;
  }
  std::printf("liver: %zu vertices, %zu triangles; %zu rays per batch, %d batches, 1 thread\n",
              mesh->positions.size(), mesh->triangles.size(), rayCount, batches);
  const Bounds3 box = boundsOf(mesh->positions);
  truth::TruthCamera camera;
  camera.target = box.centre();
  camera.eye = box.centre() + Float3{-60.0f, -80.0f, 250.0f};
  camera.verticalFovDeg = 40.0f;
  const std::vector<Ray> walk = walkRays(*mesh, rayCount);
  const std::vector<Ray> cam = cameraRays(camera, 400, 300);
  for (truth::Intersector kind : {truth::Intersector::Embree, truth::Intersector::Bvh}) {
    if (tracerOnly) break;
    const auto start = std::chrono::steady_clock::now();
    auto rays = truth::makeRayMesh(mesh->positions, mesh->triangles, kind);
    if (!rays) {
      std::printf("%s: %s\n", truth::intersectorName(kind), rays.error().message.c_str());
      continue;
    }
    const double buildMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    std::printf("%s: build %.1f ms\n", truth::intersectorName(kind), buildMs);
    int hits = 0;
    const std::vector<double> walkRates = rayRates(**rays, walk, batches, hits);
    printRates("walk rays", truth::intersectorName(kind), walkRates, hits, walk.size());
    const std::vector<double> cameraRates = rayRates(**rays, cam, batches, hits);
    printRates("camera rays", truth::intersectorName(kind), cameraRates, hits, cam.size());
    const std::vector<double> nearestRates = pointRates(**rays, walk, batches, 1.1, hits);
    printRates("nearest 1.1", truth::intersectorName(kind), nearestRates, hits, walk.size());
  }
  // The path tracer on the liver: a capsule over parenchyma-like tissue (subsurface texture
  // mapping's Table 1 "organs" row), a point and a directional light.
  truth::TruthMaterial material;
  truth::TruthLayer capsule, organ;
  capsule.sigmaA = truth::Rgb{0.6, 0.6, 0.6};
  capsule.sigmaS = truth::Rgb{2.0, 1.0, 1.0};
  capsule.g = {0.25, 0.25, 0.25};
  capsule.thicknessMm = 0.1;
  organ.sigmaA = truth::Rgb{0.5, 0.5, 0.5};
  organ.sigmaS = truth::Rgb{1.0, 1.0, 2.0};
  organ.g = {0.8, 0.8, 0.8};
  material.layers = {capsule, organ};
  // --liver-material: the data liver's own material file (five layers per texel of its
  // subsurface map, scene::truthMaterialOf), on its render mesh with UVs.
  SurfaceMesh liverMesh = *mesh;
  if (liverMaterial) {
    scene::OrganSource source;
    source.mesh = path;
    source.material = std::string(TISSUE_BENCH_DATA_DIR) + "/materials/liver.json";
    source.materialOptions.textureRoots = {TISSUE_BENCH_GENERATED_DATA_DIR, TISSUE_BENCH_DATA_DIR};
    source.uvAtlasFallback = false;
    auto assets = scene::loadOrganAssets(source);
    if (!assets) {
      std::printf("%s\n", assets.error().message.c_str());
      return 1;
    }
    auto m = scene::truthMaterialOf(*assets);
    if (!m) {
      std::printf("%s\n", m.error().message.c_str());
      return 1;
    }
    material = *m;
    liverMesh = assets->mesh;
    std::printf("liver material: %zu layers, %d subsurface map(s)\n", material.layers.size(),
                material.maps.mapCount);
  }
  truth::TruthLight lights[2];
  lights[1].type = truth::TruthLightType::Directional;
  const truth::TruthMesh truthMesh{liverMesh.positions, liverMesh.triangles, liverMesh.uvs};
  for (truth::Intersector kind : {truth::Intersector::Embree, truth::Intersector::Bvh}) {
    if (kind == truth::Intersector::Embree && !truth::embreeAvailable()) continue;
    if (kind == truth::Intersector::Bvh && !withBvh) continue;
    truth::PathTraceSettings s;
    s.width = 80;
    s.height = 60;
    s.samplesPerPass = spp / 2;
    s.passes = 2;
    s.threads = threads;
    s.intersector = kind;
    s.surfaceRoughness = roughness;
    if (roulette >= 0.0) s.rouletteWeight = roulette;
    s.spectral = spectral;
    s.localMajorants = localMajorants;
    s.nextEventMis = nextEventMis;
    if (centreSamples > 0) {
      printPixelSamples(truthMesh, material, lights, camera, s, centreSamples);
      return 0;
    }
    const double cpu0 = bench::cpuSeconds();
    auto image = truth::renderPathTraced(truthMesh, material, lights, camera, s);
    const double cpu = bench::cpuSeconds() - cpu0;
    if (!image) {
      std::printf("%s\n", image.error().message.c_str());
      return 1;
    }
    std::int64_t covered = 0;
    double relativeNoise = 0.0;  // mean over organ pixels of stderr / mean (luminance)
    for (std::size_t i = 0; i < image->covered.size(); ++i) {
      if (!image->covered[i]) continue;
      const Float3 m = image->radiance[i], e = image->stderrs[i];
      const double lum = 0.2126 * double(m.x) + 0.7152 * double(m.y) + 0.0722 * double(m.z);
      const double err = std::sqrt(0.2126 * 0.2126 * double(e.x * e.x) + 0.7152 * 0.7152 * double(e.y * e.y) +
                                   0.0722 * 0.0722 * double(e.z * e.z));
      if (lum > 0.0) relativeNoise += err / lum;
      ++covered;
    }
    relativeNoise /= double(std::max<std::int64_t>(covered, 1));
    double noise2 = 0.0, signal2 = 0.0;  // the atlas's measure: sqrt(sum stderr^2 / sum radiance^2)
    double bandNoise2[3] = {0, 0, 0}, bandSignal2[3] = {0, 0, 0};
    for (std::size_t i = 0; i < image->covered.size(); ++i)
      if (image->covered[i]) {
        const Float3 m = image->radiance[i], e = image->stderrs[i];
        noise2 += double(dot(e, e));
        signal2 += double(dot(m, m));
        for (int c = 0; c < 3; ++c) {
          bandNoise2[c] += double((&e.x)[c]) * double((&e.x)[c]);
          bandSignal2[c] += double((&m.x)[c]) * double((&m.x)[c]);
        }
      }
    const double pixelSamples = double(image->width * image->height) * image->samplesPerPixel;
    std::printf(
        "path tracer  %-7s %dx%d, %d spp, %d thread(s): %.2f s (%.2f CPU s), per CPU s %.0f pixel samples "
        "(%.0f on the organ), "
        "%.0f paths/s, %.1f collisions per path, capped %lld, lost %lld; per-pixel noise %.1f%% at %d spp, "
        "organ pixels to 1%% noise per CPU s %.3f; rel RMS noise %.3f\n",
        truth::intersectorName(kind), image->width, image->height, image->samplesPerPixel, image->threads,
        image->seconds, cpu, pixelSamples / cpu, double(covered) * image->samplesPerPixel / cpu,
        double(image->paths) / cpu, double(image->interactions) / double(covered * image->samplesPerPixel),
        static_cast<long long>(image->cappedPaths), static_cast<long long>(image->lostPaths),
        100.0 * relativeNoise, image->samplesPerPixel,
        // Efficiency: organ pixels brought to 1% noise per second, rate / samples needed, with the
        // samples needed (noise * sqrt(spp) / 0.01)^2.
        double(covered) / cpu / (1e4 * relativeNoise * relativeNoise), std::sqrt(noise2 / signal2));
    // Per band: the share of the atlas measure's noise (stderr^2 over the sum of |radiance|^2) and
    // the band's own relative noise; the per-sample relative variance noise^2 * spp; the depth
    // queries per path; the atlas measure's figure of merit 1 / (noise^2 * CPU s per pixel sample).
    std::printf("  per band noise^2 share R %.2f G %.2f B %.2f; own rel noise R %.3f G %.3f B %.3f\n",
                bandNoise2[0] / noise2, bandNoise2[1] / noise2, bandNoise2[2] / noise2,
                std::sqrt(bandNoise2[0] / bandSignal2[0]), std::sqrt(bandNoise2[1] / bandSignal2[1]),
                std::sqrt(bandNoise2[2] / bandSignal2[2]));
    std::printf(
        "  per-sample rel variance %.3f, depth queries per path %.1f, next events per path %.1f (MIS "
        "flights %.1f), efficiency 1/(var * CPU s per organ sample) %.0f\n",
        noise2 / signal2 * image->samplesPerPixel, double(image->depthQueries) / double(image->paths),
        double(image->nextEvents) / double(image->paths),
        double(image->guidedNextEvents) / double(image->paths),
        double(covered) * image->samplesPerPixel / cpu / (noise2 / signal2 * image->samplesPerPixel));
  }
  return 0;
}
