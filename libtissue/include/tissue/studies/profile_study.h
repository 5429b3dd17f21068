#pragma once
/// \file
/// The profile choice: a diffusion profile R_d(r) and the totals of one wavelength's layered
/// medium by Monte Carlo (MCML's model; Wang 1995), Jensen 2001's dipole, Donner-Jensen 2005's
/// multipole or Christensen-Burley 2015, on the same radial grid, so the four can be set against
/// each other. GL-free. Lengths in mm, R_d(r) in mm^-2, totals fractions of incident power.

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "tissue/core/result.h"
#include "tissue/optics/medium.h"
#include "tissue/optics/monte_carlo.h"

namespace tissue::studies {

enum class ProfileMethod { MonteCarlo, Dipole, Multipole, Burley };

/// "mc", "dipole", "multipole" or "burley"; none for anything else.
std::optional<ProfileMethod> parseProfileMethod(std::string_view name);

struct ProfileConfig {
  ProfileMethod method = ProfileMethod::Dipole;
  std::int64_t photons = 100000;           ///< Monte Carlo photons
  std::uint64_t seed = 1;                  ///< Monte Carlo seed
  int threads = 0;                         ///< Monte Carlo worker threads; 0: all cores
  std::function<void(double)> onProgress;  ///< Monte Carlo progress, fraction 0..1 (may be empty)
};

/// One wavelength's profile and totals.
struct ChannelProfile {
  double rd = 0, rdStderr = 0;     ///< total diffuse reflectance (standard error: Monte Carlo only)
  double tt = 0, ttStderr = 0;     ///< total transmittance (multipole and Monte Carlo; else 0)
  double specular = 0;             ///< Fresnel reflectance at normal incidence (not in rd)
  std::vector<double> rdRadial;    ///< mm^-2, per ring of the grid
  double seconds = 0;              ///< s, Monte Carlo: the run; analytic: one evaluation of the profile
  std::int64_t photons = 0;        ///< Monte Carlo: photons launched
  int threads = 0;                 ///< Monte Carlo: worker threads used
  std::int64_t cappedPhotons = 0;  ///< Monte Carlo: photons dropped at the hop cap (none absorb them)
  double cappedWeight = 0;         ///< Monte Carlo: their weight, fraction of launched photons
};

/// The first layer as the analytic models see it: reduced coefficients (mm^-1), the relative
/// index n_layer / n_above and the thickness (mm; infinite: a half space).
struct AnalyticLayer {
  double sigmaA = 0, sigmaSPrime = 0, eta = 1, thicknessMm = 0;
};
AnalyticLayer analyticLayer(const optics::LayeredMedium& medium);

/// Outer radius of a default grid, mm: 6 diffusion lengths 1/sigma_tr, at most 30 transport
/// mean free paths 1/sigma_t'.
double defaultProfileRadiusMm(const optics::LayeredMedium& medium);

/// True when a multipole is asked for a slab thinner than 1/sigma_t', where it is unreliable.
bool multipoleUnreliable(const optics::LayeredMedium& medium);

/// The profile of `medium` on `grid` by the config's method. The analytic methods use the first
/// layer only (a finite one: the multipole; the dipole and Burley treat it as a half space).
/// Burley's albedo is the dipole's total R_d of the same medium and its length the mean free
/// path 1/sigma_t' scaled by the searchlight/mfp fit.
Result<ChannelProfile> profileChannel(const optics::LayeredMedium& medium, const optics::RadialGrid& grid,
                                      const ProfileConfig& config);

/// A profile per channel (one medium per wavelength) on one grid: `tissue-sim profile`.
struct ProfileStudyConfig {
  ProfileConfig profile;
  int bins = 100;     ///< rings
  double drMm = 0.0;  ///< ring width, mm; 0: defaultProfileRadiusMm (the largest of the media) / bins
};

struct ProfileStudy {
  ProfileMethod method = ProfileMethod::Dipole;
  std::uint64_t seed = 0;  ///< Monte Carlo seed
  optics::RadialGrid grid{};
  std::vector<ChannelProfile> channels{};  ///< one per medium
  std::vector<std::string> warnings{};     ///< e.g. an analytic method on a layered medium
};

/// Profiles each of `media` (e.g. a material's three channels) on one grid.
Result<ProfileStudy> studyProfile(const std::vector<optics::LayeredMedium>& media,
                                  const ProfileStudyConfig& config);

/// The study as JSON text: Rd, Rd_stderr, Tt, Tt_stderr and specular (a number for one channel,
/// [R, G, B] for three); Monte Carlo: photons, threads, seed, seconds, photons_per_second; else
/// profile_us (one channel's radial profile, us); with `radial` the rings ("radial": dr_mm, r_mm,
/// Rd), else only radial_bins and radial_dr_mm; units.
std::string profileStudyJson(const ProfileStudy& study, bool radial);

}  // namespace tissue::studies
