// Photons per second per core of the 1D Monte Carlo (tissue::optics::simulateMonteCarlo, one
// thread), and camera paths per second per core of the path-traced truth (tissue::truth, a cosine
// probe at the centre of a wide slab box under a light along the normal: its diffuse reflectance,
// the same quantity), on the four validation cases of shared/reference/monte_carlo_validation.md, the inputs
// of the MCML comparison in docs/RESULTS.md ("Ground-truth speed"). Prints median, p99 (slow
// tail) and worst over runs, with Rd and Tt. Rates per CPU second of the process (the run has one
// worker thread), so that other load on the machine does not count (MCML is timed by user time):
//   tissue_monte_carlo_bench [--runs N] [--scale X]   (X scales every case's photon count)

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "cpu_time.h"
#include "tissue/core/statistics.h"
#include "tissue/optics/monte_carlo.h"
#include "tissue/truth/path_tracer.h"

namespace {

using tissue::optics::kInfiniteThickness;
using tissue::optics::Layer;
using tissue::optics::LayeredMedium;

struct Case {
  const char* name;
  LayeredMedium medium;
  std::int64_t photons;
};

// The validation cases in mm and mm^-1 (the reference gives cm and cm^-1).
std::vector<Case> cases() {
  const Layer a{.n = 1.0, .mua = 1.0, .mus = 9.0, .g = 0.75, .thickness = 0.2};
  const Layer b{.n = 1.5, .mua = 1.0, .mus = 9.0, .g = 0.0, .thickness = kInfiniteThickness};
  const Layer c{.n = 1.5, .mua = 1.0, .mus = 9.0, .g = 0.0, .thickness = 0.2};
  const std::vector<Layer> d{{.n = 1.37, .mua = 0.1, .mus = 10.0, .g = 0.9, .thickness = 1.0},
                             {.n = 1.37, .mua = 0.1, .mus = 1.0, .g = 0.0, .thickness = 1.0},
                             {.n = 1.37, .mua = 0.2, .mus = 1.0, .g = 0.7, .thickness = 2.0}};
  return {{"A thin matched slab", {1.0, 1.0, {a}}, 1000000},
          {"B half-space n 1.5", {1.0, 1.0, {b}}, 200000},
          {"C slab n 1.5", {1.0, 1.0, {c}}, 1000000},
          {"D three layers", {1.0, 1.0, d}, 300000}};
}

// A closed box: top face z = 0 (outward +z), bottom z = -thickness, sides at +-w (mm).
struct Box {
  std::vector<tissue::Float3> positions;
  std::vector<tissue::Triangle> triangles;
  Box(float w, float thickness) {
    const float z1 = -thickness;
    positions = {{-w, -w, z1},   {w, -w, z1},   {w, w, z1},   {-w, w, z1},
                 {-w, -w, 0.0f}, {w, -w, 0.0f}, {w, w, 0.0f}, {-w, w, 0.0f}};
    triangles = {{4, 5, 6}, {4, 6, 7}, {0, 2, 1}, {0, 3, 2}, {0, 1, 5}, {0, 5, 4},
                 {2, 3, 7}, {2, 7, 6}, {1, 2, 6}, {1, 6, 5}, {3, 0, 4}, {3, 4, 7}};
  }
};

// The case as the truth's material: every band the same medium.
tissue::truth::TruthMaterial truthMaterial(const LayeredMedium& m) {
  tissue::truth::TruthMaterial out;
  out.ambientN = m.ambientAbove;
  for (const Layer& l : m.layers) {
    tissue::truth::TruthLayer t;
    t.sigmaA = tissue::truth::Rgb{l.mua, l.mua, l.mua};
    t.sigmaS = tissue::truth::Rgb{l.mus, l.mus, l.mus};
    t.g = {l.g, l.g, l.g};
    t.n = l.n;
    t.thicknessMm = std::isfinite(l.thickness) ? l.thickness : tissue::truth::kUnboundedMm;
    out.layers.push_back(t);
  }
  return out;
}

// Camera paths per CPU second of the path tracer on the case, one thread; its Rd (red band).
// `photonVariance`: the 1D code's variance of Rd per photon (MCML's estimator), for the rate of
// photons that would give the tracer's standard error in the same time.
void benchTracer(const Case& c, int runs, double scale, double photonVariance) {
  double depth = 0.0;
  for (const Layer& l : c.medium.layers)
    depth += std::isfinite(l.thickness) ? l.thickness : 50.0;  // a half-space: 50 mm deep
  const Box box(50.0f, float(depth));
  const tissue::truth::TruthMaterial material = truthMaterial(c.medium);
  tissue::truth::TruthLight light;
  light.type = tissue::truth::TruthLightType::Directional;
  light.direction = {0.0f, 0.0f, -1.0f};
  light.radiance = {1.0f, 1.0f, 1.0f};
  tissue::truth::TruthCamera probe;
  probe.projection = tissue::truth::Projection::CosineProbe;
  probe.target = {0.37f, -0.21f, 0.0f};
  probe.up = {0.0f, 0.0f, 1.0f};
  tissue::truth::PathTraceSettings s;
  s.width = 8;
  s.height = 8;
  s.threads = 1;
  s.passes = 1;
  s.samplesPerPass = std::max(2, int(double(c.photons) * scale / 20.0 / 64.0));
  std::vector<double> rates;
  double rd = 0.0, rdError = 0.0;
  for (int r = 0; r < runs; ++r) {
    const double cpu0 = tissue::bench::cpuSeconds();
    auto image =
        tissue::truth::renderPathTraced({box.positions, box.triangles, {}}, material, {&light, 1}, probe, s);
    if (!image) {
      std::printf("%s: %s\n", c.name, image.error().message.c_str());
      return;
    }
    rates.push_back(double(image->paths) / (tissue::bench::cpuSeconds() - cpu0));
    rd = rdError = 0.0;
    for (std::size_t i = 0; i < image->radiance.size(); ++i) {
      rd += double(image->radiance[i].x) / double(image->radiance.size());
      rdError += double(image->stderrs[i].x * image->stderrs[i].x);
    }
    rdError = std::sqrt(rdError) / double(image->radiance.size());
  }
  const tissue::SampleSummary sum = tissue::summarizeSamples(rates);
  std::printf(
      "%-20s %8lld paths,   path tracer:           median %.3f M paths/s, p99 (slow tail) %.3f, worst %.3f;"
      " Rd %.5f +- %.5f; MCML-equivalent (the photons giving that Rd error) %.3f M/s\n",
      c.name, static_cast<long long>(s.samplesPerPass) * 64, sum.median * 1e-6,
      tissue::quantile(rates, 0.01) * 1e-6, *std::min_element(rates.begin(), rates.end()) * 1e-6, rd, rdError,
      sum.median * photonVariance / (rdError * rdError * double(s.samplesPerPass) * 64.0) * 1e-6);
}

}  // namespace

int main(int argc, char** argv) {
  int runs = 5;
  double scale = 1.0;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--runs")) runs = std::max(1, std::atoi(argv[i + 1]));
    if (!std::strcmp(argv[i], "--scale")) scale = std::atof(argv[i + 1]);
  }
  for (const Case& c : cases()) {
    tissue::optics::MonteCarloSettings s;
    s.photons = std::max<std::int64_t>(20, std::int64_t(double(c.photons) * scale));
    s.threads = 1;
    s.seed = 7;
    std::vector<double> rates;
    double rd = 0.0, tt = 0.0, variance = 0.0;
    for (int r = 0; r < runs; ++r) {
      const double cpu0 = tissue::bench::cpuSeconds();
      auto result = tissue::optics::simulateMonteCarlo(c.medium, s);
      if (!result) {
        std::printf("%s: %s\n", c.name, result.error().message.c_str());
        return 1;
      }
      rates.push_back(double(result->photons) / (tissue::bench::cpuSeconds() - cpu0));
      rd = result->rd;
      variance = result->rdStderr * result->rdStderr * double(result->photons);
      tt = result->tt;
    }
    const tissue::SampleSummary sum = tissue::summarizeSamples(rates);
    std::printf(
        "%-20s %8lld photons, 1 thread: median (per CPU s) %.3f M photons/s, p99 (slow tail) %.3f, worst "
        "%.3f;"
        " Rd %.5f Tt %.5f\n",
        c.name, static_cast<long long>(s.photons), sum.median * 1e-6, tissue::quantile(rates, 0.01) * 1e-6,
        *std::min_element(rates.begin(), rates.end()) * 1e-6, rd, tt);
    benchTracer(c, runs, scale, variance);
  }
  return 0;
}
