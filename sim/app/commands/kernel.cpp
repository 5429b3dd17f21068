// tissue-sim kernel: one separable SSS kernel of a material (Freude 2014's models, d'Eon's
// Gaussians, Jimenez's reference), its taps for a shader, build time and errors.
#include <cmath>
#include <ctime>

#include "command.h"
#include "named_material.h"
#include "output.h"
#include "tissue/core/stopwatch.h"
#include "tissue/optics/kernel.h"
#include "tissue/optics/kernel_error.h"

namespace tissue::sim_app {
namespace {

struct KernelOptions {
  std::string material;
  std::string model;
  int rank = 1;
  int taps = 17;
  int grid = 100;
  double k = 1.0;
  double b = 0.0;
  bool normalize = false;
};

nlohmann::json rgb(const std::array<double, optics::kChannels>& v) {
  return nlohmann::json::array({v[0], v[1], v[2]});
}

nlohmann::json tapsJson(const std::vector<optics::KernelTap>& taps) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& t : taps)
    out.push_back({t.weight.x, t.weight.y, t.weight.z, t.offsetMm});
  return out;
}

int runKernel(const KernelOptions& o, const GlobalOptions& global) {
  auto model = optics::parseKernelModel(o.model);
  if (!model) return fail("kernel", "--model: " + model.error().message);
  auto material = findNamedMaterial(o.material);
  if (!material) return fail("kernel", "--material: " + material.error().message);
  optics::KernelSettings s;
  s.taps = o.taps;
  s.rank = o.rank;
  s.gridHalfCells = o.grid;
  s.guidedK = o.k;
  s.guidedB = o.b;
  s.normalizeEnergy = o.normalize;
  // The whole build as a renderer would run it: dipole profile, 2D grid, model, taps.
  // Wall time, and process CPU time (the build is single-threaded), which load on a shared machine
  // disturbs less. Built twice: the first build of a process also pays for faulting in cold code
  // and memory; build_ms is the second, build_first_ms the first.
  double firstMs = 0;
  double buildMs = 0;
  double buildCpuMs = 0;
  Result<optics::SeparableKernel> kernel = Error{"not built"};
  for (int round = 0; round < 2; ++round) {
    Stopwatch watch;
    const std::clock_t cpuStart = std::clock();
    kernel = optics::buildKernel(*material, *model, s);
    buildMs = watch.elapsedMs();
    buildCpuMs = 1000.0 * static_cast<double>(std::clock() - cpuStart) / CLOCKS_PER_SEC;
    if (round == 0) firstMs = buildMs;
  }
  if (!kernel) return fail("kernel", kernel.error().message);
  auto profile = optics::groundTruthProfile(*material);
  if (!profile) return fail("kernel", profile.error().message);
  auto truth = optics::groundTruthKernel(*profile, o.grid);
  if (!truth) return fail("kernel", truth.error().message);

  nlohmann::json out;
  out["material"] = material->name;
  out["model"] = std::string(optics::kernelModelName(*model));
  out["rank"] = kernel->components.size();
  out["taps"] = tapsJson(kernel->taps());
  if (kernel->components.size() > 1) {
    nlohmann::json comps = nlohmann::json::array();
    for (const auto& c : kernel->components)
      comps.push_back({{"sign", {c.sign.x, c.sign.y, c.sign.z}}, {"taps", tapsJson(c.taps)}});
    out["components"] = comps;
  }
  out["build_ms"] = buildMs;
  out["build_cpu_ms"] = buildCpuMs;
  out["build_first_ms"] = firstMs;
  out["kernel_rms"] = rgb(optics::kernelSpaceRms(*truth, *kernel));
  out["image_rms"] = rgb(optics::imageSpaceRms(*truth, *kernel, optics::TestSignal::CircleAndSquares));
  out["energy"] = rgb(optics::kernelEnergy(*kernel));
  out["grid_cell_mm"] = truth->cellMm;
  out["kernel_half_width_mm"] = profile->kernelHalfWidthMm;
  out["units"] =
      "taps: [w_R, w_G, w_B, offset_mm]; offsets in mm on the surface (scale by pixels per mm, from "
      "sssWidth); "
      "kernel_rms over the (2h+1)^2 ground-truth grid normalised to 1; image_rms on the circle-and-squares "
      "signal "
      "in [0, 1], 256^2 pixels of grid_cell_mm";
  printResult(global, out);
  return 0;
}

}  // namespace

void registerKernelCommand(CLI::App& app, const GlobalOptions& global, int& exitCode) {
  auto opts = std::make_shared<KernelOptions>();
  auto* cmd = app.add_subcommand("kernel", "separable SSS kernel of a material: taps, build time, errors");
  cmd->add_option("--material", opts->material, "Jensen 2001 material (case-insensitive), e.g. Skin1")
      ->required();
  cmd->add_option("--model", opts->model, "svd, preintegrated, guided, manual, deon or jimenez")->required();
  cmd->add_option("--rank", opts->rank, "SVD rank or d'Eon Gaussian count, 1..8 (default 1)");
  cmd->add_option("--taps", opts->taps, "taps per 1D pass, odd (default 17)");
  cmd->add_option("--grid", opts->grid, "ground-truth grid half size h, cells (default 100: 201^2)");
  cmd->add_option("--k", opts->k, "guided: Gamma's exponent k (default 1)");
  cmd->add_option("--b", opts->b, "guided: Gamma's axis term b (default 0: off)");
  cmd->add_flag("--normalize", opts->normalize, "svd: normalise to the ground truth's 1-norm (eq. 5.12)");
  cmd->callback([opts, &global, &exitCode] { exitCode = runKernel(*opts, global); });
}

}  // namespace tissue::sim_app
