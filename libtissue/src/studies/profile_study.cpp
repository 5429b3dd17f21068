// The profile choice: Monte Carlo, dipole, multipole and Burley on one grid.
#include "tissue/studies/profile_study.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "json_text.h"
#include "tissue/optics/burley.h"
#include "tissue/optics/dipole.h"
#include "tissue/optics/multipole.h"

namespace tissue::studies {
namespace {

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

// One value per channel: a number for a single-wavelength medium, [R, G, B] for a material.
template <class T>
nlohmann::json perChannel(const std::vector<ChannelProfile>& ch, T ChannelProfile::*field) {
  if (ch.size() == 1) return ch[0].*field;
  nlohmann::json a = nlohmann::json::array();
  for (const auto& c : ch)
    a.push_back(c.*field);
  return a;
}

}  // namespace

std::optional<ProfileMethod> parseProfileMethod(std::string_view name) {
  if (name == "mc") return ProfileMethod::MonteCarlo;
  if (name == "dipole") return ProfileMethod::Dipole;
  if (name == "multipole") return ProfileMethod::Multipole;
  if (name == "burley") return ProfileMethod::Burley;
  return std::nullopt;
}

AnalyticLayer analyticLayer(const optics::LayeredMedium& m) {
  const auto& l = m.layers[0];
  return {l.mua, l.mus * (1.0 - l.g), l.n / m.ambientAbove, l.thickness};
}

double defaultProfileRadiusMm(const optics::LayeredMedium& m) {
  const auto a = analyticLayer(m);
  const double sigmaTPrime = a.sigmaA + a.sigmaSPrime;
  const double sigmaTr = std::sqrt(3.0 * a.sigmaA * sigmaTPrime);
  return sigmaTr > 0 ? std::min(6.0 / sigmaTr, 30.0 / sigmaTPrime) : 30.0 / sigmaTPrime;
}

bool multipoleUnreliable(const optics::LayeredMedium& m) {
  const auto a = analyticLayer(m);
  return m.layers[0].thickness < 1.0 / (a.sigmaA + a.sigmaSPrime);
}

Result<ChannelProfile> profileChannel(const optics::LayeredMedium& medium, const optics::RadialGrid& grid,
                                      const ProfileConfig& config) {
  if (medium.layers.empty()) return Error{"the medium has no layers"};
  ChannelProfile out;
  if (config.method == ProfileMethod::MonteCarlo) {
    optics::MonteCarloSettings s;
    s.photons = config.photons;
    s.seed = config.seed;
    s.threads = config.threads;
    s.grid = grid;
    s.onProgress = config.onProgress;
    auto r = optics::simulateMonteCarlo(medium, s);
    if (!r) return r.error();
    return ChannelProfile{r->rd,      r->rdStderr, r->tt,      r->ttStderr,      r->specular,    r->rdRadial,
                          r->seconds, r->photons,  r->threads, r->cappedPhotons, r->cappedWeight};
  }
  const auto a = analyticLayer(medium);
  const double r0 = (medium.ambientAbove - medium.layers[0].n) / (medium.ambientAbove + medium.layers[0].n);
  out.specular = r0 * r0;
  out.rdRadial.resize(static_cast<std::size_t>(std::max(grid.bins, 0)));
  std::function<double(double)> profile;
  if (config.method == ProfileMethod::Dipole ||
      (config.method == ProfileMethod::Multipole && std::isinf(a.thicknessMm))) {
    const auto d = optics::makeDipole(a.sigmaA, a.sigmaSPrime, a.eta);
    out.rd = optics::dipoleTotalRd(d);
    profile = [d](double r) { return optics::dipoleRd(d, r); };
  } else if (config.method == ProfileMethod::Multipole) {
    const auto m = optics::makeMultipole(a.sigmaA, a.sigmaSPrime, a.eta, a.thicknessMm);
    out.rd = optics::multipoleTotalR(m);
    out.tt = optics::multipoleTotalT(m);
    profile = [m](double r) { return optics::multipoleR(m, r); };
  } else {
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

Result<ProfileStudy> studyProfile(const std::vector<optics::LayeredMedium>& media,
                                  const ProfileStudyConfig& config) {
  if (media.empty()) return Error{"no medium to profile"};
  if (config.bins < 1 || config.drMm < 0.0)
    return Error{"the profile needs >= 1 ring and a ring width >= 0 mm"};
  ProfileStudy study{.method = config.profile.method, .seed = config.profile.seed};
  if (study.method != ProfileMethod::MonteCarlo && media[0].layers.size() > 1)
    study.warnings.push_back("analytic methods use the first layer only");
  if (study.method == ProfileMethod::Multipole && multipoleUnreliable(media[0]))
    study.warnings.push_back("the slab is thinner than 1/sigma_t'; the multipole is unreliable");
  double rMax = 0;
  for (const auto& m : media)
    rMax = std::max(rMax, defaultProfileRadiusMm(m));
  study.grid = {.drMm = config.drMm > 0 ? config.drMm : rMax / config.bins, .bins = config.bins};
  for (const auto& m : media) {
    auto ch = profileChannel(m, study.grid, config.profile);
    if (!ch) return ch.error();
    study.channels.push_back(std::move(*ch));
  }
  return study;
}

std::string profileStudyJson(const ProfileStudy& s, bool radial) {
  const auto& ch = s.channels;
  nlohmann::json out{{"Rd", perChannel(ch, &ChannelProfile::rd)},
                     {"Rd_stderr", perChannel(ch, &ChannelProfile::rdStderr)},
                     {"Tt", perChannel(ch, &ChannelProfile::tt)},
                     {"Tt_stderr", perChannel(ch, &ChannelProfile::ttStderr)},
                     {"specular", perChannel(ch, &ChannelProfile::specular)}};
  double seconds = 0;
  std::int64_t photons = 0;
  for (const auto& c : ch)
    seconds += c.seconds, photons += c.photons;
  if (s.method == ProfileMethod::MonteCarlo)
    out.update({{"photons", photons},
                {"capped_photons", perChannel(ch, &ChannelProfile::cappedPhotons)},
                {"capped_weight", perChannel(ch, &ChannelProfile::cappedWeight)},
                {"threads", ch[0].threads},
                {"seed", s.seed},
                {"seconds", seconds},
                {"photons_per_second", static_cast<double>(photons) / seconds}});
  else
    out["profile_us"] = seconds * 1e6 / static_cast<double>(ch.size());  // one channel's radial profile
  if (radial) {
    nlohmann::json r{{"dr_mm", s.grid.drMm}};
    for (int i = 0; i < s.grid.bins; ++i)
      r["r_mm"].push_back(s.grid.radius(i));
    if (ch.size() == 1)
      r["Rd"] = ch[0].rdRadial;
    else
      for (const auto& c : ch)
        r["Rd"].push_back(c.rdRadial);
    out["radial"] = r;
  } else {
    out.update({{"radial_bins", s.grid.bins}, {"radial_dr_mm", s.grid.drMm}});
  }
  out["units"] = "r in mm, radial Rd in mm^-2, Rd/Tt fractions of incident power (specular excluded)";
  return detail::jsonText(out);
}

}  // namespace tissue::studies
