// tissue-sim profile: a diffusion profile R_d(r) and the totals of a material or a medium file, by
// Monte Carlo (MCML's model), Jensen's dipole, the Donner-Jensen multipole or Christensen-Burley.
#include <unistd.h>

#include <cstdio>
#include <iostream>

#include "command.h"
#include "named_material.h"
#include "output.h"
#include "tissue/optics/materials.h"
#include "tissue/studies/profile_study.h"

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

void drawProgress(double fraction) {
  const int width = 40;
  const int filled = static_cast<int>(fraction * width);
  std::fprintf(stderr, "\r[%s%s] %3d%%", std::string(static_cast<std::size_t>(filled), '#').c_str(),
               std::string(static_cast<std::size_t>(width - filled), ' ').c_str(),
               static_cast<int>(fraction * 100));
  if (fraction >= 1.0) std::fprintf(stderr, "\n");
  std::fflush(stderr);
}

Result<void> checkOptions(const ProfileOptions& o) {
  if (!studies::parseProfileMethod(o.method))
    return Error{"--method '" + o.method + "' is unknown; use mc, dipole, multipole or burley"};
  if (o.material.empty() == o.medium.empty())
    return Error{"pass exactly one of --material NAME and --medium FILE.json"};
  if (o.photons < 1) return Error{"--photons must be >= 1"};
  if (o.bins < 1 || o.drMm < 0.0) return Error{"--bins must be >= 1 and --dr > 0 mm"};
  return {};
}

int runProfile(const ProfileOptions& o, const GlobalOptions& global) {
  if (auto ok = checkOptions(o); !ok) return fail("profile", ok.error().message);
  std::vector<optics::LayeredMedium> media;  // one per channel
  nlohmann::json source{{"method", o.method}};
  if (!o.medium.empty()) {
    auto m = optics::loadMediumFile(o.medium);
    if (!m) return fail("profile", m.error().message);
    media.push_back(*m);
    source["medium"] = o.medium;
  } else {
    auto mat = findNamedMaterial(o.material);
    if (!mat) return fail("profile", mat.error().message);
    for (int c = 0; c < optics::kChannels; ++c)
      media.push_back(optics::halfSpace(*mat, c));
    source.update({{"material", mat->name}, {"channels", {"R", "G", "B"}}});
  }
  studies::ProfileStudyConfig config{.profile = {.method = *studies::parseProfileMethod(o.method),
                                                 .photons = o.photons,
                                                 .seed = o.seed,
                                                 .threads = o.threads,
                                                 .onProgress = {}},
                                     .bins = o.bins,
                                     .drMm = o.drMm};
  if (o.progress || (o.method == "mc" && isatty(STDERR_FILENO) && o.photons >= 1000000))
    config.profile.onProgress = drawProgress;
  auto study = studies::studyProfile(media, config);
  if (!study) return fail("profile", study.error().message);
  for (const auto& w : study->warnings)
    std::cerr << "tissue-sim profile: warning: " << w << "\n";
  auto out = nlohmann::json::parse(studies::profileStudyJson(*study, global.json));
  out.update(source);
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
