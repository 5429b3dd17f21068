// tissue-sim kernel: one separable SSS kernel of a material (Freude 2014's models, d'Eon's
// Gaussians, Jimenez's reference), its taps for a shader, build time and errors
// (studies::measureKernel).
#include "command.h"
#include "named_material.h"
#include "output.h"
#include "tissue/studies/kernel_study.h"

namespace tissue::sim_app {
namespace {

struct KernelOptions {
  std::string material;
  std::string model;
  optics::KernelSettings settings;
};

int runKernel(const KernelOptions& o, const GlobalOptions& global) {
  auto model = optics::parseKernelModel(o.model);
  if (!model) return fail("kernel", "--model: " + model.error().message);
  auto material = findNamedMaterial(o.material);
  if (!material) return fail("kernel", "--material: " + material.error().message);
  auto m = studies::measureKernel(*material, *model, o.settings);
  if (!m) return fail("kernel", m.error().message);
  printJsonText(global, studies::kernelMeasurementJson(*m));
  return 0;
}

}  // namespace

void registerKernelCommand(CLI::App& app, const GlobalOptions& global, int& exitCode) {
  auto o = std::make_shared<KernelOptions>();
  auto* cmd = app.add_subcommand("kernel", "separable SSS kernel of a material: taps, build time, errors");
  cmd->add_option("--material", o->material, "Jensen 2001 material (case-insensitive), e.g. Skin1")
      ->required();
  cmd->add_option("--model", o->model, "svd, preintegrated, guided, manual, deon or jimenez")->required();
  cmd->add_option("--rank", o->settings.rank, "SVD rank or d'Eon Gaussian count, 1..8 (default 1)");
  cmd->add_option("--taps", o->settings.taps, "taps per 1D pass, odd (default 17)");
  cmd->add_option("--grid", o->settings.gridHalfCells,
                  "ground-truth grid half size h, cells (default 100: 201^2)");
  cmd->add_option("--k", o->settings.guidedK, "guided: Gamma's exponent k (default 1)");
  cmd->add_option("--b", o->settings.guidedB, "guided: Gamma's axis term b (default 0: off)");
  cmd->add_flag("--normalize", o->settings.normalizeEnergy,
                "svd: normalise to the ground truth's 1-norm (eq. 5.12)");
  cmd->callback([o, &global, &exitCode] { exitCode = runKernel(*o, global); });
}

}  // namespace tissue::sim_app
