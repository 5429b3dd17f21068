// tissue-sim profile: a diffusion profile R_d(r) and the totals of a material or a medium file, by
// Monte Carlo (MCML's model), Jensen's dipole, the Donner-Jensen multipole or Christensen-Burley.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <iostream>

#include "command.h"
#include "named_material.h"
#include "output.h"
#include "tissue/optics/burley.h"
#include "tissue/optics/dipole.h"
#include "tissue/optics/materials.h"
#include "tissue/optics/monte_carlo.h"
#include "tissue/optics/multipole.h"

namespace tissue::sim_app {
namespace {

struct ProfileOptions {
  std::string method;
  std::string material;
  std::string medium;
  std::int64_t photons = 100000;
  std::uint64_t seed = 1;
  int threads = 0;
  int bins = 100;
  double drMm = 0.0;  // 0: chosen from the medium
  bool progress = false;
};

// One wavelength's profile and totals.
struct ChannelProfile {
  double rd = 0, rdStderr = 0, tt = 0, ttStderr = 0, specular = 0;
  std::vector<double> rdRadial;
  double seconds = 0;        // MC: the run; analytic: one evaluation of the whole radial profile
  std::int64_t photons = 0;  // MC: photons launched
  int threads = 0;           // MC: worker threads used
};

// The first layer as the analytic models see it: reduced coefficients, relative index.
struct AnalyticLayer {
  double sigmaA, sigmaSPrime, eta, thickness;
};
AnalyticLayer analyticLayer(const optics::LayeredMedium& m) {
  const auto& l = m.layers[0];
  return {l.mua, l.mus * (1.0 - l.g), l.n / m.ambientAbove, l.thickness};
}

// Outer radius of the default grid: 6 diffusion lengths 1/sigma_tr, at most 30 transport mean free paths.
double defaultRadius(const optics::LayeredMedium& m) {
  const auto a = analyticLayer(m);
  const double sigmaTPrime = a.sigmaA + a.sigmaSPrime;
  const double sigmaTr = std::sqrt(3.0 * a.sigmaA * sigmaTPrime);
  return sigmaTr > 0 ? std::min(6.0 / sigmaTr, 30.0 / sigmaTPrime) : 30.0 / sigmaTPrime;
}

void drawProgress(double fraction) {
  const int width = 40;
  const int filled = static_cast<int>(fraction * width);
  std::fprintf(stderr, "\r[%s%s] %3d%%", std::string(static_cast<std::size_t>(filled), '#').c_str(),
               std::string(static_cast<std::size_t>(width - filled), ' ').c_str(),
               static_cast<int>(fraction * 100));
  if (fraction >= 1.0) std::fprintf(stderr, "\n");
  std::fflush(stderr);
}

// Times `evaluate` (the whole radial profile) over repeats for at least 20 ms; seconds per call.
template <class F>
double timeEvaluation(F&& evaluate) {
  const auto start = std::chrono::steady_clock::now();
  int repeats = 0;
  double elapsed = 0;
  do {
    evaluate();
    ++repeats;
    elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  } while (elapsed < 0.02);
  return elapsed / repeats;
}

Result<ChannelProfile> computeChannel(const ProfileOptions& o, const optics::LayeredMedium& medium,
                                      const optics::RadialGrid& grid) {
  ChannelProfile out;
  if (o.method == "mc") {
    optics::MonteCarloSettings s;
    s.photons = o.photons;
    s.seed = o.seed;
    s.threads = o.threads;
    s.grid = grid;
    if (o.progress) s.onProgress = drawProgress;
    auto r = optics::simulateMonteCarlo(medium, s);
    if (!r) return r.error();
    return ChannelProfile{r->rd,       r->rdStderr, r->tt,      r->ttStderr, r->specular,
                          r->rdRadial, r->seconds,  r->photons, r->threads};
  }
  const auto a = analyticLayer(medium);
  const double r0 = (medium.ambientAbove - medium.layers[0].n) / (medium.ambientAbove + medium.layers[0].n);
  out.specular = r0 * r0;
  out.rdRadial.resize(static_cast<std::size_t>(grid.bins));
  std::function<double(double)> profile;
  if (o.method == "dipole" || (o.method == "multipole" && std::isinf(a.thickness))) {
    const auto d = optics::makeDipole(a.sigmaA, a.sigmaSPrime, a.eta);
    out.rd = optics::dipoleTotalRd(d);
    profile = [d](double r) { return optics::dipoleRd(d, r); };
  } else if (o.method == "multipole") {
    const auto m = optics::makeMultipole(a.sigmaA, a.sigmaSPrime, a.eta, a.thickness);
    out.rd = optics::multipoleTotalR(m);
    out.tt = optics::multipoleTotalT(m);
    profile = [m](double r) { return optics::multipoleR(m, r); };
  } else {
    // Burley's albedo A: the dipole's total diffuse reflectance of the same medium; l: the mean
    // free path 1/sigma_t' of the similarity-reduced medium; s from the searchlight/mfp fit.
    const double albedo = optics::dipoleTotalRd(optics::makeDipole(a.sigmaA, a.sigmaSPrime, a.eta));
    const double d =
        1.0 / (a.sigmaA + a.sigmaSPrime) / optics::burleyScaling(albedo, optics::BurleyFit::SearchlightMfp);
    out.rd = albedo;
    profile = [d, albedo](double r) { return optics::burleyProfile(r, d, albedo); };
  }
  auto evaluate = [&] {
    for (int i = 0; i < grid.bins; ++i)
      out.rdRadial[static_cast<std::size_t>(i)] = profile(grid.radius(i));
  };
  out.seconds = timeEvaluation(evaluate);
  return out;
}

Result<void> checkOptions(const ProfileOptions& o) {
  if (o.method != "mc" && o.method != "dipole" && o.method != "multipole" && o.method != "burley")
    return Error{"--method '" + o.method + "' is unknown; use mc, dipole, multipole or burley"};
  if (o.material.empty() == o.medium.empty())
    return Error{"pass exactly one of --material NAME and --medium FILE.json"};
  if (o.photons < 1) return Error{"--photons must be >= 1"};
  if (o.bins < 1 || o.drMm < 0.0) return Error{"--bins must be >= 1 and --dr > 0 mm"};
  return {};
}

// One value per channel: a number for a single-wavelength medium, [R, G, B] for a material.
nlohmann::json perChannel(const std::vector<ChannelProfile>& ch, double ChannelProfile::*field) {
  if (ch.size() == 1) return ch[0].*field;
  nlohmann::json a = nlohmann::json::array();
  for (const auto& c : ch)
    a.push_back(c.*field);
  return a;
}

int runProfile(const ProfileOptions& o, const GlobalOptions& global) {
  if (auto ok = checkOptions(o); !ok) return fail("profile", ok.error().message);
  std::vector<optics::LayeredMedium> media;  // one per channel
  nlohmann::json out;
  out["method"] = o.method;
  if (!o.medium.empty()) {
    auto m = optics::loadMediumFile(o.medium);
    if (!m) return fail("profile", m.error().message);
    media.push_back(*m);
    out["medium"] = o.medium;
  } else {
    auto mat = findNamedMaterial(o.material);
    if (!mat) return fail("profile", mat.error().message);
    for (int c = 0; c < optics::kChannels; ++c)
      media.push_back(optics::halfSpace(*mat, c));
    out["material"] = mat->name;
    out["channels"] = {"R", "G", "B"};
  }
  if (o.method != "mc" && media[0].layers.size() > 1)
    std::cerr << "tissue-sim profile: warning: analytic methods use the first layer only\n";
  if (o.method == "multipole" && media[0].layers[0].thickness < 1.0 / (analyticLayer(media[0]).sigmaA +
                                                                       analyticLayer(media[0]).sigmaSPrime))
    std::cerr
        << "tissue-sim profile: warning: the slab is thinner than 1/sigma_t'; the multipole is unreliable\n";
  double rMax = 0;
  for (const auto& m : media)
    rMax = std::max(rMax, defaultRadius(m));
  const optics::RadialGrid grid{.drMm = o.drMm > 0 ? o.drMm : rMax / o.bins, .bins = o.bins};

  std::vector<ChannelProfile> channels;
  ProfileOptions opts = o;
  opts.progress = o.progress || (o.method == "mc" && isatty(STDERR_FILENO) && o.photons >= 1000000);
  for (const auto& m : media) {
    auto ch = computeChannel(opts, m, grid);
    if (!ch) return fail("profile", ch.error().message);
    channels.push_back(std::move(*ch));
  }
  out["Rd"] = perChannel(channels, &ChannelProfile::rd);
  out["Rd_stderr"] = perChannel(channels, &ChannelProfile::rdStderr);
  out["Tt"] = perChannel(channels, &ChannelProfile::tt);
  out["Tt_stderr"] = perChannel(channels, &ChannelProfile::ttStderr);
  out["specular"] = perChannel(channels, &ChannelProfile::specular);
  double seconds = 0;
  for (const auto& c : channels)
    seconds += c.seconds;
  if (o.method == "mc") {
    std::int64_t photons = 0;
    for (const auto& c : channels)
      photons += c.photons;
    out["photons"] = photons;
    out["threads"] = channels[0].threads;
    out["seed"] = o.seed;
    out["seconds"] = seconds;
    out["photons_per_second"] = static_cast<double>(photons) / seconds;
  } else {
    out["profile_us"] = seconds * 1e6 / static_cast<double>(channels.size());  // one channel's radial profile
  }
  nlohmann::json radial;
  radial["dr_mm"] = grid.drMm;
  for (int i = 0; i < grid.bins; ++i)
    radial["r_mm"].push_back(grid.radius(i));
  if (channels.size() == 1) {
    radial["Rd"] = channels[0].rdRadial;
  } else {
    for (const auto& c : channels)
      radial["Rd"].push_back(c.rdRadial);
  }
  if (global.json) {
    out["radial"] = radial;
  } else {
    out["radial_bins"] = grid.bins;
    out["radial_dr_mm"] = grid.drMm;
  }
  out["units"] = "r in mm, radial Rd in mm^-2, Rd/Tt fractions of incident power (specular excluded)";
  printResult(global, out);
  return 0;
}

}  // namespace

void registerProfileCommand(CLI::App& app, const GlobalOptions& global, int& exitCode) {
  auto opts = std::make_shared<ProfileOptions>();
  auto* cmd = app.add_subcommand(
      "profile", "diffusion profile R_d(r) and totals: Monte Carlo, dipole, multipole, Burley");
  cmd->add_option("--method", opts->method, "mc, dipole, multipole or burley")->required();
  cmd->add_option("--material", opts->material,
                  "Jensen 2001 material (Skin1, Marble, ...) or data/materials name");
  cmd->add_option("--medium", opts->medium,
                  "medium file {\"ambient_n\", \"layers\": [{n, mua, mus, g, thickness}]}");
  cmd->add_option("--photons", opts->photons, "Monte Carlo photons per channel (default 100000)");
  cmd->add_option("--seed", opts->seed, "Monte Carlo seed (default 1)");
  cmd->add_option("--threads", opts->threads, "Monte Carlo threads (default 0: all cores)");
  cmd->add_option("--bins", opts->bins, "radial rings (default 100)");
  cmd->add_option("--dr", opts->drMm, "ring width, mm (default: 6 diffusion lengths / bins)");
  cmd->add_flag("--progress", opts->progress,
                "progress bar on stderr (default: on a terminal for >= 1e6 photons)");
  cmd->callback([opts, &global, &exitCode] { exitCode = runProfile(*opts, global); });
}

}  // namespace tissue::sim_app
