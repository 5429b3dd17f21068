// Photons per second per core of the 1D Monte Carlo (tissue::optics::simulateMonteCarlo, one
// thread) on the four validation cases of shared/reference/monte_carlo_validation.md, the inputs
// of the MCML comparison in docs/RESULTS.md ("Ground-truth speed"). Prints median, p99 (slow
// tail) and worst over runs, with Rd and Tt. Rates per CPU second of the process (the run has one
// worker thread), so that other load on the machine does not count (MCML is timed by user time):
//   tissue_monte_carlo_bench [--runs N] [--scale X]   (X scales every case's photon count)

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "cpu_time.h"
#include "tissue/core/statistics.h"
#include "tissue/optics/monte_carlo.h"

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
    double rd = 0.0, tt = 0.0;
    for (int r = 0; r < runs; ++r) {
      const double cpu0 = tissue::bench::cpuSeconds();
      auto result = tissue::optics::simulateMonteCarlo(c.medium, s);
      if (!result) {
        std::printf("%s: %s\n", c.name, result.error().message.c_str());
        return 1;
      }
      rates.push_back(double(result->photons) / (tissue::bench::cpuSeconds() - cpu0));
      rd = result->rd;
      tt = result->tt;
    }
    const tissue::SampleSummary sum = tissue::summarizeSamples(rates);
    std::printf(
        "%-20s %8lld photons, 1 thread: median (per CPU s) %.3f M photons/s, p99 (slow tail) %.3f, worst "
        "%.3f;"
        " Rd %.5f Tt %.5f\n",
        c.name, static_cast<long long>(s.photons), sum.median * 1e-6, tissue::quantile(rates, 0.01) * 1e-6,
        *std::min_element(rates.begin(), rates.end()) * 1e-6, rd, tt);
  }
  return 0;
}
